// The one-impact orbit (docs/model.md section 4): phi1, alpha, periodicity, continuity, the
// equations of motion, quadrature of the displacement, the scaling law, the paper's example.

#include "capsubot/orbit/orbit.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>

#include "capsubot/orbit/validity.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::Near;
using testing::NearAbsBelowOne;
using testing::Quadrature;

constexpr double kClosedFormTol = 1e-11;  // identities of the closed form, O(1..10) values
constexpr double kRootTol = 1e-12;        // phi1 from Brent to 1e-14 in phase

using Case = testing::NamedCase;

// Orbits that exist (status ok), valid or not: harmonic and Fourier, e = 1, 0.5, 0.
const Case kCases[] = {
    {"paper_example", Forcing::Harmonic(0.5, 0.5, -2.944899971002), Params{1.0, 1.0}},
    {"small_T0_e05", Forcing::Harmonic(0.05, 0.02, -2.5), Params{0.1, 0.5}},
    {"plastic_e0", Forcing::Harmonic(0.08, 0.01, -2.4), Params{0.1, 0.0}},
    {"right_wall_case", Forcing::Harmonic(0.2, 0.03, -3.1), Params{1.0, 0.5}},
    {"fourier_k3", Forcing::Fourier(0.02, {0.01, 0.0, 0.005}, {0.04, 0.01, 0.0}, -2.6),
     Params{0.1, 0.7}},
};

class OrbitCases : public ::testing::TestWithParam<Case> {
 protected:
  Orbit Make() const {
    const Orbit o = ComputeOrbit(GetParam().forcing, GetParam().params);
    EXPECT_TRUE(o.ok()) << StatusName(o.status);
    return o;
  }
};

TEST_P(OrbitCases, StopPhaseIsTheFirstRootOfG) {
  const Orbit o = Make();
  const Forcing& f = o.forcing;
  const auto g = [&](double phi) { return o.Pi_tau - o.T0 * phi - f.Pi(phi); };
  EXPECT_TRUE(Near(g(o.phi1), 0.0, kRootTol));
  EXPECT_GT(o.phi1, 0.0);
  EXPECT_LT(o.phi1, kTau);
  for (int i = 1; i < 10000; ++i) {  // dense scan: g stays positive before phi1
    const double phi = o.phi1 * i / 10000.0;
    ASSERT_GT(g(phi), 0.0) << "g has an earlier root near " << phi;
  }
}

// The orbit keeps phi1's cosine and sine and Phi(phi1) from its search (the validity check
// and the extrema use them): the library's numbers up to rounding.
TEST_P(OrbitCases, CarriesTheCosineSineAndPhiOfTheStopPhase) {
  constexpr double kRoundingTol = 1e-15;  // a few ulp of numbers of size 1 (Phi: relative)
  const Orbit o = Make();
  EXPECT_TRUE(Near(o.cos_phi1, std::cos(o.phi1), kRoundingTol));
  EXPECT_TRUE(Near(o.sin_phi1, std::sin(o.phi1), kRoundingTol));
  EXPECT_TRUE(NearAbsBelowOne(o.Phi1, o.forcing.Phi(o.phi1), kRoundingTol));
}

TEST_P(OrbitCases, MassRatioIsTheRootOfPsi) {
  const Orbit o = Make();
  const Forcing& f = o.forcing;
  const double a = o.alpha, e = o.e, tau = kTau;
  // psi(alpha) written out directly from docs/model.md section 4.
  const double psi = e * tau * o.Pi_tau / (1 + e) - (1 - a) * f.Phi(tau) -
                     a * (o.T0 * o.phi1 * o.phi1 / 2 + (tau - o.phi1) * o.Pi_tau + f.Phi(o.phi1));
  EXPECT_TRUE(Near(psi, 0.0, kClosedFormTol));
  EXPECT_GT(a, 0.0);
  EXPECT_LT(a, 1.0);
}

