// Stability of the one-impact orbit (docs/model.md section 8): the analytic Jacobian of the impact
// map against finite differences through the independent simulator, and the verdict against
// what a simulation from a perturbed state does.

#include "capsubot/orbit/stability.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <string>
#include <utility>

#include "capsubot/orbit/validity.hpp"
#include "capsubot/simulate/simulator.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::StartAt;

using testing::Near;

// Central differences with step h have truncation error ~h^2 |J'''| and rounding error
// ~1e-16/h: with h = 1e-6 both are far below 1e-6 (observed agreement ~1e-9).
constexpr double kFdStep = 1e-6;
constexpr double kFdTol = 1e-6;

// The impact map of docs/model.md section 8 through the simulator: from just before a right-wall
// impact at motor phase theta with relative velocity u (capsule at rest), run to the next
// right-wall impact; returns theta' - theta (the phase advance) and u' (its impact velocity),
// and the stop phase phi1 of the way.
struct MapResult {
  double advance = NAN, u = NAN, phi1 = NAN;
  std::int64_t other_events = 0;  // events besides one stop (0 on a one-impact orbit)
};

MapResult SimulatedMap(const Forcing& motor, const Params& p, double alpha, double theta,
                       double u) {
  struct Log : SimObserver {
    MapResult m;
    int right = 0;
    void OnEvent(const SimEvent& e) override {
      if (e.kind == EventKind::kImpactRight) {
        if (++right == 2) {
          m.advance = e.after.phi;
          m.u = e.u_before;
        }
      } else if (e.kind == EventKind::kStop && std::isnan(m.phi1)) {
        m.phi1 = e.after.phi;
      } else {
        ++m.other_events;
      }
    }
  } log;
  SimOptions opt = StartAt(alpha, 1.0, u, 0.0, 3.0);
  opt.max_impacts_right = 2;  // the impact at phi = 0 and the next one
  Simulate(motor.WithPhase(theta), p, opt, &log);
  return log.m;
}

Eigen::Matrix2d FiniteDifferenceJacobian(const Forcing& motor, const Params& p, double alpha,
                                         double theta, double u) {
  Eigen::Matrix2d J;
  for (int k = 0; k < 2; ++k) {
    const double dt = k == 0 ? kFdStep : 0.0, du = k == 1 ? kFdStep * u : 0.0;
    const MapResult plus = SimulatedMap(motor, p, alpha, theta + dt, u + du);
    const MapResult minus = SimulatedMap(motor, p, alpha, theta - dt, u - du);
    const double d = 2.0 * (k == 0 ? dt : du);
    // theta' = theta + advance
    J(0, k) = ((theta + dt + plus.advance) - (theta - dt + minus.advance)) / d;
    J(1, k) = (plus.u - minus.u) / d;
  }
  return J;
}

struct Case {
  std::string name;
  bool fourier;
  double A, c, T0, e, phi0;
  bool stable;  // expected verdict (spectral radius from the scan, see the comment below)
};

Forcing Force(const Case& k) {
  return k.fourier ? Forcing::Fourier(k.c, {0.0, 0.1 * k.A}, {k.A, 0.0}, k.phi0)
                   : Forcing::Harmonic(k.A, k.c, k.phi0);
}

Params P(const Case& k) { return Params{k.T0, k.e}; }

class OrbitStability : public ::testing::TestWithParam<Case> {};

TEST_P(OrbitStability, AnalyticJacobianMatchesFiniteDifferencesThroughTheSimulator) {
  const Case& k = GetParam();
  const Solution s = Solve(Force(k), P(k));
  ASSERT_TRUE(s.validity.valid());
  const Stability st = ComputeStability(s.orbit);
  ASSERT_TRUE(st.computed);
  const Eigen::Matrix2d fd =
      FiniteDifferenceJacobian(s.orbit.forcing, P(k), s.orbit.alpha, k.phi0, s.orbit.u);
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      EXPECT_TRUE(Near(st.jacobian(i, j), fd(i, j), kFdTol * std::max(1.0, std::abs(fd(i, j)))))
          << "entry (" << i << ", " << j << ")";
    }
  }
}

