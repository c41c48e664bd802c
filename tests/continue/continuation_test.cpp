// Continuation of periodic motions (docs/continuation.md). References: the analytic one-impact
// orbit and its impact-map multipliers (orbit.hpp, validity.hpp, stability.hpp), root finders on
// the analytic family (one_impact_family.hpp), Newton shooting (periodic.hpp) and long runs of the
// simulator (attractors.hpp).

#include "capsubot/continue/continuation.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <string>

#include "capsubot/orbit/stability.hpp"
#include "capsubot/orbit/validity.hpp"
#include "continue/one_impact_family.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::AfterImpact;
using testing::AlphaBranch;
using testing::Bisect;
using testing::Find;
using testing::ImpactPhase;
using testing::kA;
using testing::kC;
using testing::kPhi0;
using testing::LargestMassRatio;
using testing::Near;
using testing::NearAbsBelowOne;
using testing::OrbitAt;
using testing::OrbitParams;
using testing::Range;
using testing::Robot;
using testing::RobotOrbitPhase;

// The corrector's residual is 1e-12 and the impact phase is exact to rounding: the mean
// velocity agrees with the analytic orbit's to 1e-9 relative (the required bar).
constexpr double kVelocityTol = 1e-9;
// Central differences of step 1e-6 against the closed-form impact-map Jacobian (required 1e-7).
constexpr double kMultiplierTol = 1e-7;
// The analytic orbit's mass ratio at the simulated impact phase equals the branch's parameter
// to the corrector's residual amplified by the orbit's sensitivity.
constexpr double kParameterTol = 1e-9;
// Special points are located to this in the parameter (required).
constexpr double kLocationTol = 1e-8;

TEST(Continuation, OneImpactBranchInAlphaIsTheAnalyticOrbitAtEveryPoint) {
  const Branch b = AlphaBranch(0.05);
  ASSERT_EQ(b.status, ContinuationStatus::kOk);
  ASSERT_GE(b.points.size(), 40u);
  EXPECT_EQ(b.backward_end, BranchEnd::kRangeEnd);
  EXPECT_EQ(b.forward_end, BranchEnd::kRangeEnd);  // back to alpha = 0.2 after the fold
  for (const BranchPoint& p : b.points) {
    ASSERT_EQ(p.motion.impacts_right, 1) << p.parameter;
    ASSERT_EQ(p.motion.impacts_left, 0) << p.parameter;
    const RobotModel r = Robot(p.parameter);
    const double phi0 = ImpactPhase(r, p.motion);
    const Orbit o = OrbitAt(kA, phi0);
    ASSERT_TRUE(o.ok());
    EXPECT_TRUE(Near(o.alpha, p.parameter, kParameterTol)) << phi0;
    EXPECT_TRUE(Near(p.motion.mean_velocity, o.v_mean, kVelocityTol * std::abs(o.v_mean)))
        << p.parameter;
    const Stability st = ComputeStability(o);
    ASSERT_EQ(p.motion.multipliers.size(), 2u);
    for (int i = 0; i < 2; ++i) {
      const auto mu = p.motion.multipliers[static_cast<std::size_t>(i)];
      const auto ref = st.multipliers[static_cast<std::size_t>(i)];
      EXPECT_TRUE(Near(mu.real(), ref.real(), kMultiplierTol)) << p.parameter;
      EXPECT_TRUE(Near(std::abs(mu.imag()), std::abs(ref.imag()), kMultiplierTol)) << p.parameter;
    }
  }
}

TEST(Continuation, FoldIsWhereTheAnalyticMassRatioIsLargest) {
  // d alpha / d phi0 = 0 of the analytic family between -3.14 and -3.0, where a scan of
  // `capsubot solve` shows alpha rising then falling.
  const double alpha_fold = LargestMassRatio(kA, -3.14, -3.0);
  for (double max_step : {0.05, 0.005}) {  // the step changes the cost, not the fold
    const Branch b = AlphaBranch(max_step);
    const SpecialPoint* fold = Find(b, SpecialPointType::kFold);
    ASSERT_NE(fold, nullptr) << max_step;
    EXPECT_TRUE(fold->located);
    EXPECT_TRUE(Near(fold->parameter, alpha_fold, kLocationTol)) << max_step;
    EXPECT_TRUE(Near(fold->motion.multipliers[0].real(), 1.0, 1e-5));
    // The branch turns there: parameters on both sides of the fold are below it.
    const double top = std::max_element(b.points.begin(), b.points.end(),
                                        [](const BranchPoint& x, const BranchPoint& y) {
                                          return x.parameter < y.parameter;
                                        })
                           ->parameter;
    EXPECT_LE(top, fold->parameter + 1e-12);
  }
}