TEST_P(OrbitCases, ReturnsToTheImpactStateAfterOnePeriod) {
  const Orbit o = Make();
  EXPECT_DOUBLE_EQ(o.x(0.0), 1.0);
  EXPECT_TRUE(Near(o.dx(0.0), -o.e * o.u, kClosedFormTol));
  EXPECT_TRUE(NearAbsBelowOne(o.x(kTau), 1.0, kClosedFormTol));
  EXPECT_TRUE(NearAbsBelowOne(o.dx(kTau), o.u, kClosedFormTol));
  // The impact law maps the pre-impact state to the post-impact one.
  EXPECT_TRUE(NearAbsBelowOne(o.v(0.0), o.alpha * (1 + o.e) * o.u, kClosedFormTol));
  EXPECT_TRUE(NearAbsBelowOne(o.v_plus, o.alpha * (1 + o.e) * o.u, kClosedFormTol));
}

TEST_P(OrbitCases, StateIsContinuousWhereTheCapsuleStops) {
  const Orbit o = Make();
  constexpr double h = 1e-9;  // one-sided neighbours; x' is bounded so jumps would show
  EXPECT_TRUE(Near(o.x(o.phi1 - h), o.x(o.phi1 + h), 1e-7));
  EXPECT_TRUE(Near(o.dx(o.phi1 - h), o.dx(o.phi1 + h), 1e-7));
  EXPECT_TRUE(Near(o.v(o.phi1 - h), 0.0, 1e-7));
  EXPECT_DOUBLE_EQ(o.v(o.phi1 + h), 0.0);
  EXPECT_TRUE(NearAbsBelowOne(o.x1, o.x(o.phi1), kClosedFormTol));
}

TEST_P(OrbitCases, SatisfiesTheEquationsOfMotionOfEachMode) {
  // docs/model.md section 3: forward slide (1-a) v' = -T0 - F, a(1-a) u' = F + a T0; rest a u' = F.
  const Orbit o = Make();
  const double a = o.alpha;
  constexpr double h = 1e-4;  // central differences: error ~ h^2 * third derivative
  for (double phi : {0.2 * o.phi1, 0.7 * o.phi1}) {
    const double vdot = (o.v(phi + h) - o.v(phi - h)) / (2 * h);
    const double udot = (o.dx(phi + h) - o.dx(phi - h)) / (2 * h);
    EXPECT_TRUE(NearAbsBelowOne((1 - a) * vdot, -o.T0 - o.forcing.F(phi), 1e-6));
    EXPECT_TRUE(NearAbsBelowOne(a * (1 - a) * udot, o.forcing.F(phi) + a * o.T0, 1e-6));
    EXPECT_TRUE(NearAbsBelowOne((o.x(phi + h) - o.x(phi - h)) / (2 * h), o.dx(phi), 1e-6));
  }
  for (double phi : {o.phi1 + 0.3 * (kTau - o.phi1), o.phi1 + 0.8 * (kTau - o.phi1)}) {
    const double udot = (o.dx(phi + h) - o.dx(phi - h)) / (2 * h);
    EXPECT_TRUE(NearAbsBelowOne(a * udot, o.forcing.F(phi), 1e-6));
    EXPECT_TRUE(NearAbsBelowOne((o.x(phi + h) - o.x(phi - h)) / (2 * h), o.dx(phi), 1e-6));
  }
}

TEST_P(OrbitCases, DisplacementIsTheQuadratureOfTheVelocity) {
  const Orbit o = Make();
  EXPECT_TRUE(
      NearAbsBelowOne(o.I, Quadrature([&](double p) { return o.v(p); }, 0.0, o.phi1), 1e-11));
  EXPECT_TRUE(NearAbsBelowOne(o.v_mean, o.I / kTau, 1e-15));
}