// Away from the fixed point (a pre-impact state that is not periodic) the general formula
// still holds, given phi1 and phi2 of that state (taken from the simulation).
TEST_P(OrbitStability, ImpactMapJacobianHoldsAwayFromTheFixedPoint) {
  const Case& k = GetParam();
  const Orbit o = ComputeOrbit(Force(k), P(k));
  ASSERT_TRUE(o.ok());
  const double theta = k.phi0 + 1e-3, u = o.u * (1.0 + 1e-3);
  const MapResult m = SimulatedMap(o.forcing, P(k), o.alpha, theta, u);
  ASSERT_EQ(m.other_events, 0) << "the perturbed state keeps the one-impact structure";
  const Eigen::Matrix2d J =
      ImpactMapJacobian(o.forcing.WithPhase(theta), k.T0, k.e, o.alpha, u, m.phi1, m.advance);
  const Eigen::Matrix2d fd = FiniteDifferenceJacobian(o.forcing, P(k), o.alpha, theta, u);
  for (int i = 0; i < 2; ++i) {
    for (int j = 0; j < 2; ++j) {
      EXPECT_TRUE(Near(J(i, j), fd(i, j), kFdTol * std::max(1.0, std::abs(fd(i, j)))))
          << "entry (" << i << ", " << j << ")";
    }
  }
}

// Simulate from the post-impact state with u and v perturbed by 1e-6 (relative) and follow the
// right-wall impacts: a stable orbit returns (deviation shrinks below 1e-9), an unstable one
// departs (deviation above 1e-3, or the one-impact structure breaks).
TEST_P(OrbitStability, PerturbedOrbitReturnsIfStableAndDepartsIfUnstable) {
  const Case& k = GetParam();
  const Solution s = Solve(Force(k), P(k));
  ASSERT_TRUE(s.validity.valid());
  const Orbit& o = s.orbit;
  const Stability st = ComputeStability(o);
  ASSERT_EQ(st.stable, k.stable) << "spectral radius " << st.spectral_radius;
  struct Log : SimObserver {
    double u = 0.0, last_deviation = 0.0, max_deviation = 0.0;
    std::int64_t impacts = 0, others = 0;
    void OnEvent(const SimEvent& e) override {
      if (e.kind == EventKind::kImpactRight) {
        ++impacts;
        const double dev = std::abs(e.after.phi - kTau * static_cast<double>(impacts)) +
                           std::abs(e.u_before - u) / u;
        last_deviation = dev;
        max_deviation = std::max(max_deviation, dev);
      } else if (e.kind != EventKind::kStop) {
        ++others;
      }
    }
  } log;
  log.u = o.u;
  SimOptions opt;
  opt.alpha = o.alpha;
  opt.x0 = 1.0;
  opt.u0 = -o.e * o.u * (1.0 + 1e-6);  // (no perturbation when e = 0: u0 = 0)
  opt.v0 = o.v_plus * (1.0 + 1e-6);
  opt.periods = 80.0;
  const SimResult r = Simulate(o.forcing, P(k), opt, &log);
  if (k.stable) {
    EXPECT_EQ(r.impacts_right, 80);
    EXPECT_EQ(log.others, 0);
    EXPECT_LT(log.last_deviation, 1e-9);
  } else {
    const bool departed = log.max_deviation > 1e-3 || log.others > 0 || r.impacts_right != 80;
    EXPECT_TRUE(departed) << "max deviation " << log.max_deviation;
  }
}

