// The drives of the reach search (docs/reach.md, "Drives"): every point of the box is a force
// under the bound, exactly; the bound is checked against a dense sampling of F written out here;
// a force of the family has coordinates that give it back.

#include "capsubot/reach/drive_family.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::Near;

// max |F| of the drive is its bound (s bound for the sine) to rounding of the scale (a few ulp).
constexpr double kBoundRoundingTol = 1e-12;
// A dense sampling of F (2^16 phases, then a parabola through the three samples around the
// largest |F|) finds the exact maximum to about (h^2/8) |F''| ~ 1e-8 for K <= 4; the exact
// maximum is never below the sampled one by more than rounding.
constexpr int kSamples = 1 << 16;
constexpr double kSampledMaxTol = 1e-7;

// F of the series c + sum a_k cos k t + b_k sin k t, written out (not Forcing's code).
double SeriesAt(const Forcing& f, double t) {
  double F = f.mean();
  for (int k = 1; k <= f.harmonics(); ++k) F += f.a(k) * std::cos(k * t) + f.b(k) * std::sin(k * t);
  return F;
}

double SampledMaxAbs(const Forcing& f) {
  const double h = kTau / kSamples;
  double best = 0.0;
  int at = 0;
  for (int i = 0; i < kSamples; ++i) {
    const double v = std::abs(SeriesAt(f, i * h));
    if (v > best) {
      best = v;
      at = i;
    }
  }
  // Refine by the parabola through the neighbours (|F| is smooth at its largest value).
  const double l = std::abs(SeriesAt(f, (at - 1) * h)), r = std::abs(SeriesAt(f, (at + 1) * h));
  const double curvature = l - 2.0 * best + r;
  return curvature < 0.0 ? best - 0.125 * (r - l) * (r - l) / curvature : best;
}

std::vector<double> RandomPoint(const DriveFamily& family, std::mt19937_64& rng) {
  std::vector<double> lower, upper;
  DriveBox(family, lower, upper);
  std::vector<double> y(lower.size());
  for (std::size_t i = 0; i < y.size(); ++i) {
    y[i] = std::uniform_real_distribution<double>(lower[i], upper[i])(rng);
  }
  return y;
}

class DriveFamilyK : public ::testing::TestWithParam<int> {};

TEST_P(DriveFamilyK, EveryPointOfTheBoxIsAForceAtItsBoundExactly) {
  const DriveFamily family = DriveFamily::Fourier(GetParam());
  std::mt19937_64 rng(20261206 + static_cast<unsigned>(GetParam()));
  const double bound = 0.75;
  for (int trial = 0; trial < 50; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const std::vector<double> y = RandomPoint(family, rng);
    const Forcing f = DriveAt(family, y.data(), bound, 0.3);
    ASSERT_EQ(f.harmonics(), family.sine() ? 1 : family.harmonics);
    // The sine: A + c = s bound; a series of K >= 2 harmonics: its whole bound.
    const double expected = family.sine() ? y[0] * bound : bound;
    EXPECT_TRUE(Near(f.MaxAbs(), expected, kBoundRoundingTol * bound));
    // The exact maximum against dense sampling of the series written out.
    const double sampled = SampledMaxAbs(f);
    EXPECT_GE(f.MaxAbs(), sampled - kBoundRoundingTol);
    EXPECT_TRUE(Near(f.MaxAbs(), sampled, kSampledMaxTol));
    // The first harmonic is a pure sine with b_1 >= 0 (the gauge of the family).
    EXPECT_EQ(f.a(1), 0.0);
    EXPECT_GE(f.b(1), 0.0);
  }
}