TEST_P(OrbitCases, ScalingForceAndFrictionScalesVelocitiesAndDepth) {
  // docs/model.md section 6: A, c, T0 times k leaves phi1 and alpha, multiplies u, v+, I, 1 - x.
  const Orbit o = Make();
  constexpr double k = 3.7;
  const Forcing& f = o.forcing;
  std::vector<double> a, b;
  for (int i = 1; i <= f.harmonics(); ++i) {
    a.push_back(k * f.a(i));
    b.push_back(k * f.b(i));
  }
  Params p = GetParam().params;
  p.T0 *= k;
  const Orbit s = ComputeOrbit(Forcing::Fourier(k * f.mean(), a, b, f.phi0()), p);
  ASSERT_TRUE(s.ok());
  EXPECT_TRUE(Near(s.phi1, o.phi1, kRootTol));
  EXPECT_TRUE(Near(s.alpha, o.alpha, 1e-10));
  EXPECT_TRUE(NearAbsBelowOne(s.u, k * o.u, 1e-10));
  EXPECT_TRUE(NearAbsBelowOne(s.v_plus, k * o.v_plus, 1e-10));
  EXPECT_TRUE(NearAbsBelowOne(s.I, k * o.I, 1e-10));
  for (double phi : {0.5, 2.0, 4.0}) {
    EXPECT_TRUE(NearAbsBelowOne(1 - s.x(phi), k * (1 - o.x(phi)), 1e-9));
  }
}

