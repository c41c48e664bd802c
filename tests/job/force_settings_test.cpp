// The table of the force's parts (capsubot/job/force_settings.hpp): a row per part, helps that
// name only the force's own parts, and no default shown for a part that is not given.

#include "capsubot/job/force_settings.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <type_traits>
#include <variant>

#include "job/setting_table_checks.hpp"

namespace capsubot {
namespace {

TEST(ForceSettings, EachPartHasARowOfItsOwnAndTheHelpsNameOnlyTheParts) {
  EXPECT_TRUE(testing::WellFormed(ForceSettings()));
  EXPECT_EQ(ForceSettings().size(), 8u);
}

// A part not given is NaN or empty: a front end shows no default (ForceSpec decides what is
// missing, and phi0's default depends on the force's kind).
TEST(ForceSettings, NoPartHasADefault) {
  const ForceText none;
  int checked = 0;
  for (const SettingRow<ForceText>& row : ForceSettings()) {
    std::visit(
        [&](auto member) {
          using Field = std::decay_t<decltype(none.*member)>;
          if constexpr (std::is_same_v<Field, double>) {
            EXPECT_TRUE(std::isnan(none.*member)) << row.field;
            ++checked;
          } else if constexpr (std::is_same_v<Field, std::string>) {
            EXPECT_TRUE((none.*member).empty()) << row.field;
            ++checked;
          }
        },
        row.member);
  }
  EXPECT_EQ(checked, 8);
}

}  // namespace
}  // namespace capsubot
