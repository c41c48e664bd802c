// Which modes use a setting (capsubot/job/setting_use.hpp): the settings a mode leaves unused,
// the refusal of a setting given to a mode that does not use it, and the helps opened by the
// modes that use each setting, checked against the jobs' own tables of uses.

#include "capsubot/job/setting_use.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "capsubot/job/optimize_settings.hpp"
#include "capsubot/job/search_settings.hpp"
#include "capsubot/job/sweep_setting_tables.hpp"
#include "capsubot/job/sweep_settings.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

const std::vector<SettingUse> kUses = {
    {"hops", {"", "forcing", "reach"}}, {"alpha", {"reach"}}, {"rho_max", {"forcing", "reach"}}};
const ModeSet kModes = {"problem", {"forcing", "reach"}, "the main job"};

TEST(SettingUse, AModeLeavesUnusedTheSettingsItDoesNotUse) {
  EXPECT_EQ(UnusedSettings(kUses, "forcing"), std::vector<std::string>({"alpha"}));
  EXPECT_EQ(UnusedSettings(kUses, ""), std::vector<std::string>({"alpha", "rho_max"}));
}

TEST(SettingUse, ASettingGivenToAModeThatDoesNotUseItIsRefusedInTheFrontEndsNames) {
  const SettingNames names{{{"alpha", "--alpha"}}};
  const ModeName mode = [](const std::string& m) { return m.empty() ? "the main job" : m; };
  EXPECT_EQ(testing::InvalidArgumentMessage(
                [&] { RejectUnusedSettings(kUses, {"alpha"}, "forcing", mode, names); }),
            "--alpha conflicts with forcing: expected --alpha only with reach");
  EXPECT_NO_THROW(RejectUnusedSettings(kUses, {"alpha", "hops"}, "reach", mode, names));
}

TEST(SettingUse, AHelpOpensWithTheRunsThatUseTheSetting) {
  EXPECT_EQ(ModesOpening(kUses, "hops", kModes), "");  // every run
  EXPECT_EQ(ModesOpening(kUses, "alpha", kModes), "with {problem} reach: ");
  EXPECT_EQ(ModesOpening(kUses, "rho_max", kModes), "with {problem}: ");  // every mode
  EXPECT_EQ(ModesOpening(kUses, "max_time", kModes), "");                 // not listed
  const std::vector<SettingUse> main_and_one = {{"hops", {"", "reach"}}};
  EXPECT_EQ(ModesOpening(main_and_one, "hops", kModes), "with the main job or {problem} reach: ");
}

// The helps of the search's settings in optimize and sweep say the modes their rules let use
// them: the same meaning, opened by each job's own table of uses.
template <class Options>
void ExpectOpenedByTheirUses(const SettingTable<Options>& table,
                             const SettingTable<Options>& meanings,
                             const std::vector<SettingUse>& uses, const ModeSet& modes) {
  ASSERT_EQ(table.size(), meanings.size());
  for (std::size_t k = 0; k < table.size(); ++k) {
    const std::string help = table[k].help;
    const std::string opening = ModesOpening(uses, table[k].field, modes);
    EXPECT_EQ(help, opening + meanings[k].help) << table[k].field;
    for (const std::string& mode : modes.modes) {
      const bool named = opening.find(mode) != std::string::npos;
      bool used = true;
      for (const SettingUse& use : uses) {
        if (use.setting == table[k].field) used = use.UsedBy(mode);
      }
      // A help that names some modes names exactly those that use the setting.
      if (opening.find('|') != std::string::npos || opening.find("} ") != std::string::npos) {
        EXPECT_EQ(named, used) << table[k].field << " " << mode;
      }
    }
  }
}

TEST(SettingUse, TheSearchHelpsOfOptimizeAndSweepNameTheModesThatUseEachSetting) {
  ExpectOpenedByTheirUses(GaitBoundSettings(), GaitBoundMeanings(), OptimizeSettingUses(),
                          OptimizeModes());
  ExpectOpenedByTheirUses(SearchSettings(), SearchMeanings(), OptimizeSettingUses(),
                          OptimizeModes());
  ExpectOpenedByTheirUses(SweepGaitSettings(), GaitBoundMeanings(), SweepSettingUses(),
                          SweepModes());
  ExpectOpenedByTheirUses(SweepSearchSettings(), SearchMeanings(), SweepSettingUses(),
                          SweepModes());
  // The sweep's hops are used by forcing and reach only: its help says so.
  int hops = 0;
  for (const auto& row : SweepSearchSettings()) {
    if (std::string(row.field) != "hops") continue;
    ++hops;
    EXPECT_EQ(std::string(row.help).rfind("with {optimize} forcing|reach: ", 0), 0u);
  }
  EXPECT_EQ(hops, 1);
}

}  // namespace
}  // namespace capsubot
