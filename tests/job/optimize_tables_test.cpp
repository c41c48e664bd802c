// The tables of the optimize job's settings (capsubot/job/optimize_settings.hpp,
// search_settings.hpp, reach_effort_settings.hpp): `capsubot optimize` declares one option per
// row, so no two rows may set one field or one value, and a help may name only the job's
// settings.

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <vector>

#include "capsubot/job/optimize_settings.hpp"
#include "capsubot/job/reach_effort_settings.hpp"
#include "capsubot/job/search_settings.hpp"
#include "capsubot/job/sweep_setting_tables.hpp"
#include "job/setting_table_checks.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::WellFormed;

// The problem's helps name the force bound and the Fourier drive's harmonics, settings of the
// search's tables.
TEST(OptimizeTables, EachTableIsWellFormed) {
  EXPECT_TRUE(WellFormed(OptimizeProblemSettings(), {"bound", "harmonics"}));
  EXPECT_TRUE(WellFormed(GaitBoundMeanings()));
  EXPECT_TRUE(WellFormed(SearchMeanings()));
  EXPECT_TRUE(WellFormed(GaitBoundSettings(), {"problem"}));  // opened by the problems
  // Opened by the problems; the note of harmonics' default names the waveform.
  EXPECT_TRUE(WellFormed(SearchSettings(), {"problem", "waveform"}));
}

// The tables bound to the settings' values as the command binds them.
testing::SettingTablesCheck OptimizeTables(const OptimizeSettings& s) {
  testing::SettingTablesCheck check;
  check.Add(OptimizeProblemSettings(), s);
  check.Add(GaitBoundSettings(), s.search.gait);
  check.Add(SearchSettings(), s.search);
  check.Add(ReachEffortSettings(), s.reach);
  return check;
}

TEST(OptimizeTables, EveryRowSetsAFieldAndAValueOfItsOwn) {
  const OptimizeSettings settings;
  EXPECT_TRUE(OptimizeTables(settings).EachFieldAndValueOnce());
}

TEST(OptimizeTables, HelpsNameOnlyTheJobsSettings) {
  const OptimizeSettings settings;
  const testing::SettingTablesCheck check = OptimizeTables(settings);
  ASSERT_FALSE(check.AllPlaceholders().empty());
  EXPECT_TRUE(check.HelpsNameKnownSettings({}));
}

// Each row's field is a setting of the job's rules: a setting some problems use
// (OptimizeSettingUses), refused by that name when given to the problem P1 (phase) that does not
// use it, or one of the settings every problem uses: the problem, the stability requirement and
// the time limit.
TEST(OptimizeTables, TheFieldsAreTheNamesOfTheJobsRules) {
  const std::set<std::string> every_problem = {"problem", "rho_max", "max_time"};
  std::set<std::string> used_by_some;
  for (const SettingUse& use : OptimizeSettingUses()) used_by_some.insert(use.setting);
  OptimizeSettings phase;
  phase.problem = "phase";
  phase.A = 0.3;
  phase.c = 0.1;
  const std::vector<std::string> unused = UnusedOptimizeSettings(phase);
  const std::set<std::string> unused_by_phase(unused.begin(), unused.end());
  int refused = 0;
  const auto check = [&](const auto& table) {
    for (const auto& row : table) {
      const std::string field = row.field;
      EXPECT_TRUE(used_by_some.count(field) > 0 || every_problem.count(field) > 0) << field;
      if (unused_by_phase.count(field) == 0) continue;
      ++refused;
      OptimizeSettings s = phase;
      s.given = {"problem", "A", "c", field};
      const std::string message =
          testing::InvalidArgumentMessage([&] { OptimizeJobFrom(s, SettingNames{{}}); });
      EXPECT_EQ(message.rfind(field + " conflicts with", 0), 0u)
          << field << ": \"" << message << "\"";
    }
  };
  check(OptimizeProblemSettings());
  check(GaitBoundSettings());
  check(SearchSettings());
  check(ReachEffortSettings());
  EXPECT_GT(refused, 0);
}

// The harmonics' default is the fourier problem's: the help says that reach searches the sine
// unless a Fourier drive is asked for, and shows no default of its own (which reach would not
// take); sweep, whose reach takes no harmonics, keeps the plain meaning and its default.
TEST(OptimizeTables, TheHarmonicsHelpSaysWhichDefaultReachTakes) {
  int rows = 0;
  for (const auto& row : SearchSettings()) {
    if (std::string(row.field) != "harmonics") continue;
    ++rows;
    const std::string help = row.help;
    EXPECT_NE(help.find("; default: " + std::to_string(SearchRequest{}.harmonics) +
                        ", but reach searches the sine unless {harmonics} or {waveform} fourier"),
              std::string::npos)
        << help;
    EXPECT_FALSE(row.default_shown);
  }
  for (const auto& row : SweepSearchSettings()) {
    if (std::string(row.field) != "harmonics") continue;
    ++rows;
    EXPECT_EQ(std::string(row.help).find("reach searches"), std::string::npos) << row.help;
    EXPECT_TRUE(row.default_shown);
  }
  EXPECT_EQ(rows, 2);
}

}  // namespace
}  // namespace capsubot
