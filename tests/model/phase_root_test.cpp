// The root finder of the orbit and of the simulator's events: the parabola that starts it,
// and its zeros and values against an independent bisection and Forcing::Values.

#include "capsubot/model/detail/phase_root.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::Near;

TEST(ParabolaZero, IsTheZeroOfTheParabolaNextToTheEnd) {
  // f(h) = (h - 0.3)(h - 2) = 0.6 - 2.3 h + h^2 at h = 0: zeros 0.3 and 2, the nearer is 0.3;
  // seen from phase 1 the same parabola gives 1.3.
  EXPECT_TRUE(Near(detail::ParabolaZero({Angle::Of(0.0), 0.6, -2.3, 2.0}), 0.3, 1e-15));
  EXPECT_TRUE(Near(detail::ParabolaZero({Angle::Of(1.0), 0.6, -2.3, 2.0}), 1.3, 1e-15));
  // From the other side of its vertex (h = 1.15): f(2.5) = 1.1, f' = 2.7: the zero next to
  // it is 2, behind it.
  EXPECT_TRUE(Near(detail::ParabolaZero({Angle::Of(2.5), 0.22 * 5.0, 2.7, 2.0}), 2.5 - 0.5, 1e-14));
  // A line (f'' = 0) and a parabola with no real zero.
  EXPECT_TRUE(Near(detail::ParabolaZero({Angle::Of(0.5), -1.0, 4.0, 0.0}), 0.75, 1e-15));
  EXPECT_TRUE(std::isnan(detail::ParabolaZero({Angle::Of(0.0), 1.0, 0.0, 1.0})));
}

TEST(ParabolaStart, UsesTheEndWithTheShorterNewtonStepAndStaysInside) {
  // f = h^2 - 0.01 on [0, 2]: from 0, f' = 0 (an infinite Newton step), so the end at 2
  // predicts, and for a parabola exactly: 0.1 (to the rounding of f'^2 - 2 f f'' = 16 - 15.96).
  const detail::BracketEnd lo{Angle::Of(0.0), -0.01, 0.0, 2.0}, hi{Angle::Of(2.0), 3.99, 4.0, 2.0};
  EXPECT_TRUE(Near(detail::ParabolaStart(lo, hi), 0.1, 1e-13));
  // A prediction outside the bracket is no start.
  const detail::BracketEnd far{Angle::Of(0.05), -0.0075, 0.1, 2.0};
  EXPECT_TRUE(std::isnan(detail::ParabolaStart(lo, far)));
}

TEST(PhaseRoot, ZeroAndValuesFromAnyStartAgreeWithBisection) {
  // g = Pi(phi) - m phi for a two-harmonic force: its zeros against 200 steps of bisection,
  // from the chord, from the parabola and from a poor start near an end; the values at the
  // zero (Taylor series of the last iterate) against Forcing::Values there.
  const Forcing force = Forcing::Fourier(0.2, {0.3, -0.1}, {0.4, 0.05}, 0.4);
  std::mt19937_64 rng(9);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int checked = 0;
  for (int i = 0; i < 300; ++i) {
    const double m = 0.2 + 0.5 * unit(rng);
    const auto g = [&](double phi) { return force.Pi(phi) - m * phi; };
    const auto jet = [&](const Angle& at, const ForceJet& v) {
      return detail::PhaseJet{v.Pi - m * at.phi, v.F - m, v.dF, v.ddF};
    };
    const double a = 0.05 + 2.0 * unit(rng), b = a + 0.05 + 2.0 * unit(rng);
    const double ga = g(a), gb = g(b);
    if (!(ga * gb < 0.0)) continue;
    double lo = a, hi = b;
    for (int k = 0; k < 200; ++k)
      ((g(0.5 * (lo + hi)) < 0.0) == (ga < 0.0) ? lo : hi) = 0.5 * (lo + hi);
    const ForceJet ja = force.Jet(Angle::Of(a)), jb = force.Jet(Angle::Of(b));
    const double starts[] = {std::numeric_limits<double>::quiet_NaN(),
                             detail::ParabolaStart({Angle::Of(a), ga, ja.F - m, ja.dF},
                                                   {Angle::Of(b), gb, jb.F - m, jb.dF}),
                             a + 1e-6 * (b - a)};
    for (const double start : starts) {
      const detail::PhaseZero z =
          detail::PhaseRoot(force, jet, Angle::Of(a), Angle::Of(b), ga, gb, start);
      EXPECT_TRUE(Near(z.at.phi, lo, 1e-14)) << start;
      const ForceValues v = force.Values(z.at.phi);
      EXPECT_TRUE(Near(z.values.F, v.F, 1e-14));
      EXPECT_TRUE(Near(z.values.Pi, v.Pi, 1e-14));
      EXPECT_TRUE(Near(z.values.Phi, v.Phi, 1e-14));
      EXPECT_TRUE(Near(z.at.sin, std::sin(z.at.phi), 1e-15));
      ++checked;
    }
  }
  EXPECT_GT(checked, 150);  // about a third of the random brackets hold a sign change
}

}  // namespace
}  // namespace capsubot
