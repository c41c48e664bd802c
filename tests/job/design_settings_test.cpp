// The table of the drive design's settings (capsubot/job/design_settings.hpp): one
// option per row, helps naming the drive's settings and the robot's ranges, and the limits
// written in the helps are those of the drive's waveform.

#include "capsubot/job/design_settings.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>

#include "capsubot/model/forcing.hpp"
#include "job/setting_table_checks.hpp"

namespace capsubot {
namespace {

std::string HelpOf(const std::string& field) {
  for (const SettingRow<DesignDriveChoice>& row : DesignDriveSettings()) {
    if (field == row.field) return row.help;
  }
  return "";
}

TEST(DesignDriveSettings, TheTableIsWellFormed) {
  EXPECT_TRUE(testing::WellFormed(DesignDriveSettings(), {"frequency_range", "m2_range"}));
}

TEST(DesignDriveSettings, TheLimitsInTheHelpsAreTheWaveformsConstants) {
  EXPECT_NE(HelpOf("harmonics").find(fmt::format("1 <= K <= {}", kMaxHarmonics)),
            std::string::npos);
  EXPECT_NE(HelpOf("pulse_levels").find(fmt::format("2 <= N <= {}", kMaxPulseLevels)),
            std::string::npos);
}

}  // namespace
}  // namespace capsubot
