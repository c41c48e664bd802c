// The start of a simulation as a user gives it (capsubot/job/simulate_start_spec.hpp): the
// state and the mass ratio, all of them, or the analytic orbit instead, with the messages in
// the front end's names.

#include "capsubot/job/simulate_start_spec.hpp"

#include <gtest/gtest.h>

#include <string>
#include <variant>

#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::InvalidArgumentMessage;

TEST(SimulateStartSpec, GivesTheStateOrTheOrbit) {
  const SimulateStart state = SimulateStartSpec{0.3, 0.5, 0.1, -0.2}.Build(false, "ask");
  ASSERT_TRUE(std::holds_alternative<SimulateFromState>(state));
  const SimulateFromState& s = std::get<SimulateFromState>(state);
  EXPECT_EQ(s.alpha, 0.3);
  EXPECT_EQ(s.x0, 0.5);
  EXPECT_EQ(s.u0, 0.1);
  EXPECT_EQ(s.v0, -0.2);
  EXPECT_TRUE(std::holds_alternative<SimulateFromOrbit>(SimulateStartSpec{}.Build(true, "ask")));
}

TEST(SimulateStartSpec, NamesWhatIsMissingOrTooMuchInTheFrontEndsNames) {
  const FlagNames flags = {
      {"alpha", "--alpha"}, {"x0", "--x0"}, {"u0", "--u0"}, {"v0", "--v0"}, {"from_orbit", "-O"}};
  const SimulateStartSpec no_alpha{std::nullopt, 0.5, 0.0, 0.0};
  EXPECT_EQ(InvalidArgumentMessage([&] { no_alpha.Build(false, "-O", flags); }),
            "--alpha is missing: give the mass ratio (or -O)");
  const SimulateStartSpec no_v0{0.3, 0.5, 0.0, std::nullopt};
  EXPECT_EQ(InvalidArgumentMessage([&] { no_v0.Build(false, "from_orbit=True"); }),
            "the initial state is missing: give all of x0, u0, v0 (or from_orbit=True)");
  EXPECT_EQ(InvalidArgumentMessage([&] { no_v0.Build(true, "-O", flags); }),
            "-O takes the state and alpha from the analytic orbit: do not give --alpha, --x0, "
            "--u0 or --v0 with it");
}

}  // namespace
}  // namespace capsubot
