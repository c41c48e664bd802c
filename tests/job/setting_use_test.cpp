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
// them: each help is its meaning after an opening read here on its own terms ("with {field}
// a|b: ", "with <main job> or {field} a|b: ", "with {field}: ", or none) and compared with the
// job's table of uses. A job may follow the meaning with a note of its own ("; default: ...").
template <class Options>
void ExpectOpenedByTheirUses(const SettingTable<Options>& table,
                             const SettingTable<Options>& meanings,
                             const std::vector<SettingUse>& uses, const ModeSet& modes) {
  ASSERT_FALSE(table.empty());
  const std::string field = "{" + std::string(modes.field) + "}";
  for (const SettingRow<Options>& row : table) {
    const SettingRow<Options>* meaning = nullptr;
    for (const SettingRow<Options>& m : meanings) {
      if (std::string(m.field) == row.field) meaning = &m;
    }
    ASSERT_NE(meaning, nullptr) << row.field;
    const std::string help = row.help;
    const std::string text = meaning->help;
    const std::size_t at = help.find(text);
    ASSERT_NE(at, std::string::npos) << row.field;
    const std::string note = help.substr(at + text.size());
    EXPECT_TRUE(note.empty() || note.rfind("; ", 0) == 0) << row.field << ": " << note;
    const std::string opening = help.substr(0, at);
    // The runs the opening names: the main job, and the modes after the mode's field.
    const bool main_job = opening.find(modes.main_job) != std::string::npos;
    std::vector<std::string> named;
    const std::size_t list = opening.rfind(field + " ");  // after "no {optimize} or"
    if (list != std::string::npos) {
      const std::size_t begin = list + field.size() + 1;
      std::string rest = opening.substr(begin, opening.find(": ", begin) - begin);
      for (std::size_t bar = rest.find('|'); bar != std::string::npos; bar = rest.find('|')) {
        named.push_back(rest.substr(0, bar));
        rest.erase(0, bar + 1);
      }
      named.push_back(rest);
    } else if (opening.find(field + ": ") != std::string::npos) {
      named = modes.modes;  // every mode
    }
    const SettingUse* use = nullptr;
    for (const SettingUse& u : uses) {
      if (u.setting == row.field) use = &u;
    }
    std::vector<std::string> used = modes.modes;  // not listed: every run
    bool main_used = true;
    if (use != nullptr) {
      used.clear();
      for (const std::string& m : modes.modes) {
        if (use->UsedBy(m)) used.push_back(m);
      }
      main_used = use->UsedBy("");
    }
    if (opening.empty()) {  // every run uses it
      EXPECT_TRUE(main_used && used == modes.modes) << row.field;
      continue;
    }
    EXPECT_EQ(opening.rfind("with ", 0), 0u) << row.field;
    EXPECT_EQ(named, used) << row.field;
    EXPECT_EQ(main_job, main_used) << row.field;
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
