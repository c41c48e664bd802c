// Forcing: F, Pi, Phi of both families against GSL quadrature; exact crossings and bounds
// against dense scans; input errors.

#include "capsubot/model/forcing.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <stdexcept>
#include <string>

#include "capsubot/orbit/orbit.hpp"
#include "capsubot/orbit/validity.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::Near;
using testing::Quadrature;

constexpr double kQuadratureTol = 1e-11;  // QAGS asked for 1e-13 relative; values are O(1..10)
constexpr double kRootTol = 1e-10;        // |F - level| at a returned crossing
// Two roundings of one closed form (crossing phases and force values of size 1): a few ulp.
constexpr double kRoundingTol = 1e-14;
constexpr int kScan = 200000;  // dense scan used as the independent reference

struct Case {
  const char* name;
  Forcing forcing;
};

class ForcingFamilies : public ::testing::TestWithParam<Case> {};

TEST_P(ForcingFamilies, PiIsTheIntegralOfF) {
  const Forcing& f = GetParam().forcing;
  for (double phi : {0.3, 1.7, 3.9, kTau, 8.0}) {
    EXPECT_TRUE(
        Near(f.Pi(phi), Quadrature([&](double s) { return f.F(s); }, 0.0, phi), kQuadratureTol))
        << "phi = " << phi;
  }
}

TEST_P(ForcingFamilies, PhiIsTheIntegralOfPi) {
  const Forcing& f = GetParam().forcing;
  for (double phi : {0.3, 1.7, 3.9, kTau, 8.0}) {
    EXPECT_TRUE(
        Near(f.Phi(phi), Quadrature([&](double s) { return f.Pi(s); }, 0.0, phi), kQuadratureTol))
        << "phi = " << phi;
  }
}

TEST_P(ForcingFamilies, MeanForceGivesPiOverOnePeriod) {
  const Forcing& f = GetParam().forcing;
  EXPECT_TRUE(Near(f.Pi(kTau), f.mean() * kTau, 1e-13));
}

TEST_P(ForcingFamilies, DerivativeMatchesCentralDifference) {
  const Forcing& f = GetParam().forcing;
  constexpr double h = 1e-5;  // central difference error ~ h^2 |F'''| ~ 1e-9
  for (double phi : {0.1, 2.2, 5.0}) {
    EXPECT_TRUE(Near(f.dF(phi), (f.F(phi + h) - f.F(phi - h)) / (2 * h), 1e-8));
  }
}

// Jet: the values bit for bit as Values and dF, and F'' against a central difference of F'.
TEST_P(ForcingFamilies, JetAddsTheFirstTwoDerivativesToTheValues) {
  const Forcing& f = GetParam().forcing;
  constexpr double h = 1e-5;  // central difference error ~ h^2 |F''''| ~ 1e-9
  for (double phi : {0.1, 2.2, 5.0, kTau}) {
    const Angle at = Angle::Of(phi);
    const ForceJet j = f.Jet(at);
    const ForceValues v = f.Values(at);
    EXPECT_EQ(j.F, v.F);
    EXPECT_EQ(j.Pi, v.Pi);
    EXPECT_EQ(j.Phi, v.Phi);
    EXPECT_EQ(j.dF, f.dF(phi));
    EXPECT_TRUE(Near(j.ddF, (f.dF(phi + h) - f.dF(phi - h)) / (2 * h), 1e-8)) << "phi " << phi;
  }
}

TEST_P(ForcingFamilies, CrossingsAreExactlyTheSignChangesOfADenseScan) {
  const Forcing& f = GetParam().forcing;
  const Range r = f.Bounds(0.0, kTau);
  for (double level : {r.min + 0.3 * (r.max - r.min), r.min + 0.77 * (r.max - r.min), f.mean()}) {
    for (auto [lo, hi] : {std::pair{0.0, kTau}, std::pair{1.0, 4.0}, std::pair{-2.0, 3.5}}) {
      const PhaseList x = f.Crossings(level, lo, hi);
      int sign_changes = 0;
      double prev = f.F(lo) - level;
      for (int i = 1; i <= kScan; ++i) {
        const double cur = f.F(lo + (hi - lo) * i / kScan) - level;
        if ((prev < 0) != (cur < 0)) ++sign_changes;
        prev = cur;
      }
      EXPECT_EQ(x.n, sign_changes) << "level " << level << " on [" << lo << ", " << hi << "]";
      for (int i = 0; i < x.n; ++i) {
        EXPECT_TRUE(Near(f.F(x.phi[i]), level, kRootTol));
        EXPECT_GE(x.phi[i], lo);
        EXPECT_LE(x.phi[i], hi);
        if (i > 0) {
          EXPECT_LT(x.phi[i - 1], x.phi[i]);
        }
      }
    }
  }
}