// Orbits picked from scans of `capsubot solve --stability` over phi0 (256 phases), all valid;
// spectral radius in brackets: e < 1 and e = 1, small and large T0, e = 0, a Fourier force.
INSTANTIATE_TEST_SUITE_P(
    Stability, OrbitStability,
    ::testing::Values(
        Case{"e0p5_stable_rho0p16", false, 0.05, 0.02, 0.1, 0.5, -2.842, true},
        Case{"e0p5_unstable_rho4p8", false, 0.05, 0.02, 0.1, 0.5, 2.208, false},
        Case{"e0p5_unstable_rho1p29", false, 0.05, 0.02, 0.1, 0.5, -2.442, false},
        Case{"e1_stable_rho0p27", false, 0.05, 0.02, 0.1, 1.0, -2.74, true},
        Case{"e1_unstable_rho5p1", false, 0.05, 0.02, 0.1, 1.0, 2.16, false},
        Case{"e0_stable_rho0p45_T0_0p004", false, 0.002, 0.0005, 0.004, 0.0, -2.6998, true},
        Case{"e0_unstable_rho1p8_T0_0p01", false, 0.005, 0.001, 0.01, 0.0, -2.4053, false},
        Case{"large_T0_0p3_e0p8_stable_rho0p49", false, 0.12, 0.05, 0.3, 0.8, -2.9207, true},
        Case{"large_T0_0p3_e0p8_unstable_rho4p3", false, 0.12, 0.05, 0.3, 0.8, 2.2826, false},
        Case{"fourier_stable_rho0p11", true, 0.05, 0.02, 0.1, 0.5, -2.7243, true},
        Case{"fourier_unstable_rho4p9", true, 0.05, 0.02, 0.1, 0.5, 2.2089, false}),
    [](const ::testing::TestParamInfo<Case>& info) { return info.param.name; });

TEST(Stability, NotComputedWithoutOrbit) {
  Params p;
  const Orbit none = ComputeOrbit(Forcing::Harmonic(0.5, 0.0, 0.0), p);  // Pi(tau) = 0
  ASSERT_FALSE(none.ok());
  const Stability st = ComputeStability(none);
  EXPECT_FALSE(st.computed);
  EXPECT_FALSE(st.stable);
  EXPECT_TRUE(std::isnan(st.spectral_radius));
  EXPECT_TRUE(std::isnan(st.jacobian(0, 0)));
  EXPECT_TRUE(std::isnan(st.multipliers[0].real()));
  EXPECT_FALSE(ComputeStability(Orbit{}).computed);
}

TEST(Stability, MultipliersAreTheEigenvaluesSortedByModulus) {
  Params p;
  p.T0 = 0.1;
  p.e = 0.5;
  for (const double phi0 : {-2.842, 2.208, -3.1, 2.9}) {
    const Stability st = ComputeStability(ComputeOrbit(Forcing::Harmonic(0.05, 0.02, phi0), p));
    ASSERT_TRUE(st.computed);
    const Eigen::Matrix2d& J = st.jacobian;
    const auto sum = st.multipliers[0] + st.multipliers[1];
    const auto product = st.multipliers[0] * st.multipliers[1];
    EXPECT_TRUE(Near(sum.real(), J.trace(), 1e-12));
    EXPECT_TRUE(Near(sum.imag(), 0.0, 1e-12));
    EXPECT_TRUE(Near(product.real(), J(0, 0) * J(1, 1) - J(0, 1) * J(1, 0), 1e-12));
    EXPECT_GE(std::abs(st.multipliers[0]), std::abs(st.multipliers[1]));
    EXPECT_DOUBLE_EQ(st.spectral_radius, std::abs(st.multipliers[0]));
    EXPECT_EQ(st.stable, st.spectral_radius < 1.0);
  }
}

// How stability is lost, at the crossing itself. For each force a scan of phi0 finds a stable
// orbit next to an unstable one with the expected label; bisection in phi0 then locates where
// the spectral radius reaches 1, and there the multiplier that left the unit circle must be
// +1 (fold), -1 (flip) or a complex pair of modulus 1 (torus). The fold is also checked
// against the orbit family itself: a fold is a turning point of alpha(phi0) (docs/model.md
// section 12), seen here as a sign change of its finite differences.
struct LossCase {
  const char* name;
  double A, c, T0, e;
  StabilityLoss loss;
  friend void PrintTo(const LossCase& c, std::ostream* os) { *os << c.name; }
};

class StabilityLossAtTheCrossing : public ::testing::TestWithParam<LossCase> {};

constexpr int kScanPoints = 2001;
constexpr int kBisections = 60;
// At the bisected crossing the radius is 1 to rounding; the multiplier's position on the
// circle is then known to about the conditioning of the 2x2 eigenproblem.
constexpr double kCrossingTol = 1e-6;
constexpr double kFoldStep = 1e-4;  // finite-difference step of alpha(phi0) at the fold

