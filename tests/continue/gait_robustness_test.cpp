// How far T0, e and alpha can move before a gait's motion is lost (gait_robustness.hpp,
// docs/optimize.md). Reference: Newton shooting (periodic.hpp) at each reported limit,
// independent of the continuation that found it.

#include "capsubot/continue/gait_robustness.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "capsubot/attract/periodic.hpp"
#include "capsubot/model/model_parameter.hpp"
#include "continue/one_impact_family.hpp"

namespace capsubot {
namespace {

using testing::RobustGait;

// At a fold the multiplier differs from +1 like the square root of the distance to it: the
// location tolerance 1e-10 in the parameter leaves about 1e-5; the shooting's own central
// differences add about 1e-6.
constexpr double kMultiplierTol = 1e-4;
// A step across a grazing: the grazings are located to 1e-10 by the flight's distance from the
// wall (branch_edges_test.cpp checks them against a bisection on the motion's existence);
// 1e-5 is far beyond that and far below the distance to the fold.
constexpr double kAcross = 1e-5;

// The robot of the gait with parameter `name` set to `value`.
RobotModel At(const Orbit& o, const std::string& name, double value) {
  RobotModel r{o.forcing, Params{o.T0, o.e, 0.0}, o.alpha};
  SetParameter(r, ParseRobotParameter(name), 0, value);
  return r;
}

PeriodicMotion Shoot(const Orbit& o, const std::string& name, double value,
                     const PhaseState& start) {
  const RobotModel r = At(o, name, value);
  return ShootPeriodicMotion(r.forcing, r.params, r.alpha, start, 1, ShootingOptions{});
}

// The checks of one limit in direction `sign` (-1 down, +1 up) from the gait's value.
void CheckLimit(const Orbit& o, const ParameterRobustness& p, const MotionLimit& l, int sign) {
  SCOPED_TRACE(p.name + (sign < 0 ? " down" : " up") + ": " + l.Name());
  EXPECT_GE(l.parameter, p.from);
  EXPECT_LE(l.parameter, p.to);
  if (!l.special) return;
  // Folds are located to 1e-10; a grazing's bisection ends within about 1e-9.
  EXPECT_LE(l.accuracy, 0.01 * kAcross);
  const PeriodicMotion at = Shoot(o, p.name, l.parameter, l.motion.state);
  ASSERT_EQ(at.status, ShootingStatus::kConverged);
  if (l.type == SpecialPointType::kFold) {
    EXPECT_LE(at.distance_to_plus_one, kMultiplierTol) << at.multipliers.front();
  } else if (l.type == SpecialPointType::kPeriodDoubling) {
    EXPECT_LE(at.distance_to_minus_one, kMultiplierTol) << at.multipliers.front();
  } else if (l.type == SpecialPointType::kGrazing) {
    // The gait's signature (one right-wall impact per period) on the start's side, another
    // one (or none) just beyond.
    EXPECT_EQ(at.impacts_right + at.impacts_left, 1);
    const PeriodicMotion beyond = Shoot(o, p.name, l.parameter + sign * kAcross, at.state);
    EXPECT_FALSE(beyond.status == ShootingStatus::kConverged &&
                 beyond.impacts_right + beyond.impacts_left == 1)
        << beyond.impacts_right << " right + " << beyond.impacts_left << " left";
  }
}

TEST(GaitRobustness, EachLimitOfTheRobustGaitIsARealSpecialPoint) {
  const Orbit o = RobustGait();
  const GaitRobustness g = ComputeGaitRobustness(o);
  ASSERT_EQ(g.parameters.size(), 3U);
  for (const ParameterRobustness& p : g.parameters) {
    ASSERT_EQ(p.status, ContinuationStatus::kOk) << p.name << ": " << p.message;
    CheckLimit(o, p, p.down, -1);
    CheckLimit(o, p, p.up, +1);
  }
  // This gait sits close to a fold (its leading multiplier is the real 0.9 = rho_max): the
  // motion ends in a fold when T0 rises, e falls or alpha rises, and its other side grazes the
  // left wall when alpha falls (the kinds found by `capsubot continue` on this gait).
  EXPECT_STREQ(g.parameters[0].up.Name(), "fold");
  EXPECT_STREQ(g.parameters[1].down.Name(), "fold");
  EXPECT_STREQ(g.parameters[1].up.Name(), "range_end");  // e = 1 is the end of [0, 1]
  EXPECT_STREQ(g.parameters[2].down.Name(), "grazing");
  EXPECT_STREQ(g.parameters[2].up.Name(), "fold");
  EXPECT_EQ(g.parameters[0].value, 1.0);
  EXPECT_EQ(g.parameters[2].from, 0.5 * o.alpha);
}

TEST(GaitRobustness, BadFactorIsNamed) {
  RobustnessOptions options;
  options.t0_factor = 1.0;
  try {
    ComputeGaitRobustness(RobustGait(), options);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "t0_factor = 1 is invalid: expected a finite number > 1");
  }
}

}  // namespace
}  // namespace capsubot
