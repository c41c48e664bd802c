// The simulator's force seen from a segment's origin: its values and jet at an angle against
// the motor's own series shifted there (Forcing::WithPhase, an independent evaluation), its
// tabulated piece signs against the sign of F - level computed at the piece's middle, and the
// accuracy of the angles a root search steps to.

#include "simulate/segment_force.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <vector>

#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::Near;

std::vector<Forcing> Motors() {
  return {Forcing::Harmonic(0.34063197373861814, 0.06410131873607934, -3.1181183398453047),
          Forcing::Fourier(0.3, {0.2, -0.1, 0.05}, {0.5, 0.1, 0.0}, 0.7)};
}

TEST(SegmentForce, JetAtAnAngleIsTheShiftedMotorsJet) {
  std::mt19937_64 rng(11);
  std::uniform_real_distribution<double> phase(0.0, kTau);
  int checked = 0;
  for (const Forcing& motor : Motors()) {
    detail::SegmentForce f;
    f.Prepare(motor, nullptr, 0, 1e-12);
    for (int i = 0; i < 200; ++i) {
      const double shift = phase(rng), s = 1.5 * phase(rng);
      f.Set(motor, shift);
      const Forcing shifted = motor.WithPhase(motor.phi0() + shift);
      const ForceJet want = shifted.Jet(Angle::Of(s));
      const ForceJet got = f.Jet(detail::SegmentForce::At(s));
      const ForceValues values = f.Values(s);
      EXPECT_TRUE(Near(got.F, want.F, 1e-14));
      EXPECT_TRUE(Near(got.dF, want.dF, 1e-14));
      EXPECT_TRUE(Near(got.ddF, want.ddF, 1e-14));
      EXPECT_TRUE(Near(got.Pi, want.Pi, 1e-14));
      EXPECT_TRUE(Near(got.Phi, want.Phi, 1e-13));
      EXPECT_EQ(values.F, got.F);  // Values is Jet without the derivatives, bit for bit
      EXPECT_EQ(values.Pi, got.Pi);
      EXPECT_EQ(values.Phi, got.Phi);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 400);
}

TEST(SegmentForce, TabulatedPieceSignsAreTheSignsAtThePiecesMiddles) {
  // Every part of a piece between consecutive crossings, long or short, placed anywhere in
  // the segment: the tabulated sign (or, for short parts, the evaluated one) is the sign of
  // F - level at the part's middle.
  std::mt19937_64 rng(5);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  constexpr double kTol = 1e-12;
  int checked = 0, tabulated = 0;
  for (const Forcing& motor : Motors()) {
    const double levels[] = {0.25, -0.25, 0.0, 0.1, -0.1};
    detail::SegmentForce f;
    f.Prepare(motor, levels, 5, kTol);
    for (int i = 0; i < 400; ++i) {
      const double shift = kTau * unit(rng);
      f.Set(motor, shift);
      for (const double level : levels) {
        const detail::CrossingList cuts = f.Crossings(level, 0.0, kTau);
        // A random part of the piece after a random crossing (or of the whole period).
        const int k = cuts.n > 0 ? static_cast<int>(unit(rng) * cuts.n) % cuts.n : 0;
        const double a = cuts.n > 0 ? cuts.phi[k] : 0.0;
        const double b =
            cuts.n > 1 ? (k + 1 < cuts.n ? cuts.phi[k + 1] : cuts.phi[0] + kTau) : a + kTau;
        const double u = unit(rng), w = unit(rng) * (1.0 - u);
        const double l = a + u * (b - a), r = l + std::max(w * (b - a), 1e-9);
        const double g = f.F(0.5 * (l + r)) - level;
        const double want = g > kTol ? 1.0 : g < -kTol ? -1.0 : 0.0;
        EXPECT_EQ(f.PieceSign(level, l, r), want) << level << " on (" << l << ", " << r << ")";
        tabulated += r - l >= detail::SegmentForce::kNearCut ? 1 : 0;
        ++checked;
      }
    }
  }
  EXPECT_EQ(checked, 4000);
  EXPECT_GT(tabulated, 3000);  // most parts are long: the table, not an evaluation, decides
}

TEST(SegmentForce, StepsToSmallPhasesKeepTheRelativeAccuracyOfTheSine) {
  // A root search converging on a short flight steps to phases of 1e-8 .. 1e-2 from far
  // iterates, from the origin and from close ones: sin s within a few ulp of sin s itself.
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> exponent(-8.0, -2.0), unit(0.0, 1.0);
  const detail::SegmentForce f;
  int checked = 0;
  for (int i = 0; i < 3000; ++i) {
    const double to = std::pow(10.0, exponent(rng));
    const double from_phase[] = {0.0, to * (1.0 + 0.4 * unit(rng)), 0.1 + unit(rng)};
    for (const double p : from_phase) {
      const Angle from = detail::SegmentForce::At(p);
      const Angle got = detail::StepAngle(f, from, to);
      EXPECT_EQ(got.phi, to);
      EXPECT_TRUE(Near(got.sin, std::sin(to), 4e-16 * std::sin(to))) << p << " -> " << to;
      EXPECT_TRUE(Near(got.cos, std::cos(to), 4e-16));
      ++checked;
    }
  }
  EXPECT_EQ(checked, 9000);
}

}  // namespace
}  // namespace capsubot
