// The design job's settings (capsubot/job/design_settings.hpp): the table of the drive design's
// settings (one option per row, helps naming the drive's settings and the robot's ranges, the
// limits in the helps those of the drive's waveform), and the runs the settings select with what
// each refuses (DesignRunChoice).

#include "capsubot/job/design_settings.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <optional>
#include <set>
#include <string>
#include <vector>

#include "capsubot/model/forcing.hpp"
#include "job/setting_table_checks.hpp"
#include "test_utils.hpp"

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

// The runs the settings select, and what each refuses, in the front end's names.
TEST(DesignRunChoice, EachRunRefusesWhatItCannotTake) {
  EXPECT_EQ((DesignRunChoice{std::nullopt, false, false}.Run()), "");
  EXPECT_EQ((DesignRunChoice{std::nullopt, false, true}.Run()), "from-rest");
  EXPECT_EQ((DesignRunChoice{std::nullopt, true, false}.Run()), "grid");
  EXPECT_EQ((DesignRunChoice{std::string("pulse"), false, false}.Run()), "drive");
  const SettingNames names{{{"from_rest", "--from-rest"},
                            {"grid", "--grid"},
                            {"drive", "--drive"},
                            {"harmonics", "--harmonics"},
                            {"reach_starts", "--reach-starts"},
                            {"json", "--json"}}};
  const ModeName run = [&names](const std::string& r) { return DesignRunName(r, names); };
  const auto refusal = [&](const DesignRunChoice& choice, const std::set<std::string>& given,
                           const std::vector<SettingUse>& more = {}) {
    return testing::InvalidArgumentMessage([&] { choice.RejectUnused(given, names, run, more); });
  };
  EXPECT_EQ(refusal({std::nullopt, true, true}, {}),
            "--from-rest is invalid with --grid: expected one of them (a grid writes the "
            "one-impact gait of each point to its CSV file)");
  EXPECT_EQ(refusal({std::string("saw"), false, false}, {}),
            "--drive saw is invalid: expected sine, fourier or pulse");
  const auto starts = [](const std::string& text, const char* prefix) {
    return text.rfind(prefix, 0) == 0;
  };
  EXPECT_TRUE(starts(refusal({std::string("sine"), false, true}, {}),
                     "--from-rest is invalid with --drive"));
  EXPECT_EQ(refusal({std::nullopt, false, false}, {"reach_starts"}),
            "--reach-starts is invalid with one design (no --from-rest, no --grid): expected "
            "--reach-starts only with --from-rest or --drive");
  EXPECT_TRUE(starts(refusal({std::string("pulse"), false, false}, {"harmonics"}),
                     "--harmonics is invalid with --drive pulse"));
  // The front end's own settings, after the library's.
  EXPECT_TRUE(starts(refusal({std::nullopt, true, false}, {"json"}, {{"json", {""}}}),
                     "--json is invalid with --grid"));
  EXPECT_NO_THROW(
      (DesignRunChoice{std::nullopt, false, true}.RejectUnused({"reach_starts"}, names, run)));
}

}  // namespace
}  // namespace capsubot
