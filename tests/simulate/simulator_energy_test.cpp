// The simulator's energy budget (docs/model.md section 11) and its transient/record split.
// References: the energy theorem (motor work = friction + impact losses + change of the kinetic
// energy, for ANY span, derived in docs/simulate.md), the analytic orbit's per-period losses
// T0 I and alpha (1-alpha) (1-e^2) u^2/2 (docs/model.md sections 4 and 11), and GSL quadrature
// of max(F x', 0) along the analytic orbit.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "capsubot/attract/orbit_start.hpp"
#include "capsubot/orbit/stability.hpp"
#include "capsubot/orbit/validity.hpp"
#include "capsubot/simulate/simulator.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::Near;
using testing::Quadrature;
using testing::StartAt;

// The budget is a sum of closed forms evaluated at events located to ~1e-14 in phase: the
// balance holds to rounding (observed ~1e-15 relative). The bar of docs/model.md section 11.
constexpr double kBalanceTol = 1e-10;
// Periodic state returned after the recorded periods (rounding of a converged attractor).
constexpr double kReturnTol = 1e-11;
// Quadrature of a function with kinks (sign changes of F x'), QAGS to 1e-13 requested.
constexpr double kQuadratureTol = 1e-9;

// Kinetic energy of the two bodies in units of (m1+m2) omega^2 L^2: shell v, inner body v + u.
double Kinetic(double alpha, const SimState& s) {
  return 0.5 * ((1.0 - alpha) * s.v * s.v + alpha * (s.v + s.u) * (s.v + s.u));
}

// |W - (friction + impact + dK)| <= kBalanceTol times the largest term.
::testing::AssertionResult Balanced(const Energy& en, double dK) {
  const double rhs = en.friction_loss + en.impact_loss + dK;
  const double scale =
      std::max({std::abs(en.motor_work), en.friction_loss, en.impact_loss, std::abs(dK), 1e-300});
  return Near(en.motor_work, rhs, kBalanceTol * scale);
}

SimOptions WithEnergy(SimOptions opt) {
  opt.energy = true;
  return opt;
}

TEST(SimulatorEnergy, NotComputedUnlessAsked) {
  const SimResult r = Simulate(Forcing::Harmonic(0.05, 0.02, 0.0), Params{0.1, 0.5},
                               StartAt(0.3, 0.5, 0.1, 0.0, 2.0));
  EXPECT_TRUE(std::isnan(r.energy.motor_work));
  EXPECT_TRUE(std::isnan(r.energy.motor_work_positive));
  EXPECT_TRUE(std::isnan(r.energy.friction_loss));
  EXPECT_TRUE(std::isnan(r.energy.impact_loss));
}

// The energy theorem over arbitrary spans: random forces (above and below T0, harmonic and
// Fourier), states and alpha (fixed seed), e = 0, 0.5, 1; runs with impacts on both walls,
// chattering ended by a stick, break-aways and backward slides.
TEST(SimulatorEnergy, MotorWorkEqualsLossesPlusKineticEnergyChangeOnRandomRuns) {
  std::uint64_t seed = 2024;
  const auto uniform = [&seed](double lo, double hi) {  // a small LCG: reproducible anywhere
    seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + (hi - lo) * static_cast<double>(seed >> 11) / 9007199254740992.0;
  };
  int checked = 0, with_sticks = 0, with_left = 0;
  for (int i = 0; i < 150; ++i) {
    const double A = uniform(0.0, 0.2), c = uniform(0.0, 0.05), phi0 = uniform(-M_PI, M_PI);
    const Forcing f = i % 2 == 0 ? Forcing::Harmonic(A, c, phi0)
                                 : Forcing::Fourier(c, {0.0, 0.2 * A}, {A, 0.0}, phi0);
    const Params p{0.1, i % 3 == 0 ? 1.0 : i % 3 == 1 ? 0.5 : 0.0};
    const double alpha = uniform(0.05, 0.95);
    const SimOptions opt =
        WithEnergy(StartAt(alpha, uniform(0.0, 1.0), uniform(-0.3, 0.3), uniform(-0.1, 0.1), 4.0));
    const SimResult r = Simulate(f, p, opt);
    ASSERT_EQ(r.status, SimStatus::kOk) << "run " << i;
    SimState start;
    start.u = opt.u0;
    start.v = opt.v0;
    EXPECT_TRUE(Balanced(r.energy, Kinetic(alpha, r.final_state) - Kinetic(alpha, start)))
        << "run " << i;
    EXPECT_GE(r.energy.motor_work_positive, std::max(r.energy.motor_work, 0.0) - 1e-15);
    EXPECT_GE(r.energy.friction_loss, 0.0);
    EXPECT_GE(r.energy.impact_loss, 0.0);
    if (p.e == 1.0 && r.sticks == 0) {
      EXPECT_EQ(r.energy.impact_loss, 0.0);
    }
    with_sticks += r.sticks > 0;
    with_left += r.impacts_left > 0;
    ++checked;
  }
  EXPECT_EQ(checked, 150);
  EXPECT_GE(with_sticks, 5);  // the plastic cut-off's loss is part of the balance
  EXPECT_GE(with_left, 20);
}