TEST(Continuation, GrazingIsWhereTheAnalyticOrbitTouchesTheRightWall) {
  // The unstable orbit of the same robot (impact near motor phase 2.94, `capsubot orbits`)
  // continued in A: its interior maximum of x reaches the right wall near A = 0.063 (x_max =
  // 0.974 at A = 0.06 and 1.135 at 0.08), where a second impact appears.
  const double alpha = OrbitAt(kA, kPhi0).alpha;
  const double phi_start = RobotOrbitPhase(kA, alpha, 2.9423);
  double phi = phi_start;
  const auto x_max_minus_one = [&](double A) {
    phi = RobotOrbitPhase(A, alpha, phi);
    const Solution s = Solve(Forcing::Harmonic(A, kC, phi), OrbitParams());
    return s.validity.x_max - 1.0;
  };
  const double A_graze = Bisect(x_max_minus_one, 0.06, 0.065);
  const Orbit o = OrbitAt(kA, phi_start);
  ContinuationOptions opt = Range(0.03, 0.079, kA);
  opt.both_directions = false;
  const Branch b =
      ContinueBranch([&](double A) { return Robot(alpha, A); }, AfterImpact(o, phi_start), opt);
  ASSERT_EQ(b.status, ContinuationStatus::kOk);
  const SpecialPoint* graze = Find(b, SpecialPointType::kGrazing);
  ASSERT_NE(graze, nullptr);
  EXPECT_TRUE(graze->located);
  EXPECT_TRUE(Near(graze->parameter, A_graze, kLocationTol));
  EXPECT_EQ(graze->motion.impacts_right, 1);  // the motion on the side it came from
}

// The 2-right/1-left period-1 motion of the stable optimum's force at T0 = 0.5, continued in
// alpha (the flip the shooting test brackets near 0.6822 by bisection on the multiplier), with
// special points located to `location_tolerance`.
const Forcing kFlipForce =
    Forcing::Harmonic(0.34063197373861814, 0.06410131873607934, -3.1181183398453047);

Params FlipParams() {
  Params params;
  params.T0 = 0.5;
  return params;
}

Branch FlipBranch(double location_tolerance) {
  const RobotFamily family = [](double alpha) {
    return RobotModel{kFlipForce, FlipParams(), alpha};
  };
  ContinuationOptions opt = Range(0.66, 0.70, 0.70);
  opt.shooting.transient = 300;
  opt.location_tolerance = location_tolerance;
  return ContinueBranch(family, RestStart(0.5, 1.0), opt);
}

TEST(Continuation, PeriodDoublingIsWhereThePeriodTwoMotionOfTheLongRunsBegins) {
  const Forcing& force = kFlipForce;
  const Params params = FlipParams();
  const Branch b = FlipBranch(ContinuationOptions{}.location_tolerance);
  ASSERT_EQ(b.status, ContinuationStatus::kOk);
  ASSERT_EQ(b.points[static_cast<std::size_t>(b.start_index)].motion.impacts_right, 2);
  const SpecialPoint* pd = Find(b, SpecialPointType::kPeriodDoubling);
  ASSERT_NE(pd, nullptr);
  ASSERT_TRUE(pd->located);
  EXPECT_TRUE(Near(pd->parameter, 0.6822, 1e-3));
  // The shooting at the located value finds the multiplier -1.
  const PeriodicMotion at =
      ShootPeriodicMotion({force, params, pd->parameter}, pd->motion.state, 1, {});
  ASSERT_EQ(at.status, ShootingStatus::kConverged);
  EXPECT_TRUE(Near(at.multipliers[0].real(), -1.0, 1e-6));
  // Brute force on both sides: long runs from the flip's state, slightly kicked.
  PhaseState kicked = pd->motion.state;
  kicked.x += 1e-4;
  MotionOptions slow;
  slow.transient = 3000;
  const Motion below = LongRunMotion({force, params, pd->parameter - 0.002}, kicked, slow);
  const Motion above = LongRunMotion({force, params, pd->parameter + 0.002}, kicked, slow);
  EXPECT_EQ(below.period, 2);
  EXPECT_EQ(above.period, 1);
  // The period-2 motion exists below the flip: the shooting with period 2 finds it.
  const PeriodicMotion two =
      ShootPeriodicMotion({force, params, pd->parameter - 0.002}, below.section, 2, {});
  ASSERT_EQ(two.status, ShootingStatus::kConverged);
  EXPECT_EQ(two.period, 2);
  EXPECT_EQ(two.impacts_right, 4);
  EXPECT_EQ(two.impacts_left, 2);
}

