// Branch switching at a grazing (SwitchAtGrazing of branch_switch.hpp, docs/continuation.md).
// References, independent of the switch: Newton shooting with the motion's period from its state
// (periodic.hpp), a direct run of the simulator from it (simulator.hpp), and the original
// branch's own points on both sides of the grazing.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "capsubot/attract/periodic.hpp"
#include "capsubot/continue/branch_switch.hpp"
#include "capsubot/continue/parameter_branch.hpp"
#include "capsubot/simulate/simulator.hpp"
#include "continue/one_impact_family.hpp"

namespace capsubot {
namespace {

using testing::Find;
using testing::InvalidArgumentMessage;
using testing::kA;
using testing::kPhi0;
using testing::OrbitAt;
using testing::Range;
using testing::Robot;
using testing::RobustGait;
using testing::StartAt;
using testing::UnstableBranchInA;

// The switched branch's corrector stops at a residual of 1e-12; Newton shooting from its state
// moves it by that residual times the inverse of (J - I).
constexpr double kShootingTol = 1e-9;
// How far a direct run may drift from an unstable periodic motion and still be on it. The run
// starts within kStartError of the fixed point (the corrector's tolerance) and the departure
// grows by the spectral radius rho at each return, so it stays within kStay for
// log(kStay / kStartError) / log(rho) returns: that many are checked. For the gait's switched
// motion below (period 6, rho = 341) that is 2 returns.
constexpr double kStay = 1e-6;
constexpr double kStartError = 1e-12;

// Impacts per period differ (right or left), compared over a common multiple of the periods.
bool OtherImpactsPerPeriod(const PeriodicMotion& a, const PeriodicMotion& b) {
  return a.impacts_right * b.period != b.impacts_right * a.period ||
         a.impacts_left * b.period != b.impacts_left * a.period;
}

double Distance(double x, double u, double v, const PhaseState& z) {
  return std::max({std::abs(x - z.x), std::abs(u - z.u), std::abs(v - z.v)});
}

// m is a periodic motion of robot r: Newton shooting with its period from its state converges
// there, and a direct run of the simulator from it returns to it after each period p with the
// motion's impacts, for as many returns as its instability lets any run stay on it.
::testing::AssertionResult IsPeriodicMotion(const RobotModel& r, const PeriodicMotion& m) {
  const PeriodicMotion shot = ShootPeriodicMotion(r, m.state, m.period, ShootingOptions{});
  const double moved = Distance(shot.state.x, shot.state.u, shot.state.v, m.state);
  if (shot.status != ShootingStatus::kConverged || !(shot.residual <= kShootingTol) ||
      !(moved <= kShootingTol)) {
    return ::testing::AssertionFailure() << "shooting: " << ShootingStatusName(shot.status)
                                         << ", residual " << shot.residual << ", moved " << moved;
  }
  const Forcing at_psi = r.forcing.WithPhase(r.forcing.phi0() + m.state.psi);
  const int returns = std::max(1, static_cast<int>(std::log(kStay / kStartError) /
                                                   std::log(std::max(m.spectral_radius, 2.0))));
  for (int k = 1; k <= returns; ++k) {
    const SimResult run =
        Simulate(at_psi, r.params, StartAt(r.alpha, m.state.x, m.state.u, m.state.v, k * m.period));
    const double d = Distance(run.final_state.x, run.final_state.u, run.final_state.v, m.state);
    if (run.status != SimStatus::kOk || !(d <= kStay) || run.impacts_right != k * m.impacts_right ||
        run.impacts_left != k * m.impacts_left) {
      return ::testing::AssertionFailure()
             << "direct run of " << k << " x " << m.period
             << " periods: " << SimStatusName(run.status) << ", " << d << " from the state, "
             << run.impacts_right << " right + " << run.impacts_left << " left impacts";
    }
  }
  return ::testing::AssertionSuccess() << returns << " returns";
}

TEST(GrazingSwitch, RobustGaitGoesOnBeyondItsGrazingWithOtherImpactsPerPeriod) {
  // The robust gait's branch in alpha over the range of its robustness (gait_robustness.hpp)
  // grazes the left wall at alpha = 0.6319567436 with alpha falling (branch_edges_test.cpp
  // checks such ends against a bisection on the motion's existence).
  const Orbit o = RobustGait();
  const Params params{o.T0, o.e};
  const RobotFamily family = NamedParameterFamily({o.forcing, params, o.alpha}, "alpha");
  const ContinuationOptions range = Range(0.5 * o.alpha, 0.5 * (1.0 + o.alpha), o.alpha);
  const Branch gait = ContinueBranch(family, OrbitImpactState(o, o.forcing), range);
  ASSERT_EQ(gait.status, ContinuationStatus::kOk) << gait.message;
  const SpecialPoint* graze = Find(gait, SpecialPointType::kGrazing);
  ASSERT_NE(graze, nullptr);
  ASSERT_EQ(graze->motion.impacts_right + graze->motion.impacts_left, 1);
  const Branch beyond = SwitchAtGrazing(family, gait, *graze, range);
  ASSERT_EQ(beyond.status, ContinuationStatus::kOk) << beyond.message;
  const BranchPoint& first = beyond.points[static_cast<std::size_t>(beyond.start_index)];
  SCOPED_TRACE(first.parameter);
  EXPECT_LT(first.parameter, graze->parameter);  // beyond it, on the side alpha was falling to
  EXPECT_TRUE(OtherImpactsPerPeriod(first.motion, graze->motion))
      << first.motion.impacts_right << " right + " << first.motion.impacts_left << " left per "
      << first.motion.period;
  EXPECT_TRUE(IsPeriodicMotion(family(first.parameter), first.motion));
}

TEST(GrazingSwitch, UnstableOrbitInAEndsAtItsGrazing) {
  const Branch b = UnstableBranchInA();
  const SpecialPoint* graze = Find(b, SpecialPointType::kGrazing);
  ASSERT_NE(graze, nullptr);
  // The branch ends at the grazing: the motion with two right-wall impacts lies on the same
  // side of it (smaller A), on a branch that turns back there, which no step within its own
  // length reaches; nothing with other impacts lies beyond.
  EXPECT_EQ(b.forward_end, BranchEnd::kGrazing);
  EXPECT_EQ(graze->wall, Wall::kRight);
  for (const BranchPoint& p : b.points) {
    ASSERT_EQ(p.motion.impacts_right, 1) << p.parameter;
    EXPECT_LE(p.parameter, graze->parameter);
  }
  const double alpha = OrbitAt(kA, kPhi0).alpha;
  const Branch beyond = SwitchAtGrazing([alpha](double A) { return Robot(alpha, A); }, b, *graze,
                                        Range(0.03, 0.079, kA));
  EXPECT_EQ(beyond.status, ContinuationStatus::kNoMotion);
  EXPECT_TRUE(beyond.points.empty());
  EXPECT_EQ(beyond.message,
            "no periodic motion with other impacts per period at the parameter +1e-05 to +0.001 "
            "beyond the grazing (Newton shooting from its state, also after 50 periods of the "
            "simulator): the motion ends at the grazing");
}

TEST(GrazingSwitch, RangeEndingAtTheGrazingLeavesNoRoomBeyondIt) {
  const Branch b = UnstableBranchInA();
  const SpecialPoint* graze = Find(b, SpecialPointType::kGrazing);
  ASSERT_NE(graze, nullptr);
  const double alpha = OrbitAt(kA, kPhi0).alpha;
  const Branch beyond = SwitchAtGrazing([alpha](double A) { return Robot(alpha, A); }, b, *graze,
                                        Range(0.03, graze->parameter + 1e-6, kA));
  EXPECT_EQ(beyond.status, ContinuationStatus::kNoMotion);
  EXPECT_EQ(beyond.message.rfind("no parameter +1e-05 to +0.001 beyond the grazing lies inside "
                                 "the range [0.03, 0.06314",
                                 0),
            0U)
      << beyond.message;
}

TEST(GrazingSwitch, RefusesAPointThatIsNoGrazingOfTheBranch) {
  const Branch b = UnstableBranchInA();
  const double alpha = OrbitAt(kA, kPhi0).alpha;
  const RobotFamily family = [alpha](double A) { return Robot(alpha, A); };
  SpecialPoint fold;
  fold.type = SpecialPointType::kFold;
  fold.after_point = 0;
  EXPECT_EQ(
      InvalidArgumentMessage([&] { SwitchAtGrazing(family, b, fold, Range(0.03, 0.079, kA)); }),
      "special point type = fold (after_point = 0) is invalid: expected a grazing of the "
      "branch");
  const SpecialPoint* graze = Find(b, SpecialPointType::kGrazing);
  ASSERT_NE(graze, nullptr);
  SpecialPoint outside = *graze;
  outside.after_point = static_cast<int>(b.points.size()) - 1;
  EXPECT_NE(InvalidArgumentMessage([&] {
              SwitchAtGrazing(family, b, outside, Range(0.03, 0.079, kA));
            }).find("is invalid: expected a grazing of the branch"),
            std::string::npos);
}

}  // namespace
}  // namespace capsubot
