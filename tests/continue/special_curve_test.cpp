// Two-parameter curves of special points (docs/continuation.md, "Two-parameter curves").
// References: Newton shooting at each point of a curve (periodic.hpp: its own Jacobian and
// multipliers), and the analytic one-impact orbit at the impact phase the simulator finds there
// (orbit.hpp, stability.hpp, validity.hpp) with root finders on the analytic family
// (one_impact_family.hpp).

#include "capsubot/continue/special_curve.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <string>

#include "capsubot/continue/parameter_branch.hpp"
#include "capsubot/orbit/stability.hpp"
#include "capsubot/orbit/validity.hpp"
#include "continue/one_impact_family.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::AlphaBranch;
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
using testing::UnstableBranchInA;

// Required: a followed period doubling has a multiplier -1 to 1e-8 (the curve holds
// det(P_z + I) to 1e-9; the shooting's own central differences agree to about 1e-10).
constexpr double kFlipTol = 1e-8;
// Required: a followed fold or grazing agrees with the analytic conditions to 1e-8 (the curve's
// grazing lies 1e-9 inside the wall by construction).
constexpr double kAnalyticTol = 1e-8;
// The impact-map multipliers of the analytic orbit against the curve's central differences
// (as for branches: 1e-7).
constexpr double kMultiplierTol = 1e-7;

// The robots (alpha, A) of the example's force.
RobotModel AlphaA(double alpha, double A) { return Robot(alpha, A); }

CurveOptions Box(double from, double to, double from2, double to2, double start2) {
  CurveOptions o;
  o.continuation = Range(from, to, from);
  o.from2 = from2;
  o.to2 = to2;
  o.start2 = start2;
  return o;
}

// The curve of the example branch's special point of this type in (alpha, A), A in
// [0.04, 0.06].
Curve AlphaACurve(SpecialPointType type, double max_step = 0.05) {
  const Branch b = AlphaBranch(0.05);
  const SpecialPoint* sp = Find(b, type);
  EXPECT_NE(sp, nullptr);
  if (sp == nullptr) return {};
  CurveOptions o = Box(0.2, 0.3, 0.04, 0.06, kA);
  o.continuation.max_step = max_step;
  o.continuation.initial_step = std::min(o.continuation.initial_step, max_step);
  return FollowSpecialPoint(AlphaA, *sp, o);
}

// Every few points of a curve, and its ends.
std::vector<std::size_t> Sample(const Curve& c, std::size_t count) {
  std::vector<std::size_t> at;
  const std::size_t n = c.points.size();
  for (std::size_t k = 0; k < count && n > 0; ++k) at.push_back(k * (n - 1) / (count - 1));
  return at;
}

TEST(SpecialCurve, PeriodDoublingCurveHasAMultiplierMinusOneAtEveryPoint) {
  const Curve c = AlphaACurve(SpecialPointType::kPeriodDoubling);
  ASSERT_EQ(c.status, ContinuationStatus::kOk) << c.message;
  ASSERT_GE(c.points.size(), 10u);
  EXPECT_EQ(c.backward_end, BranchEnd::kRangeEnd);
  EXPECT_EQ(c.forward_end, BranchEnd::kRangeEnd);
  for (const CurvePoint& p : c.points) {
    // Newton shooting with period 1 from the point's state, at its robot: its own Jacobian.
    const RobotModel r = AlphaA(p.parameter, p.parameter2);
    const PeriodicMotion m = ShootPeriodicMotion(r, p.motion.state, 1, {});
    ASSERT_EQ(m.status, ShootingStatus::kConverged) << p.parameter << " " << p.parameter2;
    double nearest = HUGE_VAL;
    for (const auto& mu : m.multipliers) nearest = std::min(nearest, std::abs(mu + 1.0));
    EXPECT_LE(nearest, kFlipTol) << p.parameter << " " << p.parameter2;
  }
  // The analytic orbit there (independent of the central differences): its impact map has the
  // multiplier -1 too.
  for (std::size_t i : Sample(c, 5)) {
    const CurvePoint& p = c.points[i];
    const Orbit o = OrbitAt(p.parameter2, ImpactPhase(AlphaA(p.parameter, p.parameter2), p.motion));
    ASSERT_TRUE(o.ok());
    EXPECT_TRUE(Near(o.alpha, p.parameter, kAnalyticTol));
    const Stability st = ComputeStability(o);
    double nearest = HUGE_VAL;
    for (const auto& mu : st.multipliers) nearest = std::min(nearest, std::abs(mu + 1.0));
    EXPECT_LE(nearest, kMultiplierTol) << p.parameter << " " << p.parameter2;
  }
}

TEST(SpecialCurve, FoldCurveIsWhereTheAnalyticMassRatioIsLargest) {
  for (double max_step : {0.05, 0.005}) {  // the step changes the cost, not the curve
    const Curve c = AlphaACurve(SpecialPointType::kFold, max_step);
    ASSERT_EQ(c.status, ContinuationStatus::kOk) << c.message;
    ASSERT_GE(c.points.size(), 5u);
    for (std::size_t i : Sample(c, 4)) {
      const CurvePoint& p = c.points[i];
      const double phi = ImpactPhase(AlphaA(p.parameter, p.parameter2), p.motion);
      EXPECT_TRUE(
          Near(p.parameter, LargestMassRatio(p.parameter2, phi - 0.1, phi + 0.1), kAnalyticTol))
          << "A = " << p.parameter2 << ", max_step " << max_step;
      EXPECT_TRUE(Near(p.motion.multipliers[0].real(), 1.0, kFlipTol));
    }
  }
}