TEST_P(ForcingFamilies, BoundsMatchADenseScan) {
  const Forcing& f = GetParam().forcing;
  for (auto [lo, hi] : {std::pair{0.0, kTau}, std::pair{0.5, 2.0}, std::pair{2.5, 6.0}}) {
    double mn = f.F(lo), mx = mn;
    for (int i = 1; i <= kScan; ++i) {
      const double v = f.F(lo + (hi - lo) * i / kScan);
      mn = std::min(mn, v);
      mx = std::max(mx, v);
    }
    const Range r = f.Bounds(lo, hi);
    // The exact extremum is never worse than a sample, and a sample comes within
    // max|F''| * (step/2)^2 / 2 of it (about 1e-9 here).
    EXPECT_LE(r.min, mn + 1e-15);
    EXPECT_GE(r.max, mx - 1e-15);
    EXPECT_TRUE(Near(r.min, mn, 1e-8));
    EXPECT_TRUE(Near(r.max, mx, 1e-8));
  }
  const Range whole = f.Bounds(0.0, kTau);
  EXPECT_TRUE(Near(f.MaxAbs(), std::max(-whole.min, whole.max), 1e-12));
}

TEST_P(ForcingFamilies, WithPhaseShiftsTheMotorPhase) {
  const Forcing& f = GetParam().forcing;
  const Forcing g = f.WithPhase(f.phi0() + 0.8);
  for (double phi : {0.0, 1.0, 4.0}) EXPECT_TRUE(Near(g.F(phi), f.F(phi + 0.8), 1e-13));
}

TEST_P(ForcingFamilies, InImpactFrameIsTheSameForceWithTheImpactAtPhaseZero) {
  const Forcing& f = GetParam().forcing;
  const Forcing g = f.InImpactFrame();
  EXPECT_EQ(g.phi0(), 0.0);
  EXPECT_EQ(g.mean(), f.mean());
  ASSERT_EQ(g.harmonics(), f.harmonics());
  // The same numbers, not only the same function: MaxAbs decides a force bound in its last bit.
  for (double phi : {0.0, 1.0, 2.5, 4.0, 6.0}) {
    EXPECT_EQ(g.F(phi), f.F(phi));
    EXPECT_EQ(g.Pi(phi), f.Pi(phi));
    EXPECT_EQ(g.Phi(phi), f.Phi(phi));
  }
  EXPECT_EQ(g.MaxAbs(), f.MaxAbs());
  // Its base coefficients are the rotated ones: a_k cos k phi0 + b_k sin k phi0 and
  // b_k cos k phi0 - a_k sin k phi0 (angle addition), so F(phi) = G(phi) with phi0 = 0.
  for (int k = 1; k <= f.harmonics(); ++k) {
    const double ck = std::cos(k * f.phi0()), sk = std::sin(k * f.phi0());
    EXPECT_TRUE(Near(g.a(k), f.a(k) * ck + f.b(k) * sk, 1e-15));
    EXPECT_TRUE(Near(g.b(k), f.b(k) * ck - f.a(k) * sk, 1e-15));
  }
}