struct OrbitCase {
  std::string name;
  bool fourier;
  double A, c, T0, e;
  int min_orbits;  // valid orbits the 64-phase scan holds (counted with `capsubot solve`)
  int stable;      // how many of them are stable (counted with `capsubot solve --stability`)
};

class OrbitEnergy : public ::testing::TestWithParam<OrbitCase> {
 protected:
  // The valid orbits of a 64-phase scan of phi0.
  std::vector<Orbit> ValidOrbits() const {
    const OrbitCase& k = GetParam();
    std::vector<Orbit> out;
    for (int i = 0; i < 64; ++i) {
      const double phi0 = -M_PI + kTau * i / 64;
      const Forcing f = k.fourier ? Forcing::Fourier(k.c, {0.0, 0.1 * k.A}, {k.A, 0.0}, phi0)
                                  : Forcing::Harmonic(k.A, k.c, phi0);
      const Solution s = Solve(f, P());
      if (s.validity.valid()) out.push_back(s.orbit);
    }
    return out;
  }
  Params P() const { return Params{GetParam().T0, GetParam().e}; }
};

// One period of every valid orbit from its post-impact state: W = friction + impact losses
// (the state returns, dK = 0), and each loss equals the analytic orbit's: T0 I (the capsule
// only slides forward) and one impact alpha (1-alpha) (1-e^2) u^2/2.
TEST_P(OrbitEnergy, OnePeriodOfEveryValidOrbitBalancesAndMatchesTheAnalyticLosses) {
  const std::vector<Orbit> orbits = ValidOrbits();
  ASSERT_GE(static_cast<int>(orbits.size()), GetParam().min_orbits);
  int checked = 0;
  for (const Orbit& o : orbits) {
    SCOPED_TRACE("phi0 = " + std::to_string(o.forcing.phi0()));
    const SimResult r = Simulate(o.forcing, P(), WithEnergy(StartAfterImpact(o, 1.0)));
    ASSERT_EQ(r.impacts_right, 1);
    const Energy& en = r.energy;
    EXPECT_TRUE(Balanced(en, 0.0));
    const double impact = 0.5 * o.alpha * (1.0 - o.alpha) * (1.0 - o.e * o.e) * o.u * o.u;
    EXPECT_TRUE(Near(en.friction_loss, o.T0 * o.I, kBalanceTol * en.motor_work));
    EXPECT_TRUE(Near(en.impact_loss, impact, kBalanceTol * en.motor_work));
    ++checked;
  }
  EXPECT_EQ(checked, static_cast<int>(orbits.size()));
}

// Many periods of the stable ones: the budget of N periods is N times one period's.
TEST_P(OrbitEnergy, TwoHundredPeriodsOfEveryStableOrbitBalance) {
  int checked = 0;
  for (const Orbit& o : ValidOrbits()) {
    if (!ComputeStability(o).stable) continue;
    SCOPED_TRACE("phi0 = " + std::to_string(o.forcing.phi0()));
    const SimResult r = Simulate(o.forcing, P(), WithEnergy(StartAfterImpact(o, 200.0)));
    ASSERT_EQ(r.impacts_right, 200);
    EXPECT_TRUE(Balanced(r.energy, 0.0));
    EXPECT_TRUE(
        Near(r.energy.friction_loss, 200.0 * o.T0 * o.I, kBalanceTol * r.energy.motor_work));
    ++checked;
  }
  EXPECT_EQ(checked, GetParam().stable);
}