TEST_P(DriveFamilyK, AForceOfTheFamilyHasCoordinatesThatGiveItBack) {
  const DriveFamily family = DriveFamily::Fourier(GetParam());
  std::mt19937_64 rng(7 + static_cast<unsigned>(GetParam()));
  const double bound = 2.0;
  for (int trial = 0; trial < 20; ++trial) {
    SCOPED_TRACE("trial " + std::to_string(trial));
    const Forcing f = DriveAt(family, RandomPoint(family, rng).data(), bound, -1.1);
    const std::vector<double> y = DriveCoordinates(family, f, bound);
    ASSERT_EQ(static_cast<int>(y.size()), family.Dimension());
    const Forcing g = DriveAt(family, y.data(), bound, f.phi0());
    for (double t = 0.0; t < kTau; t += 0.01) {
      ASSERT_TRUE(Near(g.F(t), f.F(t), 1e-12 * bound)) << "phi = " << t;
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Harmonics, DriveFamilyK, ::testing::Values(1, 2, 3, 4));

TEST(DriveFamily, TheSineIsAForceOfEveryLargerFamily) {
  // The sine winner A sin(s) + c at its bound seeds every K: its coordinates give the same
  // force, and WithHarmonicsOf writes it with K harmonics, unchanged.
  const Forcing sine = Forcing::Harmonic(0.7, 0.3, -2.5);
  const double bound = 1.0;
  for (int K = 1; K <= 5; ++K) {
    const DriveFamily family = DriveFamily::Fourier(K);
    const std::vector<double> y = DriveCoordinates(family, sine, bound);
    ASSERT_EQ(static_cast<int>(y.size()), family.Dimension()) << "K = " << K;
    const Forcing back = DriveAt(family, y.data(), bound, sine.phi0());
    const Forcing padded = WithHarmonicsOf(family, sine);
    EXPECT_EQ(padded.harmonics(), K);
    for (double t = 0.0; t < kTau; t += 0.05) {
      const double F = 0.7 * std::sin(t - 2.5) + 0.3;
      EXPECT_TRUE(Near(back.F(t), F, 1e-12)) << "K = " << K;
      EXPECT_TRUE(Near(padded.F(t), F, 1e-15)) << "K = " << K;
    }
  }
}

TEST(DriveFamily, ASeriesBelowItsBoundIsTheSameDriveScaledToIt) {
  // max |F| = 0.9 < 1: in a family of K >= 2 its coordinates give the same shape at max |F| = 1.
  const Forcing weak = Forcing::Harmonic(0.6, 0.3, -2.5);
  const DriveFamily family = DriveFamily::Fourier(3);
  const std::vector<double> y = DriveCoordinates(family, weak, 1.0);
  ASSERT_EQ(static_cast<int>(y.size()), family.Dimension());
  const Forcing back = DriveAt(family, y.data(), 1.0, weak.phi0());
  for (double t = 0.0; t < kTau; t += 0.05) {
    EXPECT_TRUE(Near(back.F(t), (0.6 * std::sin(t - 2.5) + 0.3) / 0.9, 1e-12));
  }
}

TEST(DriveFamily, ForcesOutsideTheFamilyHaveNoCoordinates) {
  const double bound = 1.0;
  // Above the bound.
  EXPECT_TRUE(
      DriveCoordinates(DriveFamily::Fourier(2), Forcing::Harmonic(0.9, 0.2, 0.0), bound).empty());
  // A first harmonic with a cosine (not in the family's gauge).
  EXPECT_TRUE(
      DriveCoordinates(DriveFamily::Fourier(2), Forcing::Fourier(0.1, {0.2}, {0.3}, 0.0), bound)
          .empty());
  // More harmonics than the family holds.
  EXPECT_TRUE(DriveCoordinates(DriveFamily::Fourier(2),
                               Forcing::Fourier(0.1, {0.0, 0.1, 0.1}, {0.3, 0.0, 0.1}, 0.0), bound)
                  .empty());
}

TEST(DriveFamilyInput, AHarmonicsCountOutOfRangeIsNamedWithItsRule) {
  for (int K : {0, -3, kMaxHarmonics + 1}) {
    try {
      DriveFamily::Fourier(K).Validate();
      ADD_FAILURE() << "K = " << K << " accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()),
                "harmonics = " + std::to_string(K) + " is invalid: expected 1 <= harmonics <= 16");
    }
  }
}

}  // namespace
}  // namespace capsubot