INSTANTIATE_TEST_SUITE_P(
    Families, ForcingFamilies,
    ::testing::Values(Case{"paper_example", Forcing::Harmonic(0.5, 0.5, -2.9449)},
                      Case{"harmonic_small", Forcing::Harmonic(0.05, 0.02, 1.0)},
                      Case{"fourier_k3",
                           Forcing::Fourier(0.02, {0.01, 0.0, 0.005}, {0.04, 0.01, 0.0}, 0.3)},
                      Case{"fourier_k5", Forcing::Fourier(0.1, {0.2, -0.1, 0.05, 0.0, 0.02},
                                                          {0.3, 0.1, 0.0, -0.04, 0.01}, -1.2)}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(Forcing, HarmonicIsTheOneTermFourierSeries) {
  const Forcing h = Forcing::Harmonic(0.7, 0.2, 0.4);
  const Forcing s = Forcing::Fourier(0.2, {0.0}, {0.7}, 0.4);
  for (double phi : {0.0, 1.3, 5.5}) {
    EXPECT_DOUBLE_EQ(h.F(phi), s.F(phi));
    EXPECT_TRUE(Near(h.F(phi), 0.7 * std::sin(phi + 0.4) + 0.2, 1e-15));
  }
  EXPECT_TRUE(h.harmonic());
  EXPECT_DOUBLE_EQ(h.amplitude(), 0.7);
  EXPECT_FALSE(Forcing::Fourier(0.2, {0.1}, {0.7}, 0.0).harmonic());
}

// One harmonic takes a fast path (no loop over harmonics, cos tau and sin tau as constants,
// the crossings in closed form from R and the phase of the base harmonic, which the impact
// phase only shifts). The same force written as a two-term series with a zero second harmonic
// takes the general path: F and its integrals must agree bit for bit, the crossings and bounds
// to rounding (the general path takes the phase of the rotated coefficients), and the values
// at phi = tau must be those of std::cos and std::sin.
TEST(Forcing, OneHarmonicFastPathIsTheGeneralSeriesBitForBit) {
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> coef(-1.0, 1.0), phase(-kTau, kTau);
  int checked = 0;
  for (int i = 0; i < 200; ++i) {
    const double c = coef(rng), a = coef(rng), b = coef(rng), phi0 = phase(rng);
    const Forcing fast = Forcing::Fourier(c, {a}, {b}, phi0);
    const Forcing general = Forcing::Fourier(c, {a, 0.0}, {b, 0.0}, phi0);
    for (int j = 0; j <= 64; ++j) {
      const double phi = kTau * j / 64.0;
      ASSERT_EQ(fast.F(phi), general.F(phi)) << phi;
      ASSERT_EQ(fast.dF(phi), general.dF(phi)) << phi;
      ASSERT_EQ(fast.Pi(phi), general.Pi(phi)) << phi;
      ASSERT_EQ(fast.Phi(phi), general.Phi(phi)) << phi;
      const ForceValues v = fast.Values(phi), w = general.Values(phi);
      ASSERT_EQ(v.F, w.F);
      ASSERT_EQ(v.Pi, w.Pi);
      ASSERT_EQ(v.Phi, w.Phi);
    }
    for (double level : {-0.5, 0.0, c, 0.3}) {
      const double lo = 0.25 * kTau * coef(rng) + 0.25 * kTau, hi = kTau;
      const PhaseList p = fast.Crossings(level, lo, hi), q = general.Crossings(level, lo, hi);
      ASSERT_EQ(p.n, q.n);
      for (int k = 0; k < p.n; ++k) ASSERT_NEAR(p.phi[k], q.phi[k], kRoundingTol);
      const Range r = fast.Bounds(lo, hi), s = general.Bounds(lo, hi);
      ASSERT_NEAR(r.min, s.min, kRoundingTol);
      ASSERT_NEAR(r.max, s.max, kRoundingTol);
    }
    ++checked;
  }
  EXPECT_EQ(checked, 200);
  // phi = tau from the library's sine and cosine (volatile: evaluated at run time).
  volatile double tau = kTau;
  const Forcing h = Forcing::Harmonic(0.7, 0.2, 0.0);  // F = 0.2 + 0.7 sin phi
  EXPECT_EQ(h.F(kTau), 0.2 + (0.0 * std::cos(tau) + 0.7 * std::sin(tau)));
  EXPECT_EQ(h.Pi(kTau), 0.2 * kTau + (0.0 * std::sin(tau) + 0.7 * (1.0 - std::cos(tau))));
}

TEST(Forcing, TangentLevelIsOneCrossing) {
  const Forcing f = Forcing::Harmonic(1.0, 0.0, 0.0);  // max 1 at phi = pi/2
  const PhaseList x = f.Crossings(1.0, 0.0, kTau);
  ASSERT_EQ(x.n, 1);
  EXPECT_TRUE(Near(x.phi[0], M_PI / 2, 1e-12));
}

TEST(Forcing, ConstantForceHasNoCrossings) {
  const Forcing f = Forcing::Fourier(0.3, {}, {}, 0.0);
  EXPECT_EQ(f.Crossings(0.0, 0.0, kTau).n, 0);
  EXPECT_DOUBLE_EQ(f.MaxAbs(), 0.3);
}

TEST(Forcing, RejectsNegativeAmplitudeNamingIt) {
  try {
    Forcing::Harmonic(-1.0, 0.5, 0.0);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "A = -1 is invalid: expected A >= 0");
  }
}

TEST(Forcing, RejectsNonFiniteNumbersNamingThem) {
  const double nan = std::nan("");
  EXPECT_THROW(
      {
        try {
          Forcing::Harmonic(0.5, nan, 0.0);
        } catch (const std::invalid_argument& e) {
          EXPECT_STREQ(e.what(), "c = nan is invalid: expected a finite number");
          throw;
        }
      },
      std::invalid_argument);
  try {
    Forcing::Fourier(0.1, {0.0, INFINITY}, {0.0, 0.0}, 0.0);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "a_2 = inf is invalid: expected a finite number");
  }
  try {
    Forcing::Harmonic(0.5, 0.5, nan);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "phi0 = nan is invalid: expected a finite number");
  }
}

