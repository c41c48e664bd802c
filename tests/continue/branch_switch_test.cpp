// Branch switching at a period doubling (branch_switch.hpp, docs/continuation.md). Reference:
// Newton shooting with period 2 (periodic.hpp) at the parameter of each point of the switched
// branch, independent of the continuation.

#include "capsubot/continue/branch_switch.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "capsubot/attract/attractors.hpp"
#include "capsubot/attract/periodic.hpp"
#include "continue/one_impact_family.hpp"

namespace capsubot {
namespace {

// The corrector stops at a residual of 1e-12; the shooting's own Newton from the branch's
// state moves it by the residual times the inverse of (J - I), well inside this.
constexpr double kStateTol = 1e-9;

// The 2-right/1-left period-1 motion of the stable optimum's force at T0 = 0.5, continued in
// alpha: its period doubling lies near 0.6822, long runs settle on period 2 below it
// (tests/continue/continuation_test.cpp).
const Forcing kForce =
    Forcing::Harmonic(0.34063197373861814, 0.06410131873607934, -3.1181183398453047);

Params HalfT0() {
  Params p;
  p.T0 = 0.5;
  return p;
}

ContinuationOptions Range() {
  ContinuationOptions o;
  o.from = 0.66;
  o.to = 0.70;
  o.start = 0.70;
  o.shooting.transient = 300;
  o.max_points = 60;
  return o;
}

TEST(BranchSwitch, PeriodTwoBranchAgreesWithShootingAtEveryPoint) {
  const Params params = HalfT0();
  const RobotFamily family = [&](double alpha) { return RobotModel{kForce, params, alpha}; };
  const Branch one = ContinueBranch(family, RestStart(0.5, 1.0), Range());
  ASSERT_EQ(one.status, ContinuationStatus::kOk);
  const auto pd = std::find_if(
      one.special_points.begin(), one.special_points.end(),
      [](const SpecialPoint& s) { return s.type == SpecialPointType::kPeriodDoubling; });
  ASSERT_NE(pd, one.special_points.end());
  const Branch two = SwitchAtPeriodDoubling(family, *pd, Range());
  ASSERT_EQ(two.status, ContinuationStatus::kOk) << two.message;
  ASSERT_GE(two.points.size(), 10U);
  bool below = false;
  for (const BranchPoint& b : two.points) {
    SCOPED_TRACE(b.parameter);
    EXPECT_EQ(b.motion.period, 2);
    EXPECT_EQ(b.motion.impacts_right, 4);
    EXPECT_EQ(b.motion.impacts_left, 2);
    const PeriodicMotion shot =
        ShootPeriodicMotion({kForce, params, b.parameter}, b.motion.state, 2, ShootingOptions{});
    ASSERT_EQ(shot.status, ShootingStatus::kConverged);
    EXPECT_LE(std::abs(shot.state.x - b.motion.state.x), kStateTol);
    EXPECT_LE(std::abs(shot.state.u - b.motion.state.u), kStateTol);
    EXPECT_LE(std::abs(shot.state.v - b.motion.state.v), kStateTol);
    below = below || b.parameter < pd->parameter - 1e-3;
  }
  // The long runs find the period-2 motion below the flip: so does the switched branch.
  EXPECT_TRUE(below);
}

TEST(BranchSwitch, PeriodTwoBranchEndsWhereItMeetsThePeriodOneMotion) {
  // The example's period doubling at alpha = 0.2229 (docs/continuation.md) with a range that
  // starts just below it: the period-2 branch runs from the range's end to the doubling, where
  // it passes through the period-1 motion; beyond, it is the same motion shifted by one period.
  // It once went on and came back, reporting both ends at alpha = 0.22289.
  const Orbit o = testing::OrbitAt(testing::kA, testing::kPhi0);
  const RobotFamily family = [](double alpha) { return testing::Robot(alpha); };
  ContinuationOptions opt = testing::Range(0.22289, 0.3, o.alpha);
  const Branch one = ContinueBranch(family, testing::AfterImpact(o, testing::kPhi0), opt);
  const SpecialPoint* pd = testing::Find(one, SpecialPointType::kPeriodDoubling);
  ASSERT_NE(pd, nullptr);
  const Branch two = SwitchAtPeriodDoubling(family, *pd, opt);
  ASSERT_EQ(two.status, ContinuationStatus::kOk) << two.message;
  EXPECT_EQ(two.backward_end, BranchEnd::kRangeEnd);
  EXPECT_EQ(two.forward_end, BranchEnd::kHalfPeriod);
  EXPECT_LT(two.forward_parameter, pd->parameter);
  for (const BranchPoint& b : two.points) EXPECT_LT(b.parameter, pd->parameter);
}

TEST(BranchSwitch, RefusesAPointThatIsNoPeriodDoubling) {
  SpecialPoint fold;
  fold.type = SpecialPointType::kFold;
  fold.located = true;
  const Params params = HalfT0();
  const RobotFamily family = [&](double alpha) { return RobotModel{kForce, params, alpha}; };
  try {
    SwitchAtPeriodDoubling(family, fold, Range());
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "special point type = fold (located = true) is invalid: expected a located "
                 "period_doubling");
  }
}

}  // namespace
}  // namespace capsubot