TEST_P(StabilityLossAtTheCrossing, LabelsTheMultiplierThatLeavesTheUnitCircle) {
  const LossCase& lc = GetParam();
  Params p;
  p.T0 = lc.T0;
  p.e = lc.e;
  const auto stability = [&](double phi0) {
    return ComputeStability(ComputeOrbit(Forcing::Harmonic(lc.A, lc.c, phi0), p));
  };
  int labelled = 0, crossings = 0;
  for (int i = 1; i < kScanPoints; ++i) {
    double a = -M_PI + kTau * (i - 1) / (kScanPoints - 1), b = -M_PI + kTau * i / (kScanPoints - 1);
    const Stability sa = stability(a), sb = stability(b);
    if (sb.computed) labelled += ClassifyLoss(sb) == lc.loss;
    if (!sa.computed || !sb.computed || sa.stable == sb.stable) continue;
    if (ClassifyLoss(sa.stable ? sb : sa) != lc.loss) continue;
    if (!sa.stable) std::swap(a, b);  // a stable, b unstable
    for (int k = 0; k < kBisections; ++k) {
      const double mid = 0.5 * (a + b);
      (stability(mid).stable ? a : b) = mid;
    }
    const Stability at = stability(b);
    ASSERT_TRUE(at.computed);
    EXPECT_EQ(ClassifyLoss(at), lc.loss) << "phi0 = " << b;
    EXPECT_TRUE(Near(at.spectral_radius, 1.0, kCrossingTol)) << "phi0 = " << b;
    const std::complex<double> m = at.multipliers[0];
    switch (lc.loss) {
      case StabilityLoss::kFold: {
        EXPECT_TRUE(Near(m.real(), 1.0, kCrossingTol)) << "phi0 = " << b;
        const auto alpha = [&](double phi0) {
          return ComputeOrbit(Forcing::Harmonic(lc.A, lc.c, phi0), p).alpha;
        };
        const double left = alpha(b) - alpha(b - kFoldStep),
                     right = alpha(b + kFoldStep) - alpha(b);
        EXPECT_LT(left * right, 0.0) << "alpha(phi0) has no turning point at phi0 = " << b;
        break;
      }
      case StabilityLoss::kFlip:
        EXPECT_TRUE(Near(m.real(), -1.0, kCrossingTol)) << "phi0 = " << b;
        break;
      case StabilityLoss::kTorus:
        EXPECT_GT(std::abs(m.imag()), 0.01) << "phi0 = " << b;
        break;
      case StabilityLoss::kNone:
        break;
    }
    ++crossings;
  }
  EXPECT_GT(labelled, 0);
  EXPECT_GE(crossings, 1) << "the scan found no crossing of this kind";
}

// The forces come from a scan of (e, A, c, phi0) with `capsubot sweep --stability`: the
// paper's example loses stability only by folds, A = 0.2, c = 0.03 also by flips, and a
// strong force with e = 0.5 through a complex pair.
INSTANTIATE_TEST_SUITE_P(
    Kinds, StabilityLossAtTheCrossing,
    ::testing::Values(LossCase{"fold", 0.5, 0.5, 1.0, 1.0, StabilityLoss::kFold},
                      LossCase{"flip", 0.2, 0.03, 1.0, 1.0, StabilityLoss::kFlip},
                      LossCase{"torus", 0.95, 0.36 / 7.0, 1.0, 0.5, StabilityLoss::kTorus}),
    [](const ::testing::TestParamInfo<LossCase>& info) { return info.param.name; });

TEST(StabilityLoss, NoneWhenStableOrNotComputedAndNamesForCsv) {
  EXPECT_EQ(ClassifyLoss(Stability{}), StabilityLoss::kNone);
  Params p;
  p.T0 = 0.1;
  p.e = 0.5;
  const Stability stable =
      ComputeStability(ComputeOrbit(Forcing::Harmonic(0.05, 0.02, -2.7243), p));
  ASSERT_TRUE(stable.stable);
  EXPECT_EQ(ClassifyLoss(stable), StabilityLoss::kNone);
  EXPECT_STREQ(StabilityLossName(StabilityLoss::kNone), "");
  EXPECT_STREQ(StabilityLossName(StabilityLoss::kFold), "fold");
  EXPECT_STREQ(StabilityLossName(StabilityLoss::kFlip), "flip");
  EXPECT_STREQ(StabilityLossName(StabilityLoss::kTorus), "torus");
}

}  // namespace
}  // namespace capsubot
