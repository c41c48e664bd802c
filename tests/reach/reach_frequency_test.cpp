// The motor's frequency free (docs/reach.md, "Frequency"): T0 is a variable with the bound tied
// to it and the objective is v_mean / sqrt(T0). Reference numbers come from FindAttractors run
// here at the winner's T0, and from the robot at its own T0.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "capsubot/optimize/optimize_forcing.hpp"
#include "capsubot/reach/optimize_reach.hpp"
#include "reach/quick_reach.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::Near;

// The bound holds to rounding of the ratio bound/T0 times T0.
constexpr double kBoundRoundingTol = 1e-12;

ReachOptions QuickOptions() { return testing::QuickReachOptions(30, 15, 3); }

TEST(ReachFrequency, TheWinnersSpeedIsItsMeanVelocityOverTheRootOfItsT0) {
  Params params;  // T0 = 1, e = 1
  ReachOptions o = QuickOptions();
  o.T0_min = 0.125;
  o.T0_max = 1.0;
  const ReachResult r = OptimizeReach(params, o);
  ASSERT_FALSE(std::isnan(r.mean_velocity)) << r.message;
  ASSERT_GE(r.T0, o.T0_min);
  ASSERT_LE(r.T0, o.T0_max);
  EXPECT_EQ(r.physical_speed, r.mean_velocity / std::sqrt(r.T0));
  // The bound is tied to T0: max |F| <= T0 at the winner's own T0.
  EXPECT_LE(r.max_abs_force, r.T0 * (1.0 + kBoundRoundingTol));
  EXPECT_TRUE(Near(r.force_bound, r.T0, kBoundRoundingTol));
  // The reported numbers are those of the robot at the winner's T0, run again here.
  Params at = params;
  at.T0 = r.T0;
  EXPECT_EQ(FindAttractors({r.forcing, at, r.alpha}, o.check).mean_velocity, r.mean_velocity);
  // The robust gait at the robot's own T0 is one of the candidates: the winner is at least as
  // fast in units of sqrt(mu g L) as the gait's motion from rest (sqrt(T0) = 1 there).
  ASSERT_TRUE(r.seed.from_rest.checked);
  if (r.robust_to_settings) {
    EXPECT_GE(r.physical_speed, r.seed.from_rest.attractors.mean_velocity);
  }
  EXPECT_NE(r.message.find("sqrt(mu g L)"), std::string::npos) << r.message;
}

TEST(ReachFrequencyInput, ARangeThatDoesNotHoldTheRobotsT0IsRefusedByName) {
  Params params;
  params.T0 = 2.0;
  ReachOptions o = QuickOptions();
  o.T0_min = 0.125;
  o.T0_max = 1.0;
  try {
    OptimizeReach(params, o);
    ADD_FAILURE() << "T0 = 2 outside [0.125, 1] accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "T0 = 2 is invalid: expected T0_min = 0.125 <= T0 <= T0_max = 1 (the robot's own "
              "frequency is in the range searched)");
  }
  o.T0_min = 1.0;
  o.T0_max = 0.5;
  try {
    o.Validate();
    ADD_FAILURE() << "an empty range accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "T0_min = 1, T0_max = 0.5 are invalid: expected 0 < T0_min < T0_max, finite (or "
              "both NaN: T0 fixed)");
  }
}

}  // namespace
}  // namespace capsubot
