// The sweep job's settings (capsubot/job/sweep_settings.hpp): the table of which mode reads
// which setting agrees with what each mode reads, a setting takes effect only when given, each
// mode keeps its own defaults, and the messages name the settings in the front end's names.

#include "capsubot/job/sweep_settings.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <variant>

#include "capsubot/io/io.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

// The settings of `mode` over a one-point grid of restitutions, writing to standard output.
SweepSettings SettingsOf(const std::string& mode) {
  SweepSettings s;
  s.optimize = mode;
  s.grid.axes.push_back(ParseGridAxis("e=0.5"));
  s.file.output = "-";
  return s;
}

TEST(SweepSettings, EveryModeReadsEverySettingItsRowNames) {
  int pairs = 0;
  for (const SettingUse& use : SweepSettingUses()) {
    ASSERT_FALSE(use.modes.empty()) << use.setting;
    for (const std::string& mode : use.modes) {
      SweepSettings s = SettingsOf(mode);
      s.given.insert(use.setting);  // at its default value
      // A refusal of the value (a missing force, the multistart stage, a pulse's part) is
      // fine; a setting of the row that the mode does not read is a std::logic_error.
      try {
        SweepJobFrom(s, SettingNames{});
      } catch (const std::invalid_argument&) {
      } catch (const std::logic_error& e) {
        ADD_FAILURE() << e.what();
      }
      ++pairs;
    }
  }
  EXPECT_GE(pairs, static_cast<int>(SweepSettingUses().size()));
}

TEST(SweepSettings, ASettingTakesEffectOnlyWhenGiven) {
  SweepSettings s = SettingsOf("forcing");
  s.search.hops = ForcingDesignOptions{}.hops + 4;
  EXPECT_EQ(std::get<SweepForcingMode>(SweepJobFrom(s, {}).mode).search.hops,
            ForcingDesignOptions{}.hops);
  s.given.insert("hops");
  EXPECT_EQ(std::get<SweepForcingMode>(SweepJobFrom(s, {}).mode).search.hops,
            ForcingDesignOptions{}.hops + 4);
}

TEST(SweepSettings, StableOnlyMeansRhoMaxOne) {
  SweepSettings s = SettingsOf("phi0");
  s.A = 0.3;
  s.c = 0.1;
  s.given = {"A", "c", "stable_only"};
  s.stable_only = true;
  EXPECT_EQ(std::get<SweepPhaseMode>(SweepJobFrom(s, {}).mode).phase.gait.rho_max, 1.0);
}

TEST(SweepSettings, TheReachSearchKeepsTheRobustGaitsDefaultsAndSaysSo) {
  SweepSettings s = SettingsOf("reach");
  const SweepReachMode reach = std::get<SweepReachMode>(SweepJobFrom(s, {}).mode);
  EXPECT_EQ(reach.search.gait.margins.clearance_stroke, kRobustMarginStroke);
  EXPECT_EQ(reach.search.gait.margins.stick, kRobustStickMargin);
  EXPECT_EQ(reach.search.gait.rho_max, kRobustRhoMax);
  using Defaults = std::vector<std::pair<std::string, std::string>>;
  // The command's defaults (Margins, SearchRequest) differ from the robust gait's in these.
  ASSERT_NE(Margins{}.clearance_stroke, kRobustMarginStroke);
  ASSERT_NE(Margins{}.stick, kRobustStickMargin);
  ASSERT_NE(SearchRequest{}.gait.rho_max, kRobustRhoMax);
  EXPECT_EQ(SweepModeDefaults(s), (Defaults{{"margin_stroke", FormatNumber(kRobustMarginStroke)},
                                            {"stick_margin", FormatNumber(kRobustStickMargin)},
                                            {"rho_max", FormatNumber(kRobustRhoMax)}}));
  s.margins.clearance_stroke = 0.1;
  s.given.insert("margin_stroke");
  EXPECT_EQ(std::get<SweepReachMode>(SweepJobFrom(s, {}).mode).search.gait.margins.clearance_stroke,
            0.1);
  EXPECT_EQ(SweepModeDefaults(s), (Defaults{{"stick_margin", FormatNumber(kRobustStickMargin)},
                                            {"rho_max", FormatNumber(kRobustRhoMax)}}));
  EXPECT_TRUE(SweepModeDefaults(SettingsOf("forcing")).empty());
}

// `settings`' refusal in `names` ("" when accepted).
std::string Refusal(const SweepSettings& settings, const SettingNames& names) {
  return testing::InvalidArgumentMessage([&] { SweepJobFrom(settings, names); });
}

TEST(SweepSettings, TheRulesNameTheSettingsInTheFrontEndsNames) {
  SweepSettings s = SettingsOf("");
  s.grid.axes = {ParseGridAxis("A=0.2,0.3")};
  s.A = 0.5;
  s.c = 0.1;
  s.given = {"A", "c"};
  const SettingNames flags{{{"A", "--A"}, {"grid", "--grid"}, {"optimize", "--optimize"}}};
  EXPECT_EQ(Refusal(s, flags),
            "--A = 0.5 is invalid with --grid A=0.2,0.3: expected the value from only one of them");
  EXPECT_EQ(Refusal(s, {{}, SettingNames::Style::kKeywords}),
            "A = 0.5 is invalid with grid A=0.2,0.3: expected the value from only one of them");

  SweepSettings hops = SettingsOf("fourier");
  hops.given = {"hops"};
  EXPECT_EQ(Refusal(hops, {{{"hops", "--hops"}, {"optimize", "--optimize"}}}),
            "--hops is invalid with --optimize fourier: expected it only with --optimize forcing, "
            "--optimize reach");
  hops.optimize = "";
  EXPECT_EQ(Refusal(hops, {}),
            "hops is invalid without optimize: expected it only with optimize forcing, optimize "
            "reach");
}

}  // namespace
}  // namespace capsubot