TEST(Continuation, PeriodDoublingHoldsWithTheLocationToleranceTenThousandTimesCoarser) {
  // The knob location_tolerance from 1e-10 to 1e-6: the same flip, located to the coarser
  // tolerance. Its multiplier is then -1 only to about |d mu / d alpha| 1e-6 (a few 1e-7 here):
  // the confirmation of a located point must accept that.
  constexpr double kCoarse = 1e-6;
  const Branch fine = FlipBranch(ContinuationOptions{}.location_tolerance);
  const Branch coarse = FlipBranch(kCoarse);
  const SpecialPoint* reference = Find(fine, SpecialPointType::kPeriodDoubling);
  ASSERT_NE(reference, nullptr);
  ASSERT_TRUE(reference->located);
  const SpecialPoint* pd = Find(coarse, SpecialPointType::kPeriodDoubling);
  ASSERT_NE(pd, nullptr);
  EXPECT_TRUE(pd->located);
  EXPECT_LE(pd->accuracy, kCoarse);
  EXPECT_TRUE(Near(pd->parameter, reference->parameter, kCoarse));
  EXPECT_EQ(coarse.special_points.size(), fine.special_points.size());
}

TEST(Continuation, SegmentChangeIsWhereTheForceReachesTheFrictionBound) {
  // Continued in T0, the one-impact orbit's rest phase holds the force's extremes: once
  // T0 < A + c = 0.07 the capsule breaks away during it, a new event of the period.
  const Orbit o = OrbitAt(kA, kPhi0);
  const RobotFamily family = [&](double T0) {
    RobotModel r = Robot(o.alpha);
    r.params.T0 = T0;
    return r;
  };
  const Branch b = ContinueBranch(family, AfterImpact(o, kPhi0), Range(0.05, 0.2, 0.1));
  ASSERT_EQ(b.status, ContinuationStatus::kOk);
  const SpecialPoint* change = Find(b, SpecialPointType::kSegmentChange);
  ASSERT_NE(change, nullptr);
  EXPECT_TRUE(change->located);
  EXPECT_TRUE(Near(change->parameter, kA + kC, kLocationTol));
}

TEST(Continuation, SpeedExtremumIsTheFastestPointOfTheBranch) {
  const Branch b = AlphaBranch(0.05);
  const SpecialPoint* top = Find(b, SpecialPointType::kSpeedExtremum);
  ASSERT_NE(top, nullptr);
  for (const BranchPoint& p : b.points)
    EXPECT_LE(p.motion.mean_velocity, top->motion.mean_velocity + 1e-15);
  // Dense reference: the analytic orbit's speed over the phases of that stretch of the family.
  double best = 0.0;
  for (int i = 0; i <= 4000; ++i) {
    const Orbit o = OrbitAt(kA, -2.9 + 0.6 * i / 4000.0);
    if (o.ok() && o.alpha >= 0.2) best = std::max(best, o.v_mean);
  }
  EXPECT_TRUE(NearAbsBelowOne(top->motion.mean_velocity, best, 1e-9));
}

TEST(ContinuationInput, BadOptionsAreNamed) {
  const RobotFamily family = [](double alpha) { return Robot(alpha); };
  const PhaseState start = RestStart(0.5, 0.0);
  const auto message = [&](const ContinuationOptions& o) {
    return testing::InvalidArgumentMessage([&] { ContinueBranch(family, start, o); });
  };
  EXPECT_EQ(message(Range(0.3, 0.2, 0.25)),
            "to = 0.2 is invalid: expected a finite number > from = 0.3");
  EXPECT_EQ(message(Range(0.2, 0.3, 0.4)),
            "start = 0.4 is invalid: expected from = 0.2 <= start <= to = 0.3");
  ContinuationOptions o = Range(0.2, 0.3, 0.25);
  o.max_points = 1;
  EXPECT_EQ(message(o), "max_points = 1 is invalid: expected 2 <= max_points <= 100000");
  o.max_points = 1000000;  // 3.5 GB as JSON: bounded
  EXPECT_EQ(message(o), "max_points = 1000000 is invalid: expected 2 <= max_points <= 100000");
  o = Range(0.2, 0.3, 0.25);
  o.min_step = 0.0;
  EXPECT_EQ(message(o), "min_step = 0 is invalid: expected a finite number > 0");
  o = Range(0.2, 0.3, 0.25);
  o.initial_step = 1.0;
  EXPECT_EQ(
      message(o),
      "initial_step = 1 is invalid: expected min_step = 1e-07 <= initial_step <= max_step = 0.05");
  // A range whose end is no robot: alpha = 1.2.
  EXPECT_EQ(message(Range(0.2, 1.2, 0.25)),
            "mass ratio alpha = 1.2 is invalid: expected 0 < alpha < 1");
}

}  // namespace
}  // namespace capsubot
