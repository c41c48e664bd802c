// The continuation at its edges (docs/continuation.md, Limits): steps near the ends of the
// doubles, states out of the robot's scale, a branch of constant speed, branches that end at a
// wall. References: the analytic one-impact orbit (one_impact_family.hpp), Newton shooting
// (periodic.hpp) and a bisection on the motion's existence written here.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

#include "capsubot/attract/periodic.hpp"
#include "capsubot/continue/continuation.hpp"
#include "capsubot/continue/parameter_branch.hpp"
#include "continue/one_impact_family.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::AfterImpact;
using testing::kA;
using testing::kPhi0;
using testing::OrbitAt;
using testing::Range;
using testing::Robot;
using testing::RobustGait;

// The bisection below stops at this width; Newton shooting converges to 1e-12 in the state,
// which moves the existence boundary by far less.
constexpr double kBisectionWidth = 1e-13;
// Grazings must be located to 1e-8 (the default location tolerance is 1e-10).
constexpr double kGrazingBar = 1e-8;
// A motion this far inside its grazing, and how much its spectral radius may differ from the
// grazing's (relative to max(1, rho)): the multipliers move by their slope times kInside, a
// few hundred times 1e-4 next to a fold (the robust gait's grazing in alpha lies 4e-4 from
// its fold: 0.807 against 0.832), while differences that straddle the wall are off by orders
// of magnitude (-419 where 0.81 is right).
constexpr double kInside = 1e-4;
constexpr double kMultiplierContinuity = 0.1;

// The family of an orbit's robot in `name` and the branch of its one-impact orbit over
// [from, to] with `steps` (initial, min, max).
struct Family {
  Orbit orbit;
  Params params;
  std::string name;
  RobotFamily Of() const {
    return NamedParameterFamily({orbit.forcing, params, orbit.alpha}, name);
  }
};

Branch Follow(const Family& f, double start, double from, double to, std::vector<double> steps) {
  ContinuationOptions opt = Range(from, to, start);
  opt.initial_step = steps[0];
  opt.min_step = steps[1];
  opt.max_step = steps[2];
  return ContinueBranch(f.Of(), OrbitImpactState(f.orbit, f.orbit.forcing), opt);
}

// The end of a's one-impact motion by bisection between `inside` (where it exists) and
// `beyond`: Newton shooting with period 1 from the last motion found, kept when it converges
// with a's impacts. Independent of the continuation's corrector and of the wall distance.
double ExistenceEnd(const Family& f, const PeriodicMotion& a, double inside, double beyond) {
  PhaseState state = a.state;
  for (int k = 0; k < 200 && std::abs(beyond - inside) > kBisectionWidth; ++k) {
    const double mid = 0.5 * (inside + beyond);
    const RobotModel r = f.Of()(mid);
    const PeriodicMotion m = ShootPeriodicMotion(r, state, 1, ShootingOptions{});
    if (m.status == ShootingStatus::kConverged && m.impacts_right == a.impacts_right &&
        m.impacts_left == a.impacts_left) {
      inside = mid;
      state = m.state;
    } else {
      beyond = mid;
    }
  }
  return inside;
}

// Every point of the branch has the impacts of its start: no step lands on another motion.
void ExpectOneMotion(const Branch& b) {
  ASSERT_FALSE(b.points.empty());
  const PeriodicMotion& start = b.points[static_cast<std::size_t>(b.start_index)].motion;
  for (const BranchPoint& p : b.points) {
    ASSERT_EQ(p.motion.impacts_right, start.impacts_right) << p.parameter;
    ASSERT_EQ(p.motion.impacts_left, start.impacts_left) << p.parameter;
  }
}

// The multipliers of the end grazing's motion are those of its own side: the map is smooth
// there up to the grazing, so they differ from those of the motion kInside within (shot anew,
// its differences far from the wall) by about the slope of the multipliers times kInside.
void ExpectMultipliersOfItsSide(const Family& f, const Branch& b, bool forward) {
  const SpecialPoint& g = forward ? b.special_points.back() : b.special_points.front();
  const double outwards = forward ? b.points.back().tangent : -b.points.front().tangent;
  const RobotModel r = f.Of()(g.parameter - (outwards > 0.0 ? kInside : -kInside));
  const PeriodicMotion in = ShootPeriodicMotion(r, g.motion.state, 1, ShootingOptions{});
  ASSERT_EQ(in.status, ShootingStatus::kConverged);
  EXPECT_NEAR(g.motion.spectral_radius, in.spectral_radius,
              kMultiplierContinuity * std::max(1.0, in.spectral_radius))
      << "at the grazing " << g.parameter;
}

