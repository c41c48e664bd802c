// The tables of the bifurcation diagram's settings (capsubot/job/bifurcation_settings.hpp):
// one option per row, so no two rows may set one field or one value, and a help may name only
// the diagram's settings.

#include "capsubot/job/bifurcation_settings.hpp"

#include <gtest/gtest.h>

#include "capsubot/job/bifurcation_job.hpp"
#include "job/setting_table_checks.hpp"

namespace capsubot {
namespace {

testing::SettingTablesCheck BifurcationTables(const BifurcationJobOptions& job) {
  testing::SettingTablesCheck check;
  check.Add(BifurcationRangeSettings(), job.diagram);
  check.Add(BifurcationResumeSettings(), job.files);
  return check;
}

TEST(BifurcationSettings, EveryRowSetsAFieldAndAValueOfItsOwn) {
  const BifurcationJobOptions job;
  EXPECT_TRUE(BifurcationTables(job).EachFieldAndValueOnce());
}

// The resume settings name the shard (BifurcationOptions::shard, read as K/N) and the two files
// (BifurcationShardFiles::impacts and summary, read as paths).
TEST(BifurcationSettings, HelpsNameOnlyTheDiagramsSettings) {
  const BifurcationJobOptions job;
  const testing::SettingTablesCheck check = BifurcationTables(job);
  ASSERT_FALSE(check.AllPlaceholders().empty());
  EXPECT_TRUE(check.HelpsNameKnownSettings({"shard", "impacts", "summary"}));
}

}  // namespace
}  // namespace capsubot
