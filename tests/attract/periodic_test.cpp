// Periodic motions by Newton shooting (docs/model.md section 13). References: the analytic
// one-impact orbit and its impact-map multipliers (orbit.hpp, stability.hpp), independent long
// runs of the simulator, and the decay of perturbations along the simulated motion.

#include "capsubot/attract/periodic.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "capsubot/orbit/stability.hpp"
#include "capsubot/orbit/validity.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::Near;

// Newton's fixed point and the analytic orbit agree to rounding (observed ~1e-15).
constexpr double kStateTol = 1e-10;
// Central differences with step 1e-6: truncation ~1e-12, rounding ~1e-15/1e-6; the multipliers
// agree with the analytic impact map to ~1e-10 (observed); 1e-8 is the required bar.
constexpr double kMultiplierTol = 1e-8;
// Mean velocity of a periodic motion vs a 10,000-period simulation (required 1e-10).
constexpr double kVelocityTol = 1e-10;
constexpr double kLongRunPeriods = 10000.0;

const Forcing kOptimumForce =
    Forcing::Harmonic(0.34063197373861814, 0.06410131873607934, -3.1181183398453047);

SimResult SimulateFrom(const Forcing& forcing, const Params& params, double alpha,
                       const PhaseState& z, double periods) {
  const SimOptions o = testing::StartAt(alpha, z.x, z.u, z.v, periods);
  return Simulate(forcing.WithPhase(forcing.phi0() + z.psi), params, o);
}

double Distance(const SimState& a, const PhaseState& b) {
  return std::max({std::abs(a.x - b.x), std::abs(a.u - b.u), std::abs(a.v - b.v)});
}

TEST(Periodic, FindsOneImpactOrbitOfSolveWithItsMultipliers) {
  Params params;
  params.T0 = 0.1;
  params.e = 0.5;
  const Solution s = Solve(Forcing::Harmonic(0.05, 0.02, -2.842), params);
  ASSERT_TRUE(s.validity.valid());
  const Orbit& o = s.orbit;
  const Stability st = ComputeStability(o);
  ASSERT_TRUE(st.computed);
  // A start near the orbit, right after its impact (1 % off in u and v).
  PhaseState start;
  start.x = 1.0;
  start.u = -o.e * o.u * 1.01;
  start.v = o.v_plus * 0.99;
  start.psi = 0.0;
  const PeriodicMotion m = FindPeriodicMotion({o.forcing, params, o.alpha}, start, {});
  ASSERT_EQ(m.status, ShootingStatus::kConverged);
  EXPECT_LE(m.residual, 1e-12);
  EXPECT_EQ(m.period, 1);
  EXPECT_EQ(m.impacts_right, 1);
  EXPECT_EQ(m.impacts_left, 0);
  EXPECT_TRUE(Near(m.mean_velocity, o.v_mean, kStateTol));
  // The fixed point lies on the analytic orbit (phase since its impact = psi here).
  EXPECT_EQ(m.mode, SimMode::kRest);
  ASSERT_EQ(m.dimension, 2);
  EXPECT_TRUE(Near(m.state.x, o.x(m.state.psi), kStateTol));
  EXPECT_TRUE(Near(m.state.u, o.dx(m.state.psi), kStateTol));
  EXPECT_EQ(m.state.v, 0.0);
  // The stroboscopic map at rest and the impact map are conjugate: same multipliers.
  ASSERT_EQ(m.multipliers.size(), 2U);
  for (int i = 0; i < 2; ++i) {
    EXPECT_TRUE(Near(m.multipliers[i].real(), st.multipliers[i].real(), kMultiplierTol));
    EXPECT_TRUE(Near(std::abs(m.multipliers[i].imag()), std::abs(st.multipliers[i].imag()),
                     kMultiplierTol));
  }
  EXPECT_TRUE(m.stable);
  EXPECT_TRUE(Near(m.spectral_radius, st.spectral_radius, kMultiplierTol));
  EXPECT_TRUE(Near(m.distance_to_unit_circle, 1.0 - st.spectral_radius, kMultiplierTol));
  // A ten times finer difference step gives the same multipliers.
  ShootingOptions fine;
  fine.step = 1e-7;
  const PeriodicMotion f = FindPeriodicMotion({o.forcing, params, o.alpha}, start, fine);
  ASSERT_EQ(f.multipliers.size(), 2U);
  EXPECT_TRUE(Near(std::abs(f.multipliers[0] - m.multipliers[0]), 0.0, 1e-7));
}

