// How far T0, e and alpha can move before a gait's motion is lost (gait_robustness.hpp,
// docs/optimize.md). Reference: Newton shooting (periodic.hpp) at each reported limit,
// independent of the continuation that found it.

#include "capsubot/continue/gait_robustness.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "capsubot/attract/periodic.hpp"
#include "capsubot/continue/parameter_branch.hpp"
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
  RobotModel r{o.forcing, Params{o.T0, o.e}, o.alpha};
  SetParameter(r, ParseRobotParameter(name), 0, value);
  return r;
}

PeriodicMotion Shoot(const Orbit& o, const std::string& name, double value,
                     const PhaseState& start) {
  const RobotModel r = At(o, name, value);
  return ShootPeriodicMotion(r, start, 1, ShootingOptions{});
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
    // The end at a wall: the one-impact motion at the grazing, none kAcross beyond it.
    EXPECT_EQ(at.impacts_right + at.impacts_left, 1);
    const PeriodicMotion beyond = Shoot(o, p.name, l.parameter + sign * kAcross, at.state);
    EXPECT_FALSE(beyond.status == ShootingStatus::kConverged &&
                 beyond.impacts_right + beyond.impacts_left == 1);
  } else {
    ADD_FAILURE() << "a limit is a fold, a period doubling or the grazing where it ends here";
  }
}

// A grazing below the gait's value: the gait's signature (one right-wall impact per period) on
// the start's side, another one (or none) just beyond.
void CheckGrazingBelow(const Orbit& o, const ParameterRobustness& p, const SpecialPoint& sp) {
  const PeriodicMotion at = Shoot(o, p.name, sp.parameter, sp.motion.state);
  ASSERT_EQ(at.status, ShootingStatus::kConverged);
  EXPECT_EQ(at.impacts_right + at.impacts_left, 1);
  const PeriodicMotion beyond = Shoot(o, p.name, sp.parameter - kAcross, at.state);
  EXPECT_FALSE(beyond.status == ShootingStatus::kConverged &&
               beyond.impacts_right + beyond.impacts_left == 1)
      << beyond.impacts_right << " right + " << beyond.impacts_left << " left";
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
  // motion ends in a fold when T0 rises, e falls or alpha rises (the kinds found by `capsubot
  // continue` on this gait). When alpha falls the one-impact motion ends where its inner body
  // grazes the left wall (beyond it the robot moves with a left-wall impact too: another motion,
  // not followed): that grazing, located on the wall, is the limit below.
  EXPECT_STREQ(g.parameters[0].up.Name(), "fold");
  EXPECT_STREQ(g.parameters[1].down.Name(), "fold");
  EXPECT_STREQ(g.parameters[1].up.Name(), "range_end");  // e = 1 is the end of [0, 1]
  EXPECT_STREQ(g.parameters[2].up.Name(), "fold");
  const ParameterRobustness& alpha = g.parameters[2];
  ASSERT_TRUE(alpha.down.special);
  ASSERT_EQ(alpha.down.type, SpecialPointType::kGrazing);
  SpecialPoint grazing;
  grazing.parameter = alpha.down.parameter;
  grazing.motion = alpha.down.motion;
  CheckGrazingBelow(o, alpha, grazing);
  EXPECT_EQ(g.parameters[0].value, 1.0);
  EXPECT_EQ(g.parameters[2].from, 0.5 * o.alpha);
}

// The main job's fastest motion from rest at T0 = 1, e = 1 (`capsubot optimize`,
// results/optimum.json, key reach): 73 right-wall impacts in one chattering sequence (each
// slower than the last, ended with the body resting on the wall) and 5 left ones per period.
RobotModel ReachWinner() {
  Params p;
  p.T0 = 1.0;
  p.e = 1.0;
  return {Forcing::Harmonic(0.676979732510288, 0.3230202674897121, -3.089378590956282), p,
          0.9431003086419751};
}

// Where the continuation of that motion finds an impact appear or disappear while nothing but a
// chattering sequence's count changes (the grazings `capsubot optimize` listed as the motion's
// limits before such changes were set apart): T0 = 1.00254 (5 -> 6 left impacts in a
// sequence), e = 0.986933 (74 + 6 -> 73 + 5), alpha = 0.9431 (64 + 3 -> 73 + 5).
struct CountChange {
  const char* name;
  double at;
};
constexpr CountChange kCountChanges[] = {
    {"T0", 1.00254133}, {"e", 0.98693252}, {"alpha", 0.943099983}};
// Either side of a count change, still far from the next special point (1e-4 away at least).
constexpr double kSide = 1e-6;
// The speed goes on through a count change: the mean velocities on its two sides differ by the
// slope of the speed times 2 kSide (about 0.15 per unit), far below this.
constexpr double kSpeedTol = 1e-5;

TEST(GaitRobustness, AChatteringCountChangeIsNoSpecialPoint) {
  const RobotModel r = ReachWinner();
  const Motion m = LongRunMotion(r, RestStart(0.0625, 0.0), MotionOptions{});
  ASSERT_EQ(m.status, MotionStatus::kPeriodic);
  const GaitRobustness g = ComputeMotionRobustness({r, m.section});
  ASSERT_EQ(g.parameters.size(), 3U);
  for (const CountChange& c : kCountChanges) {
    SCOPED_TRACE(c.name);
    const RobotFamily family = NamedParameterFamily(r, c.name);
    // The independent view: Newton shooting on each side; the motion and its speed go on.
    PeriodicMotion side[2];
    for (int k : {0, 1}) {
      const RobotModel at = family(c.at + (k == 0 ? -kSide : kSide));
      side[k] = FindPeriodicMotion(at, m.section, ShootingOptions{});
      ASSERT_EQ(side[k].status, ShootingStatus::kConverged);
      EXPECT_GE(side[k].impacts_right, 60);  // the chattering sequence on both sides
    }
    EXPECT_TRUE(testing::Near(side[0].mean_velocity, side[1].mean_velocity, kSpeedTol));
    const ParameterRobustness* p = nullptr;
    for (const ParameterRobustness& q : g.parameters) p = q.name == c.name ? &q : p;
    ASSERT_NE(p, nullptr);
    EXPECT_GT(p->chatter_changes, 0);
    for (const SpecialPoint& sp : p->special_points) {
      EXPECT_GT(std::abs(sp.parameter - c.at), 10 * kSide) << SpecialPointTypeName(sp.type);
    }
    for (const MotionLimit* l : {&p->down, &p->up}) {
      EXPECT_GT(std::abs(l->parameter - c.at), 10 * kSide) << l->Name();
    }
  }
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
