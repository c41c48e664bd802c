// The tables of the robot's parameters, its mass ratio and the margins of a gait
// (capsubot/job/params_settings.hpp): a row per field, each with a help, and the defaults a
// front end shows are the library's (Params{}, Margins{}: no margins).

#include "capsubot/job/params_settings.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <type_traits>
#include <variant>

#include "setting_table_checks.hpp"

namespace capsubot {
namespace {

using testing::WellFormed;

TEST(ParamsSettings, EachParameterAndMarginHasARowOfItsOwn) {
  EXPECT_TRUE(WellFormed(ParamsSettings()));
  EXPECT_TRUE(WellFormed(MarginsSettings()));
  EXPECT_TRUE(WellFormed(MassRatioSettings()));
}

// The mass ratio has no default: every command on a given robot asks for it.
TEST(ParamsSettings, TheMassRatioIsTheRobotsAndHasNoDefault) {
  ASSERT_EQ(MassRatioSettings().size(), 1u);
  EXPECT_STREQ(MassRatioSettings().front().field, "alpha");
  RobotModel robot;
  robot.alpha = 0.25;
  const auto* member = std::get_if<double RobotModel::*>(&MassRatioSettings().front().member);
  ASSERT_NE(member, nullptr);
  EXPECT_EQ(robot.*(*member), 0.25);
  EXPECT_TRUE(std::isnan(RobotModel{}.alpha));
}

// The defaults shown are those of a robot with no margins: the physical validity.
TEST(ParamsSettings, TheMarginsDefaultToNone) {
  const Margins none;
  ASSERT_FALSE(MarginsSettings().empty());
  for (const auto& row : MarginsSettings()) {
    std::visit(
        [&](auto m) {
          using Field = std::decay_t<decltype(none.*m)>;
          if constexpr (std::is_same_v<Field, double>) {
            EXPECT_EQ(none.*m, 0.0) << row.field;
          }
        },
        row.member);
  }
}

}  // namespace
}  // namespace capsubot