TEST(Periodic, ThreeRightOneLeftMotionOfStableOptimumHasTheLongRunVelocity) {
  const Params params;  // T0 = 1, e = 1
  const double alpha = 0.6435592358295166;
  ShootingOptions opt;
  opt.transient = 200;
  const PeriodicMotion m =
      FindPeriodicMotion({kOptimumForce, params, alpha}, RestStart(0.5, 1.0), opt);
  ASSERT_EQ(m.status, ShootingStatus::kConverged);
  EXPECT_LE(m.residual, 1e-12);
  EXPECT_EQ(m.period, 1);
  EXPECT_EQ(m.impacts_right, 3);
  EXPECT_EQ(m.impacts_left, 1);
  EXPECT_TRUE(m.stable);
  const SimResult r = SimulateFrom(kOptimumForce, params, alpha, m.state, kLongRunPeriods);
  ASSERT_EQ(r.status, SimStatus::kOk);
  EXPECT_TRUE(Near(m.mean_velocity, r.displacement / (kLongRunPeriods * kTau), kVelocityTol));
  EXPECT_EQ(r.impacts_right, 3 * static_cast<std::int64_t>(kLongRunPeriods));
  EXPECT_EQ(r.impacts_left, static_cast<std::int64_t>(kLongRunPeriods));
}

TEST(Periodic, PeriodTwoMotionAndItsMultipliers) {
  // T0 = 0.5, alpha = 0.8 with the stable optimum's force: every start from rest ends in 7 right
  // and 1 left impacts per 2 periods (attractors_test).
  Params params;
  params.T0 = 0.5;
  const double alpha = 0.8;
  ShootingOptions opt;
  opt.transient = 200;
  const PeriodicMotion m =
      FindPeriodicMotion({kOptimumForce, params, alpha}, RestStart(0.5, 1.0), opt);
  ASSERT_EQ(m.status, ShootingStatus::kConverged);
  EXPECT_EQ(m.period, 2);
  EXPECT_EQ(m.impacts_right, 7);
  EXPECT_EQ(m.impacts_left, 1);
  ASSERT_EQ(m.dimension, 2);
  // Independently: one period leads elsewhere, two come back.
  EXPECT_GT(Distance(SimulateFrom(kOptimumForce, params, alpha, m.state, 1.0).final_state, m.state),
            1e-3);
  EXPECT_LE(Distance(SimulateFrom(kOptimumForce, params, alpha, m.state, 2.0).final_state, m.state),
            1e-12);
  // The largest multiplier is the decay rate of a perturbation along the simulated motion:
  // the distance to the fixed point shrinks by lambda_max every 2 periods once the other
  // multiplier (about 1e-4) has died out.
  ASSERT_EQ(m.multipliers.size(), 2U);
  EXPECT_TRUE(m.stable);
  PhaseState near = m.state;
  near.x += 1e-5;
  const double d6 =
      Distance(SimulateFrom(kOptimumForce, params, alpha, near, 12.0).final_state, m.state);
  const double d7 =
      Distance(SimulateFrom(kOptimumForce, params, alpha, near, 14.0).final_state, m.state);
  EXPECT_TRUE(Near(m.multipliers[0].imag(), 0.0, 1e-12));
  EXPECT_TRUE(Near(std::abs(m.multipliers[0].real()), d7 / d6, 1e-4));
  EXPECT_LT(std::abs(m.multipliers[1]), 1e-3);
}