// The direction's end is a grazing at `wall`, located within its accuracy of the independent
// end of the motion, both within kGrazingBar.
void ExpectGrazingEnd(const Family& f, const Branch& b, bool forward, Wall wall) {
  SCOPED_TRACE(forward ? "upper end" : "lower end");
  ASSERT_EQ(forward ? b.forward_end : b.backward_end, BranchEnd::kGrazing);
  ASSERT_FALSE(b.special_points.empty());
  const SpecialPoint& g = forward ? b.special_points.back() : b.special_points.front();
  ASSERT_EQ(g.type, SpecialPointType::kGrazing);
  EXPECT_EQ(g.wall, wall);
  EXPECT_TRUE(g.located);
  EXPECT_LE(g.accuracy, kGrazingBar);
  const double outwards = forward ? b.points.back().tangent : -b.points.front().tangent;
  const double beyond = g.parameter + (outwards > 0.0 ? 1e-5 : -1e-5);
  const double inside = g.parameter - (outwards > 0.0 ? 1e-5 : -1e-5);
  const double end = ExistenceEnd(f, g.motion, inside, beyond);
  EXPECT_LE(std::abs(g.parameter - end), g.accuracy + kBisectionWidth)
      << "reported " << g.parameter << " +- " << g.accuracy << ", bisection " << end;
}

// The example's branch in alpha over [0.2, 0.3] with the given steps (docs/continuation.md).
Branch AlphaBranchWithSteps(double min_step, double max_step) {
  const Orbit o = OrbitAt(kA, kPhi0);
  ContinuationOptions opt = Range(0.2, 0.3, o.alpha);
  opt.min_step = min_step;
  opt.max_step = max_step;
  return ContinueBranch([](double alpha) { return Robot(alpha); }, AfterImpact(o, kPhi0), opt);
}

TEST(ContinuationEdges, StepsNearTheEndsOfTheDoublesStillFollowTheBranch) {
  // The ratio max_step / min_step overflows a double for both: the walk's bound on its attempts
  // must not (a one-point branch "the most points were reached" was the symptom).
  for (const auto& [lo, hi] : {std::pair{1e-7, 1e302}, std::pair{1e-310, 0.05}}) {
    const Branch b = AlphaBranchWithSteps(lo, hi);
    ASSERT_EQ(b.status, ContinuationStatus::kOk) << lo << " " << hi;
    EXPECT_GE(b.points.size(), 10u) << lo << " " << hi;
    EXPECT_NE(b.backward_end, BranchEnd::kMaxPoints) << lo << " " << hi;
    EXPECT_NE(b.forward_end, BranchEnd::kMaxPoints) << lo << " " << hi;
  }
}

TEST(ContinuationEdges, StatesOutOfTheRobotsScaleAreNoPeriodicMotion) {
  // At v = 1e16 the friction's change of one period (about 1) is below the state's rounding
  // (2): the map returns the state exactly, which is no periodic motion.
  const RobotModel r = Robot(OrbitAt(kA, kPhi0).alpha);
  ShootingOptions so;
  const PeriodicMotion m = FindPeriodicMotion(r, {0.5, 0.0, 1e16, 1.0}, so);
  EXPECT_NE(m.status, ShootingStatus::kConverged) << m.mean_velocity;
  // The continuation from the largest doubles: no motion, not a branch at infinity.
  const Branch b = ContinueBranch([](double alpha) { return Robot(alpha); },
                                  {0.5, 0.0, 1.7e308, 1.0}, Range(0.2, 0.3, r.alpha));
  EXPECT_EQ(b.status, ContinuationStatus::kNoMotion);
  EXPECT_TRUE(b.points.empty());
}

