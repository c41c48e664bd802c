// The tables of the sweep job's settings (capsubot/job/sweep_setting_tables.hpp): the command
// declares one option per row, so no two rows may set one field or one value, a help may name
// only the sweep's settings, and a bound written in a help is the constant of the rule.

#include "capsubot/job/sweep_setting_tables.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <stdexcept>
#include <string>

#include "capsubot/optimize/optimize_phase.hpp"
#include "capsubot/optimize/optimize_search.hpp"
#include "job/setting_table_checks.hpp"

namespace capsubot {
namespace {

using testing::WellFormed;

template <class Options>
std::string HelpOf(const SettingTable<Options>& table, const std::string& field) {
  for (const SettingRow<Options>& row : table) {
    if (field == row.field) return row.help;
  }
  return "";
}

bool EndsWith(const std::string& text, const std::string& end) {
  return text.size() >= end.size() && text.compare(text.size() - end.size(), end.size(), end) == 0;
}

TEST(SweepSettingTables, EachTableIsWellFormed) {
  // The helps name the mode (optimize) and the search's bound and harmonics across tables.
  EXPECT_TRUE(WellFormed(SweepModeSettings(), {"bound", "harmonics"}));
  EXPECT_TRUE(WellFormed(SweepGaitSettings(), {"optimize"}));
  EXPECT_TRUE(WellFormed(SweepSearchSettings(), {"optimize"}));
  EXPECT_TRUE(WellFormed(SweepFileSettings()));
}

TEST(SweepSettingTables, EveryRowSetsAFieldAndAValueOfItsOwn) {
  const SweepSettings settings;
  testing::SettingTablesCheck check;
  check.Add(SweepModeSettings(), settings);
  check.Add(SweepGaitSettings(), settings.search.gait);
  check.Add(SweepSearchSettings(), settings.search);
  check.Add(SweepFileSettings(), settings.file);
  EXPECT_TRUE(check.EachFieldAndValueOnce());
  ASSERT_FALSE(check.AllPlaceholders().empty());
  EXPECT_TRUE(check.HelpsNameKnownSettings({}));
}

// The command line reads these numbers without a range of its own: the help states the bounds
// of the constants, and the library's rules (PhaseOptions, SearchEffort) are those bounds.
TEST(SweepSettingTables, TheBoundsInTheHelpsAreTheRules) {
  EXPECT_TRUE(EndsWith(HelpOf(SweepModeSettings(), "scan_points"),
                       fmt::format(", {} to {}", kMinScanPoints, kMaxScanPoints)));
  EXPECT_TRUE(EndsWith(HelpOf(SweepSearchSettings(), "global_evaluations"),
                       fmt::format(", {} to {}", kMinStageEvaluations, kMaxStageEvaluations)));
  for (const int n : {kMinScanPoints - 1, kMaxScanPoints + 1}) {
    PhaseOptions phase;
    phase.scan_points = n;
    EXPECT_THROW(phase.Validate(), std::invalid_argument) << n;
  }
  for (const int n : {kMinScanPoints, kMaxScanPoints}) {
    PhaseOptions phase;
    phase.scan_points = n;
    EXPECT_NO_THROW(phase.Validate()) << n;
  }
  for (const int n : {kMinStageEvaluations - 1, kMaxStageEvaluations + 1}) {
    SearchEffort effort;
    effort.global_evaluations = n;
    EXPECT_THROW(effort.Validate(), std::invalid_argument) << n;
  }
  for (const int n : {kMinStageEvaluations, kMaxStageEvaluations}) {
    SearchEffort effort;
    effort.global_evaluations = n;
    EXPECT_NO_THROW(effort.Validate()) << n;
  }
}

}  // namespace
}  // namespace capsubot