// The positive part over one period against GSL quadrature of F x' along the analytic orbit
// (x' from docs/model.md section 4) between its sign changes, which a dense scan brackets and
// bisection locates (QAGS on each one-signed piece).
TEST_P(OrbitEnergy, PositiveMotorWorkEqualsQuadratureAlongTheAnalyticOrbit) {
  int checked = 0;
  for (const Orbit& o : ValidOrbits()) {
    SCOPED_TRACE("phi0 = " + std::to_string(o.forcing.phi0()));
    const auto power = [&o](double phi) { return o.forcing.F(phi) * o.dx(phi); };
    std::vector<double> knots = {0.0, o.phi1};
    constexpr int kScan = 4000;
    for (int i = 1; i < kScan; ++i) {
      const double a = kTau * (i - 1) / kScan, b = kTau * i / kScan;
      if ((power(a) > 0.0) == (power(b) > 0.0)) continue;
      double lo = a, hi = b;
      for (int it = 0; it < 60; ++it) {
        const double mid = 0.5 * (lo + hi);
        ((power(mid) > 0.0) == (power(lo) > 0.0) ? lo : hi) = mid;
      }
      knots.push_back(0.5 * (lo + hi));
    }
    knots.push_back(kTau);
    std::sort(knots.begin(), knots.end());
    double positive = 0.0, net = 0.0;
    for (std::size_t i = 1; i < knots.size(); ++i) {
      const double piece = Quadrature(power, knots[i - 1], knots[i]);
      net += piece;
      positive += std::max(piece, 0.0);
    }
    const SimResult r = Simulate(o.forcing, P(), WithEnergy(StartAfterImpact(o, 1.0)));
    EXPECT_TRUE(Near(r.energy.motor_work, net, kQuadratureTol * std::abs(positive)));
    EXPECT_TRUE(Near(r.energy.motor_work_positive, positive, kQuadratureTol * std::abs(positive)));
    ++checked;
  }
  EXPECT_GE(checked, GetParam().min_orbits);
}

// Parameter sets of tests/simulate/simulator_test.cpp (valid orbits counted there), e < 1
// and e = 1, harmonic and Fourier; 18 stable orbits in all (none at T0 = 0.01, e = 0).
INSTANTIATE_TEST_SUITE_P(
    Simulator, OrbitEnergy,
    ::testing::Values(OrbitCase{"harmonic_T0_0p1_e_0p5", false, 0.05, 0.02, 0.1, 0.5, 10, 6},
                      OrbitCase{"harmonic_T0_0p1_e_1", false, 0.05, 0.02, 0.1, 1.0, 10, 5},
                      OrbitCase{"harmonic_T0_0p01_e_0", false, 0.005, 0.001, 0.01, 0.0, 2, 0},
                      OrbitCase{"harmonic_large_T0_0p3", false, 0.12, 0.05, 0.3, 0.8, 10, 2},
                      OrbitCase{"fourier_T0_0p1_e_0p5", true, 0.05, 0.02, 0.1, 0.5, 10, 5}),
    [](const ::testing::TestParamInfo<OrbitCase>& info) { return info.param.name; });

// Multi-impact periodic motions reached from x0 = 0.5 at rest after a 2000-period transient
// (found by a scan over alpha with `capsubot simulate`; period p and impact counts below are
// what that scan found). The record of k p periods must return to the state at the
// transient's end (so the kinetic energy change is 0) and balance. The two chattering motions
// end their sequences at the accumulation point (docs/model.md section 14), after 13 and 33
// right impacts a period (21 and 51 when they were simulated down to the cut-off 1e-6); at
// e = 1 the capsule rests there and F pushes the body away, so it leaves the wall at once,
// without a stick, and the impacts lose nothing.
struct MotionCase {
  std::string name;
  double A, c, T0, e, alpha;
  int period, impacts_right, impacts_left, sticks;  // per period p
};