TEST(Forcing, RejectsMismatchedOrTooManyCoefficients) {
  try {
    Forcing::Fourier(0.1, {0.0}, {0.0, 0.0}, 0.0);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "Fourier coefficients: 1 cosine and 2 sine terms given: expected as many of each");
  }
  const std::vector<double> many(kMaxHarmonics + 1, 0.0);
  try {
    Forcing::Fourier(0.1, many, many, 0.0);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "harmonics K = 17 is invalid: expected K <= 16");
  }
}

// Angles without sincos: a step by angle addition (the short and the long series, and beyond
// 3/2 a fresh sincos), a chain of such steps as in a root search, and the closed-form
// crossings of one harmonic give the cosine and sine of their phase to a few ulp of std::cos
// and std::sin.
TEST(Forcing, AnglesWithoutSincosMatchTheLibrary) {
  constexpr double kStepTol = 1e-15;  // one step: a few ulp of 1 (measured: at most 2)
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> phase(-kTau, kTau), step(-2.0, 2.0);
  int steps = 0, crossings = 0;
  for (int i = 0; i < 4000; ++i) {
    const Angle from = Angle::Of(phase(rng));
    const Angle to = from.Toward(from.phi + step(rng));
    ASSERT_NEAR(to.cos, std::cos(to.phi), kStepTol) << "step " << to.phi - from.phi;
    ASSERT_NEAR(to.sin, std::sin(to.phi), kStepTol) << "step " << to.phi - from.phi;
    ++steps;
  }
  Angle chain = Angle::Of(0.3);  // 100 steps of up to 3/2, none with a sincos
  for (int i = 0; i < 100; ++i) chain = chain.Toward(chain.phi + 0.75 * step(rng));
  EXPECT_NEAR(chain.cos, std::cos(chain.phi), kRoundingTol);
  EXPECT_NEAR(chain.sin, std::sin(chain.phi), kRoundingTol);
  const Forcing f = Forcing::Fourier(0.1, {0.3}, {-0.4}, 1.1);
  for (double level : {-0.35, 0.0, 0.2, 0.55}) {
    const AngleList a = f.CrossingAngles(level, 0.5, 0.5 + kTau);
    const PhaseList p = f.Crossings(level, 0.5, 0.5 + kTau);
    ASSERT_EQ(a.n, 2);
    ASSERT_EQ(p.n, 2);
    for (int k = 0; k < a.n; ++k) {
      EXPECT_EQ(a.angle[k].phi, p.phi[k]);
      EXPECT_NEAR(a.angle[k].cos, std::cos(p.phi[k]), kRoundingTol);
      EXPECT_NEAR(a.angle[k].sin, std::sin(p.phi[k]), kRoundingTol);
      EXPECT_NEAR(f.F(p.phi[k]), level, kRootTol);
      ++crossings;
    }
  }
  EXPECT_EQ(steps, 4000);
  EXPECT_EQ(crossings, 8);
}

// Input phases: reduced modulo the true 2 pi, refused where a double carries no angle.

// The remainders below were computed with 300-bit arithmetic (mpmath): x - n 2 pi, n the
// nearest whole number to x/(2 pi), for each double x.
struct PhaseCase {
  double phi, reduced;
};

// Three roundings of the reduction, each at most half an ulp of pi.
constexpr double kReductionTol = 2e-15;