INSTANTIATE_TEST_SUITE_P(Orbits, OrbitCases, ::testing::ValuesIn(kCases),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(Orbit, PaperWorkedExampleGivesPhi1AndPhi0OfThePaper) {
  // Paper section 4: c = A = T0/2 and phi0 + phi1/2 = -pi/2 turn the stop equation into
  // 3 phi1 = 2 pi + 2 sin(phi1/2): phi1 = 2.748..., phi0 = -2.945... Solve that scalar
  // equation by fixed-point iteration (a contraction: derivative cos(phi1/2)/3), then check
  // that the orbit code's first root of g at this phi0 is the same phi1.
  double phi1 = 2.0;
  for (int i = 0; i < 100; ++i) phi1 = (kTau + 2.0 * std::sin(phi1 / 2.0)) / 3.0;
  const double phi0 = -M_PI / 2.0 - phi1 / 2.0;
  EXPECT_TRUE(Near(phi1, 2.748, 5e-4));
  EXPECT_TRUE(Near(phi0, -2.945, 5e-4));
  const Orbit o = ComputeOrbit(Forcing::Harmonic(0.5, 0.5, phi0), Params{});
  ASSERT_TRUE(o.ok());
  EXPECT_TRUE(Near(o.phi1, phi1, kRootTol));
}

TEST(Orbit, NonPositiveMeanForceHasNoOrbit) {
  for (double c : {0.0, -0.1}) {
    const Orbit o = ComputeOrbit(Forcing::Harmonic(0.3, c, 1.0), Params{});
    EXPECT_EQ(o.status, OrbitStatus::kNonPositiveMeanForce);
    EXPECT_STREQ(StatusName(o.status), "non_positive_mean_force");
    EXPECT_TRUE(std::isnan(o.phi1));
    EXPECT_TRUE(std::isnan(o.alpha));
  }
}

TEST(Orbit, NoMassRatioWhenPsiKeepsItsSign) {
  // For e = 1, psi(0) = -A tau cos(phi0) (docs/model.md section 6); at phi0 = 0, psi(0) < 0, and
  // psi(1) < 0 here (checked by the test itself), so no alpha in (0, 1) closes the orbit.
  const Orbit o = ComputeOrbit(Forcing::Harmonic(0.2, 0.03, 0.0), Params{});
  EXPECT_TRUE(Near(o.psi0, -0.2 * kTau, 1e-12));
  ASSERT_LT(o.psi1, 0.0);
  EXPECT_EQ(o.status, OrbitStatus::kNoMassRatio);
  EXPECT_TRUE(std::isnan(o.alpha));
  EXPECT_FALSE(std::isnan(o.phi1));  // phi1 does not depend on alpha
}

// Beyond double precision the orbit's formulas overflow or round alpha to 0 or 1: the status
// says so, nothing non-finite is reported as an orbit, and the orbit is never valid.
TEST(Orbit, NonFiniteQuantitiesAreAStatusNeverAnOrbit) {
  struct Case {
    const char* what;
    Forcing forcing;
    Params params;
  };
  const Case cases[] = {
      // psi1 is ~1e-19 next to psi0 ~ 1: alpha = psi0/(psi0 - psi1) rounds to 1, 1 - alpha = 0.
      {"tiny mean force", Forcing::Harmonic(0.5, 1e-19, -2.9), Params{}},
      // Pi(tau) = c tau overflows.
      {"huge mean force", Forcing::Harmonic(0.0, 1e308, 0.0), Params{}},
  };
  int checked = 0;
  for (const Case& c : cases) {
    const Solution s = Solve(c.forcing, c.params);
    EXPECT_EQ(s.orbit.status, OrbitStatus::kNonFinite) << c.what;
    EXPECT_STREQ(StatusName(s.orbit.status), "non_finite");
    EXPECT_TRUE(std::isnan(s.orbit.alpha) && std::isnan(s.orbit.u) && std::isnan(s.orbit.I))
        << c.what;
    EXPECT_FALSE(s.validity.valid()) << c.what;
    EXPECT_TRUE(s.validity.violated(Condition::kFinite)) << c.what;
    ++checked;
  }
  EXPECT_EQ(checked, 2);
  // A small but representable case keeps its orbit: alpha = 1 - 6.4e-15 is still below 1.
  const Orbit small = ComputeOrbit(Forcing::Harmonic(0.5, 1e-15, -2.9), Params{});
  ASSERT_TRUE(small.ok());
  EXPECT_LT(small.alpha, 1.0);
  EXPECT_TRUE(std::isfinite(small.u));
  // So does a huge T0, although T0 tau overflows (g(tau) = -inf): the shell stops at once,
  // phi1 = Pi(tau)/(T0 + F(0)) to first order (g is linear there; c tau/T0 in double), and
  // T0 phi1^2/2 = (c tau)^2/(2 T0) is tiny.
  const Orbit stiff = ComputeOrbit(Forcing::Harmonic(0.5, 0.5, -2.9), Params{1e308, 1.0});
  ASSERT_TRUE(stiff.ok());
  EXPECT_TRUE(NearAbsBelowOne(stiff.phi1 * 1e308, 0.5 * kTau, 1e-15));
  EXPECT_TRUE(stiff.alpha > 0.0 && stiff.alpha < 1.0);
  EXPECT_TRUE(std::isfinite(stiff.u) && std::isfinite(stiff.I));
}

TEST(Orbit, StopPhaseIsTheFirstOfSeveralRootsOfG) {
  // A force that dips below -T0 makes g non-monotone: g can return above zero after a first
  // root. F = 1.3 sin(phi - 3.1) + 0.05 with T0 = 1 (found by scanning A, c, phi0 for three
  // sign changes of g on a 10^5-point grid).
  const Forcing f = Forcing::Harmonic(1.3, 0.05, -3.1);
  const Orbit o = ComputeOrbit(f, Params{});
  const auto g = [&](double phi) { return o.Pi_tau - phi - f.Pi(phi); };
  int roots = 0;
  for (int i = 1; i <= 100000; ++i) {
    if ((g(kTau * (i - 1) / 1e5) > 0) != (g(kTau * i / 1e5) > 0)) ++roots;
  }
  ASSERT_GE(roots, 3);
  EXPECT_TRUE(Near(g(o.phi1), 0.0, kRootTol));
  for (int i = 1; i < 10000; ++i) ASSERT_GT(g(o.phi1 * i / 1e4), 0.0);
}

TEST(Params, RejectBadValuesNamingParameterValueAndRule) {
  const struct {
    Params p;
    const char* message;
  } bad[] = {
      {{0.0, 1.0}, "friction bound T0 = 0 is invalid: expected a finite T0 > 0"},
      {{INFINITY, 1.0}, "friction bound T0 = inf is invalid: expected a finite T0 > 0"},
      {{1.0, 1.3}, "restitution e = 1.3 is invalid: expected 0 <= e <= 1"},
      {{1.0, std::nan("")}, "restitution e = nan is invalid: expected 0 <= e <= 1"},
  };
  for (const auto& b : bad) {
    try {
      b.p.Validate();
      ADD_FAILURE() << "no exception for " << b.message;
    } catch (const std::invalid_argument& e) {
      EXPECT_STREQ(e.what(), b.message);
    }
    EXPECT_THROW(ComputeOrbit(Forcing::Harmonic(0.1, 0.1, 0.0), b.p), std::invalid_argument);
  }
}

}  // namespace
}  // namespace capsubot
