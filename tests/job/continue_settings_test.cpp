// The tables of the continuation's settings (capsubot/job/continue_settings.hpp): the command
// declares one option per row, so no two rows may set one field or one value, and a help may
// name only the continuation's settings.

#include "capsubot/job/continue_settings.hpp"

#include <gtest/gtest.h>

#include "capsubot/job/shooting_settings.hpp"
#include "job/setting_table_checks.hpp"

namespace capsubot {
namespace {

testing::SettingTablesCheck ContinueTables(const ContinueJobOptions& job, const FollowOptions& f) {
  testing::SettingTablesCheck check;
  check.Add(ContinueParamSettings(), job);
  check.Add(ContinuationRangeSettings(), job.continuation);
  check.Add(FollowSettings(), f);
  check.Add(ContinuationStepSettings(), job.continuation);
  check.Add(ShootingSettings(), job.continuation.shooting);
  return check;
}

TEST(ContinueSettings, EveryRowSetsAFieldAndAValueOfItsOwn) {
  const ContinueJobOptions job;
  const FollowOptions follow;
  EXPECT_TRUE(ContinueTables(job, follow).EachFieldAndValueOnce());
}

// The followed type is read as text (ParseFollowType names it "follow"); every other setting
// a help names is a row of the tables.
TEST(ContinueSettings, HelpsNameOnlyTheContinuationsSettings) {
  const ContinueJobOptions job;
  const FollowOptions follow;
  const testing::SettingTablesCheck check = ContinueTables(job, follow);
  ASSERT_FALSE(check.AllPlaceholders().empty());
  EXPECT_TRUE(check.HelpsNameKnownSettings({"follow"}));
}

}  // namespace
}  // namespace capsubot