class PeriodicMotionEnergy : public ::testing::TestWithParam<MotionCase> {};

TEST_P(PeriodicMotionEnergy, RecordAfterTransientReturnsAndBalances) {
  const MotionCase& k = GetParam();
  const Forcing f = Forcing::Harmonic(k.A, k.c, 0.0);
  const Params p{k.T0, k.e};
  constexpr double kTransient = 2000.0;
  constexpr int kRepeats = 5;
  SimOptions opt = WithEnergy(StartAt(k.alpha, 0.5, 0.0, 0.0, kTransient));
  const SimState s0 = Simulate(f, p, opt).final_state;  // the state where the record starts
  opt.transient = kTransient;
  opt.periods = kRepeats * k.period;
  const SimResult r = Simulate(f, p, opt);
  ASSERT_EQ(r.status, SimStatus::kOk);
  EXPECT_TRUE(Near(r.final_state.x, s0.x, kReturnTol));
  EXPECT_TRUE(Near(r.final_state.u, s0.u, kReturnTol));
  EXPECT_TRUE(Near(r.final_state.v, s0.v, kReturnTol));
  EXPECT_EQ(r.impacts_right, kRepeats * k.impacts_right);
  EXPECT_EQ(r.impacts_left, kRepeats * k.impacts_left);
  EXPECT_EQ(r.sticks, kRepeats * k.sticks);
  const double dK = Kinetic(k.alpha, r.final_state) - Kinetic(k.alpha, s0);
  EXPECT_TRUE(Near(dK, 0.0, kReturnTol));
  EXPECT_TRUE(Balanced(r.energy, 0.0));
  EXPECT_TRUE(Balanced(r.energy, dK));
  if (k.e < 1.0 || k.sticks > 0) {
    EXPECT_GT(r.energy.impact_loss, 0.0);
  } else {
    EXPECT_EQ(r.energy.impact_loss, 0.0);  // elastic, no stick
  }
}

INSTANTIATE_TEST_SUITE_P(
    Simulator, PeriodicMotionEnergy,
    ::testing::Values(MotionCase{"two_wall_backward_e_1", 0.08, 0.015, 0.1, 1.0, 0.3, 2, 2, 2, 0},
                      MotionCase{"period_4_e_0p5", 0.05, 0.02, 0.1, 0.5, 0.1, 4, 6, 2, 0},
                      MotionCase{"period_3_e_0p7", 0.08, 0.015, 0.1, 0.7, 0.2, 3, 4, 2, 0},
                      MotionCase{"chattering_stick_e_0p5", 0.3, 0.1, 0.5, 0.5, 0.5, 1, 13, 1, 1},
                      MotionCase{"chattering_e_1", 0.05, 0.02, 0.1, 1.0, 0.9, 1, 33, 0, 0}),
    [](const ::testing::TestParamInfo<MotionCase>& info) { return info.param.name; });

// The transient is tallied apart: transient + record = the same run without the split.
TEST(SimulatorTransient, TransientAndRecordAddUpToTheWholeRun) {
  const Forcing f = Forcing::Harmonic(0.08, 0.015, 0.0);
  const Params p{0.1, 0.7};
  SimOptions whole = WithEnergy(StartAt(0.2, 0.5, 0.0, 0.0, 30.0));
  SimOptions split = whole;
  split.transient = 12.0;
  split.periods = 18.0;
  const SimResult a = Simulate(f, p, whole), b = Simulate(f, p, split);
  ASSERT_EQ(a.status, SimStatus::kOk);
  ASSERT_EQ(b.status, SimStatus::kOk);
  EXPECT_EQ(b.transient.impacts_right + b.impacts_right, a.impacts_right);
  EXPECT_EQ(b.transient.impacts_left + b.impacts_left, a.impacts_left);
  EXPECT_EQ(b.transient.events + b.events, a.events);
  EXPECT_TRUE(Near(b.transient.span, 12.0 * kTau, 1e-9));
  EXPECT_TRUE(Near(b.span, 18.0 * kTau, 1e-9));
  EXPECT_TRUE(Near(b.transient.displacement + b.displacement, a.displacement, 1e-12));
  EXPECT_TRUE(Near(b.v_mean, b.displacement / b.span, 1e-15));
  EXPECT_TRUE(
      Near(b.transient.energy.motor_work + b.energy.motor_work, a.energy.motor_work, 1e-12));
  EXPECT_TRUE(
      Near(b.transient.energy.impact_loss + b.energy.impact_loss, a.energy.impact_loss, 1e-12));
  EXPECT_TRUE(Near(b.final_state.y, a.final_state.y, 1e-12));
}