TEST(SpecialCurve, GrazingCurveIsWhereTheAnalyticOrbitTouchesTheRightWall) {
  // The unstable orbit of the example robot continued in A grazes the right wall at A = 0.0631
  // (continuation_test.cpp); its grazing followed in (A, alpha), alpha in [0.2, 0.35].
  const double alpha = OrbitAt(kA, kPhi0).alpha;
  const auto robot = [](double A, double a) { return Robot(a, A); };
  const Branch b = UnstableBranchInA();
  const SpecialPoint* graze = Find(b, SpecialPointType::kGrazing);
  ASSERT_NE(graze, nullptr);
  CurveOptions o = Box(0.03, 0.079, 0.2, 0.35, alpha);
  const Curve c = FollowSpecialPoint(robot, *graze, o);
  ASSERT_EQ(c.status, ContinuationStatus::kOk) << c.message;
  ASSERT_GE(c.points.size(), 5u);
  for (std::size_t i : Sample(c, 5)) {
    const CurvePoint& p = c.points[i];
    EXPECT_EQ(p.motion.impacts_right, 1);  // the side without the new impact
    const double phi = ImpactPhase(robot(p.parameter, p.parameter2), p.motion);
    const Solution s = Solve(Forcing::Harmonic(p.parameter, kC, phi), OrbitParams());
    ASSERT_TRUE(s.orbit.ok());
    EXPECT_TRUE(Near(s.orbit.alpha, p.parameter2, kAnalyticTol)) << p.parameter;
    EXPECT_TRUE(Near(s.validity.x_max, 1.0, kAnalyticTol)) << p.parameter;
  }
}

TEST(SpecialCurve, SpeedExtremumCurveIsTheFastestOrbitAtEachAmplitude) {
  const Curve c = AlphaACurve(SpecialPointType::kSpeedExtremum);
  ASSERT_EQ(c.status, ContinuationStatus::kOk) << c.message;
  ASSERT_GE(c.points.size(), 5u);
  for (std::size_t i : Sample(c, 3)) {
    const CurvePoint& p = c.points[i];
    // Dense reference: the analytic family's speed over the impact phases around the point's.
    const double phi = ImpactPhase(AlphaA(p.parameter, p.parameter2), p.motion);
    double best = 0.0;
    for (int k = 0; k <= 4000; ++k) {
      const Orbit o = OrbitAt(p.parameter2, phi - 0.1 + 0.2 * k / 4000.0);
      if (o.ok()) best = std::max(best, o.v_mean);
    }
    EXPECT_TRUE(NearAbsBelowOne(p.motion.mean_velocity, best, 1e-9)) << p.parameter2;
  }
}

TEST(SpecialCurveInput, BadOptionsAreNamed) {
  EXPECT_EQ(testing::InvalidArgumentMessage([] { ParseFollowType("hopf"); }),
            "follow = hopf is invalid: expected one of fold, period_doubling, grazing, "
            "speed_extremum");
  EXPECT_EQ(ParseFollowType("grazing"), SpecialPointType::kGrazing);
  const auto message = [](const CurveOptions& o) {
    return testing::InvalidArgumentMessage([&] { o.Validate(); });
  };
  CurveOptions o = Box(0.2, 0.3, 0.04, 0.06, kA);
  o.from2 = std::nan("");
  EXPECT_EQ(message(o), "from2 = nan is invalid: expected a finite number");
  o = Box(0.2, 0.3, 0.06, 0.04, kA);
  EXPECT_EQ(message(o), "to2 = 0.04 is invalid: expected a finite number > from2 = 0.06");
  o = Box(0.2, 0.3, 0.04, 0.045, kA);
  EXPECT_EQ(message(o), "start2 = 0.05 is invalid: expected from2 = 0.04 <= start2 <= to2 = 0.045");
  SpecialPoint change;
  change.type = SpecialPointType::kSegmentChange;
  change.located = true;
  EXPECT_EQ(testing::InvalidArgumentMessage(
                [&] { FollowSpecialPoint(AlphaA, change, Box(0.2, 0.3, 0.04, 0.06, kA)); }),
            "special point type = segment_change (located = true) is invalid: expected a located "
            "fold, period_doubling, grazing or speed_extremum");
  const Forcing f = Forcing::Harmonic(kA, kC, kPhi0);
  EXPECT_EQ(testing::InvalidArgumentMessage([&] {
              NamedParameterSurface({f, OrbitParams(), 0.3}, "A", "A");
            }),
            "param2 = A is invalid: expected a parameter other than param = A");
  EXPECT_EQ(testing::InvalidArgumentMessage([&] {
              NamedParameterSurface({f, OrbitParams(), 0.3}, "b1", "A");
            }),
            "param2 = A is invalid: expected a parameter other than param = b1");
}

}  // namespace
}  // namespace capsubot
