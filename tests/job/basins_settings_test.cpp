// The table of the x0-u0 plane's settings (capsubot/job/basins_settings.hpp): one option per
// row, so no two rows may set one field or one value, and a help names no unknown setting.

#include "capsubot/job/basins_settings.hpp"

#include <gtest/gtest.h>

#include "job/setting_table_checks.hpp"

namespace capsubot {
namespace {

TEST(BasinsSettings, EveryRowSetsAFieldAndAValueOfItsOwnAndNamesNoOtherSetting) {
  const VelocityPlane plane;
  testing::SettingTablesCheck check;
  check.Add(VelocityPlaneSettings(), plane);
  EXPECT_TRUE(check.EachFieldAndValueOnce());
  EXPECT_TRUE(check.HelpsNameKnownSettings({}));
}

}  // namespace
}  // namespace capsubot
