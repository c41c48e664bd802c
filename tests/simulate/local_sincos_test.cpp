// The simulator's inline cos and sin of a local phase, against long double sinl and cosl (an
// independent computation with 11 more bits): below one unit in the last place everywhere,
// including next to the multiples of pi/2 where the result is small.

#include "simulate/local_sincos.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

namespace capsubot {
namespace {

constexpr double kMaxUlps = 1.0;  // the polynomials and the reduction keep below this

double Ulp(double x) {
  const double ax = std::abs(x);
  return std::nextafter(ax, std::numeric_limits<double>::infinity()) - ax;
}

// Error of LocalCosSin(x) in units of the last place of the exact value (the larger of cos
// and sin).
double UlpError(double x) {
  const detail::CosSin cs = detail::LocalCosSin(x);
  const long double c = std::cos(static_cast<long double>(x));
  const long double s = std::sin(static_cast<long double>(x));
  const double ec = static_cast<double>(std::abs(cs.c - c)) / Ulp(static_cast<double>(c));
  const double es = static_cast<double>(std::abs(cs.s - s)) / Ulp(static_cast<double>(s));
  return std::max(ec, es);
}

TEST(LocalCosSin, BelowOneUlpOverTwoPeriodsAndBeyond) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> phase(-1.0, 64.0);
  constexpr int kCases = 1000000;
  double worst = 0.0;
  int checked = 0;
  for (int i = 0; i < kCases; ++i, ++checked) worst = std::max(worst, UlpError(phase(rng)));
  EXPECT_EQ(checked, kCases);
  EXPECT_LT(worst, kMaxUlps);
}

TEST(LocalCosSin, BelowOneUlpNextToMultiplesOfHalfPi) {
  double worst = 0.0;
  int checked = 0;
  for (int k = -2; k <= 40; ++k) {
    const double x = k * (0.5 * M_PI);
    for (int j = -200; j <= 200; ++j, ++checked) {
      worst = std::max(worst, UlpError(x + j * Ulp(x == 0.0 ? 1.0 : x)));
    }
    for (int e = 1; e <= 15; ++e, ++checked)
      worst = std::max(worst, UlpError(x + std::pow(10.0, -e)));
  }
  EXPECT_EQ(checked, 43 * (401 + 15));
  EXPECT_LT(worst, kMaxUlps);
}

TEST(LocalCosSin, ExactAtZeroAndLibraryBeyondTheReducedRange) {
  const detail::CosSin zero = detail::LocalCosSin(0.0);
  EXPECT_EQ(zero.c, 1.0);
  EXPECT_EQ(zero.s, 0.0);
  for (const double x : {100.0, -1e6, 1e300}) {
    const detail::CosSin cs = detail::LocalCosSin(x);
    EXPECT_EQ(cs.c, std::cos(x)) << x;
    EXPECT_EQ(cs.s, std::sin(x)) << x;
  }
  EXPECT_TRUE(std::isnan(detail::LocalCosSin(std::numeric_limits<double>::quiet_NaN()).c));
}

}  // namespace
}  // namespace capsubot