// From the analytic orbit: the record's mean velocity and counts are the orbit's, the
// transient's too (it is the same orbit).
TEST(SimulatorTransient, RecordOfAnOrbitAfterATransientIsTheOrbit) {
  const Params p{0.1, 0.5};
  const Orbit o = ComputeOrbit(Forcing::Harmonic(0.05, 0.02, -2.842), p);  // stable
  SimOptions opt = StartAfterImpact(o, 5.0);
  opt.transient = 3.0;
  const SimResult r = Simulate(o.forcing, p, opt);
  EXPECT_EQ(r.transient.impacts_right, 3);
  EXPECT_EQ(r.impacts_right, 5);
  EXPECT_EQ(r.stops, 5);
  EXPECT_TRUE(Near(r.v_mean, o.v_mean, 1e-12));
  EXPECT_TRUE(Near(r.transient.v_mean, o.v_mean, 1e-12));
  EXPECT_TRUE(Near(r.displacement, 5.0 * o.I, 1e-12));
}

// Without a transient the transient's tally is untouched (zero counts, NaN figures).
TEST(SimulatorTransient, NoTransientLeavesItsTallyEmpty) {
  const SimResult r = Simulate(Forcing::Harmonic(0.05, 0.02, 0.0), Params{0.1, 0.5},
                               StartAt(0.3, 0.5, 0.1, 0.0, 2.0));
  EXPECT_EQ(r.transient.events, 0);
  EXPECT_TRUE(std::isnan(r.transient.v_mean));
  EXPECT_TRUE(std::isnan(r.transient.span));
}

// A run stopped inside the transient (here by the right-impact limit) reports its figures as
// the transient's and an empty record.
TEST(SimulatorTransient, RunStoppedInsideTheTransientHasAnEmptyRecord) {
  const Params p{0.1, 0.5};
  const Orbit o = ComputeOrbit(Forcing::Harmonic(0.05, 0.02, -2.842), p);
  SimOptions opt = StartAfterImpact(o, 5.0);
  opt.transient = 10.0;
  opt.max_impacts_right = 3;
  const SimResult r = Simulate(o.forcing, p, opt);
  EXPECT_EQ(r.status, SimStatus::kImpactLimit);
  EXPECT_EQ(r.transient.impacts_right, 3);
  EXPECT_EQ(r.impacts_right, 0);
  EXPECT_TRUE(std::isnan(r.v_mean));
  EXPECT_TRUE(Near(r.transient.v_mean, o.v_mean, 1e-12));
}

TEST(SimulatorTransient, NegativeTransientIsRejectedWithItsRule) {
  SimOptions opt = StartAt(0.3, 0.5, 0.0, 0.0, 1.0);
  opt.transient = -1.0;
  try {
    opt.Validate();
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "transient = -1 is invalid: expected 0 <= transient <= 1e8");
  }
}

TEST(OrbitStart, IsThePostImpactStateAndRejectsAMissingOrbit) {
  const Params p{0.1, 0.5};
  const Orbit o = ComputeOrbit(Forcing::Harmonic(0.05, 0.02, -2.842), p);
  const SimOptions opt = StartAfterImpact(o, 7.0);
  EXPECT_EQ(opt.alpha, o.alpha);
  EXPECT_EQ(opt.x0, 1.0);
  EXPECT_EQ(opt.u0, -0.5 * o.u);
  EXPECT_EQ(opt.v0, o.v_plus);
  EXPECT_EQ(opt.periods, 7.0);
  const Orbit none = ComputeOrbit(Forcing::Harmonic(0.05, 0.0, 0.0), p);
  try {
    StartAfterImpact(none);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "orbit status = non_positive_mean_force is invalid: expected an orbit that "
                 "exists (status ok)");
  }
}

}  // namespace
}  // namespace capsubot
