// How a front end names the settings (capsubot/model/setting_names.hpp): a field as a flag or a
// keyword, and a message of a lower stage rewritten in the front end's names, where only a
// setting's own name is rewritten (not part of a longer name, a flag, a member path or an
// operand of an expression).

#include "capsubot/model/setting_names.hpp"

#include <gtest/gtest.h>

#include <string>

namespace capsubot {
namespace {

const FlagNames kNames = {
    {"alpha", "--alpha"}, {"bound", "--bound"}, {"from", "--from"}, {"max_period", "--max-period"}};

TEST(SettingNames, AFieldIsAFlagOrAKeyword) {
  const SettingNames flags{kNames};
  const SettingNames keywords{{}, SettingNames::Style::kKeywords};
  EXPECT_EQ(flags.Name("max_period"), "--max-period");
  EXPECT_EQ(flags.Name("hops"), "hops");  // no entry: the field
  EXPECT_EQ(flags.InRule("max_period"), "max-period");
  EXPECT_EQ(keywords.InRule("max_period"), "max_period");
  EXPECT_EQ(flags.Given("alpha", "0.5"), "--alpha 0.5");
  EXPECT_EQ(keywords.Given("problem", "reach"), "problem='reach'");
  EXPECT_EQ(flags.Absent("alpha"), "no --alpha");
  EXPECT_EQ(keywords.Absent("alpha"), "alpha=None");
  EXPECT_EQ(Without(kNames, {"alpha", "from"}),
            (FlagNames{{"bound", "--bound"}, {"max_period", "--max-period"}}));
}

TEST(WithFlagNames, RewritesTheSettingThatBeginsTheMessageAndEachSettingGivenAValue) {
  EXPECT_EQ(WithFlagNames("max_period = 0 is invalid: expected 1 <= max_period", kNames),
            "--max-period = 0 is invalid: expected 1 <= max_period");
  EXPECT_EQ(WithFlagNames("alpha: missing", kNames), "--alpha: missing");
  EXPECT_EQ(WithFlagNames("to = 0.1 is invalid with from = 0.1", kNames),
            "to = 0.1 is invalid with --from = 0.1");
  EXPECT_EQ(WithFlagNames("alphabet = 3 is invalid", kNames), "alphabet = 3 is invalid");
}

TEST(WithFlagNames, LeavesWhatIsNotTheSettingsOwnName) {
  for (const std::string message :
       {"force_bound = 2 is invalid",                         // a longer name
        "expected --bound = 2 or less",                       // already a flag
        "seeds[0].alpha = 2 is invalid: expected 0 < alpha",  // a member of another object
        "expected to - from = 0.1 > 0"}) {                    // an operand of an expression
    EXPECT_EQ(WithFlagNames(message, kNames), message) << message;
  }
}

}  // namespace
}  // namespace capsubot