TEST(Periodic, FlipOfTheTwoRightOneLeftMotionIsLocatedAlongAlpha) {
  // Continuation in alpha of the 2-right/1-left period-1 motion at T0 = 0.5 (the stable
  // optimum's force): its largest multiplier is negative and passes through -1 between
  // alpha = 0.684 and 0.682 (a scan with ShootPeriodicMotion in steps of 0.001).
  Params params;
  params.T0 = 0.5;
  ShootingOptions opt;
  opt.transient = 300;
  PeriodicMotion m = FindPeriodicMotion({kOptimumForce, params, 0.70}, RestStart(0.5, 1.0), opt);
  ASSERT_EQ(m.status, ShootingStatus::kConverged);
  ASSERT_EQ(m.period, 1);
  ASSERT_EQ(m.impacts_right, 2);
  ASSERT_EQ(m.impacts_left, 1);
  int steps = 0;
  for (double alpha = 0.69; alpha >= 0.684 - 1e-12; alpha -= 0.002, ++steps) {
    m = ShootPeriodicMotion({kOptimumForce, params, alpha}, m.state, 1, {});
    ASSERT_EQ(m.status, ShootingStatus::kConverged) << alpha;
    EXPECT_GT(m.multipliers[0].real(), -1.0) << alpha;
  }
  EXPECT_EQ(steps, 4);
  // Bisection on lambda_max + 1 (real and negative throughout).
  double lo = 0.682, hi = 0.684;
  PhaseState z = m.state;
  const auto top = [&](double alpha) {
    const PeriodicMotion q = ShootPeriodicMotion({kOptimumForce, params, alpha}, z, 1, {});
    EXPECT_EQ(q.status, ShootingStatus::kConverged);
    EXPECT_TRUE(Near(q.multipliers[0].imag(), 0.0, 1e-12));
    z = q.state;
    return q.multipliers[0].real();
  };
  ASSERT_LT(top(lo), -1.0);
  ASSERT_GT(top(hi), -1.0);
  for (int i = 0; i < 30; ++i) {
    const double mid = 0.5 * (lo + hi);
    (top(mid) < -1.0 ? lo : hi) = mid;
  }
  const PeriodicMotion flip = ShootPeriodicMotion({kOptimumForce, params, hi}, z, 1, {});
  EXPECT_TRUE(Near(flip.distance_to_minus_one, 0.0, 1e-6));
  EXPECT_TRUE(Near(hi, 0.6822, 1e-3));  // where the scan saw the crossing
  // Past the flip, the simulator leaves the period-1 motion (slowly: the multiplier is about
  // -1.01) for a period-2 one nearby: twice its impacts per 2 periods.
  PhaseState kicked = flip.state;
  kicked.x += 1e-4;
  MotionOptions slow;
  slow.transient = 3000;
  const Motion after = LongRunMotion({kOptimumForce, params, hi - 0.002}, kicked, slow);
  EXPECT_EQ(after.status, MotionStatus::kPeriodic);
  EXPECT_EQ(after.period, 2);
  EXPECT_EQ(after.impacts_right, 4);
  EXPECT_EQ(after.impacts_left, 2);
}

TEST(PeriodicInput, BadOptionsAreNamed) {
  const Params params;
  const auto message = [&](const ShootingOptions& o) -> std::string {
    try {
      FindPeriodicMotion({kOptimumForce, params, 0.5}, RestStart(0.5, 0.0), o);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "no exception";
  };
  ShootingOptions o;
  o.step = 0.0;
  EXPECT_EQ(message(o), "step = 0 is invalid: expected a finite number > 0");
  o = ShootingOptions{};
  o.max_period = 65;
  EXPECT_EQ(message(o), "max_period = 65 is invalid: expected 1 <= max_period <= 64");
  o = ShootingOptions{};
  o.residual_tolerance = -1.0;
  EXPECT_EQ(message(o), "residual_tolerance = -1 is invalid: expected a finite number > 0");
}

}  // namespace
}  // namespace capsubot