TEST(ContinuationEdges, BranchOfConstantSpeedHasNoSpeedExtremum) {
  // In phi0 the robot's motion is the same motion shifted in time: its mean velocity is the
  // same at every phi0 (docs/model.md section 6), so d V/ds is rounding of random sign.
  const Orbit o = OrbitAt(kA, kPhi0);
  ContinuationOptions opt = Range(-20.0, 20.0, kPhi0);
  opt.max_points = 400;
  const Branch b = ContinueParameter(
      {Forcing::Harmonic(kA, testing::kC, kPhi0), testing::OrbitParams(), o.alpha}, "phi0",
      AfterImpact(o, kPhi0), opt);
  ASSERT_EQ(b.status, ContinuationStatus::kOk);
  ASSERT_GE(b.points.size(), 100u);
  for (const BranchPoint& p : b.points) {
    ASSERT_TRUE(testing::RelNear(p.motion.mean_velocity, o.v_mean, 1e-9)) << p.parameter;
  }
  for (const SpecialPoint& sp : b.special_points) {
    EXPECT_NE(sp.type, SpecialPointType::kSpeedExtremum) << sp.parameter;
  }
}

TEST(ContinuationEdges, BranchEndingAtAWallEndsAtItsGrazingWhateverTheSteps) {
  // The one-impact family of A = 0.2, c = 0.03 in alpha: its free flight touches the left wall
  // at the lower end and the right wall at the upper end (`continue ... --from-orbit`).
  const Family f{ComputeOrbit(Forcing::Harmonic(0.2, 0.03, -2.57993980854766), Params{1.0, 1.0}),
                 Params{1.0, 1.0}, "alpha"};
  ASSERT_TRUE(f.orbit.ok());
  const std::vector<std::vector<double>> steps = {
      {0.01, 1e-7, 0.05}, {0.001, 1e-7, 0.05}, {0.01, 1e-9, 0.01}, {0.01, 1e-7, 0.2}};
  for (const std::vector<double>& s : steps) {
    SCOPED_TRACE(::testing::Message() << s[0] << " " << s[1] << " " << s[2]);
    const Branch b = Follow(f, f.orbit.alpha, 0.3, 0.75, s);
    ASSERT_EQ(b.status, ContinuationStatus::kOk);
    ExpectOneMotion(b);
    ExpectGrazingEnd(f, b, false, Wall::kLeft);
    ExpectGrazingEnd(f, b, true, Wall::kRight);
    ExpectMultipliersOfItsSide(f, b, false);
    ExpectMultipliersOfItsSide(f, b, true);
  }
}

TEST(ContinuationEdges, RobustGaitEndsInT0AndAlphaAtItsLeftWallGrazing) {
  // The robust gait over the ranges of its robustness (gait_robustness.hpp): in T0 and in
  // alpha the lower end is where its flight touches the left wall (in alpha at 0.6319567436,
  // not at the 0.6319608 a bisection on the corrector's trials once reported).
  const Orbit o = RobustGait();
  const Family t0{o, Params{o.T0, o.e}, "T0"};
  const Branch bt = Follow(t0, o.T0, 0.5 * o.T0, 2.0 * o.T0, {0.01, 1e-7, 0.05});
  ASSERT_EQ(bt.status, ContinuationStatus::kOk);
  ExpectOneMotion(bt);
  ExpectGrazingEnd(t0, bt, false, Wall::kLeft);
  ExpectMultipliersOfItsSide(t0, bt, false);  // 0.81 stable, not the -419 of straddling ones
  const Family alpha{o, Params{o.T0, o.e}, "alpha"};
  const Branch ba =
      Follow(alpha, o.alpha, 0.5 * o.alpha, 0.5 * (1.0 + o.alpha), {0.01, 1e-7, 0.05});
  ASSERT_EQ(ba.status, ContinuationStatus::kOk);
  ExpectOneMotion(ba);  // it once went on past the grazing onto a 1 right + 1 left motion
  ExpectGrazingEnd(alpha, ba, false, Wall::kLeft);
  ExpectMultipliersOfItsSide(alpha, ba, false);
}

}  // namespace
}  // namespace capsubot