TEST(InputPhase, IsReducedModuloTheTrueTwoPi) {
  const PhaseCase cases[] = {
      {4.0, -0x1.243f6a8885a31p+1},
      {-4.0, 0x1.243f6a8885a31p+1},
      {7.0, 0x1.6f0255dde973ep-1},
      {123456.789, -0x1.84e3c9c5bd10ap+0},
      {1e6, -0x1.6e254d0f6b398p-2},
      {-1e6, 0x1.6e254d0f6b398p-2},
      {999999.9999999999, -0x1.6e254d116b398p-2},
      // 0.5 + 10^5 turns, rounded to a double: the true remainder of that double.
      {628319.0307179586, 0x1.fffffffed5476p-2},
      {628315.6307179587, -0x1.7333333325571p+1},
  };
  for (const PhaseCase& c : cases) {
    const double r = ReduceInputPhase("phi0", c.phi);
    EXPECT_NEAR(r, c.reduced, kReductionTol)
        << "phi = " << c.phi << ", difference " << r - c.reduced;
    // The force keeps the reduced phase: the same motor as the reference phase.
    const Forcing f = Forcing::Harmonic(0.5, 0.1, c.phi);
    EXPECT_EQ(f.phi0(), r);
    EXPECT_NEAR(f.F(1.0), Forcing::Harmonic(0.5, 0.1, c.reduced).F(1.0), 1e-15);
  }
}

TEST(InputPhase, WithinHalfATurnIsKeptBitForBit) {
  for (double phi : {0.0, -0.0, 1.0, -2.842, 3.141592653589793, -3.141592653589793, 1e-300}) {
    EXPECT_EQ(ReduceInputPhase("phi0", phi), phi);
    EXPECT_EQ(Forcing::Harmonic(0.5, 0.1, phi).phi0(), phi);
  }
}

TEST(InputPhase, BeyondTheBoundIsRefusedNamingRadians) {
  for (double phi : {1e300, -1e16, 1000000.0000000001}) {
    try {
      Forcing::Harmonic(0.5, 0.5, phi);
      FAIL() << "no exception for " << phi;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(" is invalid: expected a phase |phi0| <= 1e+06 rad "
                                           "(phases are in radians"),
                std::string::npos)
          << e.what();
      EXPECT_EQ(std::string(e.what()).rfind("phi0 = ", 0), 0U) << e.what();
    }
  }
  // The same bound for a phase set on a built force (a bifurcation over phi0).
  EXPECT_THROW(Forcing::Harmonic(0.5, 0.5, 0.0).WithPhase(1e300), std::invalid_argument);
  try {
    Forcing::Harmonic(0.5, 0.5, 0.0).WithPhase(-1e16);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(),
                 "phi0 = -1e+16 is invalid: expected a phase |phi0| <= 1e+06 rad (phases are in "
                 "radians; a larger one carries no angle to the digits of a double)");
  }
}

TEST(InputPhase, ReducedPhaseGivesTheOrbitOfItsRemainder) {
  // -2.9 + 10^5 turns, rounded to a double, and its remainder (mpmath, 300 bits): the orbit of
  // the remainder to rounding, not that of a phase shifted by the rounding of 10^5 (2 pi)
  // (about 1e-10 rad).
  const Params p{1.0, 0.5};
  const Orbit big = ComputeOrbit(Forcing::Harmonic(0.5, 0.3, 628315.6307179587), p);
  const Orbit ref = ComputeOrbit(Forcing::Harmonic(0.5, 0.3, -0x1.7333333325571p+1), p);
  ASSERT_TRUE(ref.ok());
  EXPECT_NEAR(big.phi1, ref.phi1, 1e-13);
  EXPECT_NEAR(big.alpha, ref.alpha, 1e-13);
  EXPECT_NEAR(big.I, ref.I, 1e-12);
  // The extrema of x come from crossing phases of F, phi + delta with delta = phi0 + const:
  // unreduced, 628315.6 + phi lost 2e-11 of x_min (-12.5969194117288 against
  // -12.5969194117497).
  const Solution big_s = Solve(Forcing::Harmonic(0.5, 0.3, 628315.6307179587), p);
  const Solution ref_s = Solve(Forcing::Harmonic(0.5, 0.3, -0x1.7333333325571p+1), p);
  EXPECT_NEAR(big_s.validity.x_min, ref_s.validity.x_min, 1e-12);
}

}  // namespace
}  // namespace capsubot
