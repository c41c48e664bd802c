// The table of the reach search's effort (capsubot/job/reach_effort_settings.hpp): its rows are
// well formed, and each row's field is the name ReachEffort::Validate gives the value it sets,
// so that a front end's flag and the message refusing its value name one setting.

#include "capsubot/job/reach_effort_settings.hpp"

#include <gtest/gtest.h>

#include <string>
#include <type_traits>
#include <variant>

#include "job/setting_table_checks.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

// The drive budgets' help names the harmonics of a Fourier drive, a setting of the optimize
// job and not of the effort.
TEST(ReachEffortSettings, TheTableIsWellFormed) {
  EXPECT_TRUE(testing::WellFormed(ReachEffortSettings(), {"harmonics"}));
}

// Every budget and the time limit refuse -1 (each rule asks for a value >= 0, or > 0).
TEST(ReachEffortSettings, EachFieldIsTheNameOfItsValuesRule) {
  ASSERT_FALSE(ReachEffortSettings().empty());
  for (const SettingRow<ReachEffort>& row : ReachEffortSettings()) {
    ReachEffort effort;
    std::visit(
        [&effort](auto member) {
          using Field = std::decay_t<decltype(effort.*member)>;
          if constexpr (std::is_arithmetic_v<Field>) effort.*member = Field(-1);
        },
        row.member);
    const std::string message = testing::InvalidArgumentMessage([&] { effort.Validate(); });
    EXPECT_EQ(message.rfind(std::string(row.field) + " = -1 is invalid", 0), 0u)
        << row.field << ": \"" << message << "\"";
  }
}

}  // namespace
}  // namespace capsubot
