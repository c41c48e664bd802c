#pragma once
// cos s and sin s together for the local phases of the simulator's segments (docs/model.md
// section 3: every force value the event searches need costs one of these), inline and
// without a library call: the argument is reduced by multiples of pi/2 (pi/2 split into
// parts whose products with the multiple are exact), and cos and sin of the remainder
// r in [-pi/4, pi/4] come from minimax polynomials of degree 14 and 13 that carry the low
// part of r. Error below one unit in the last place (tests/simulate/local_sincos_test.cpp
// checks it against long double sin and cos); arguments beyond kMaxReduced (never a local
// phase, which stays within two periods, nor the phase of a segment's origin for forcing
// phases phi0 of a few periods) and non-finite ones go to std::cos and std::sin.

#include <cmath>
#include <cstdint>
#include <cstring>

namespace capsubot::detail {

struct CosSin {
  double c, s;
};

namespace local_sincos {

// 2/pi and pi/2 = kPio2a + kPio2b + kPio2c (the first two with 33 significant bits, so
// n * kPio2a and n * kPio2b are exact for |n| < 2^20).
inline constexpr double kTwoOverPi = 6.36619772367581382433e-01;
inline constexpr double kPio2a = 1.57079632673412561417e+00;
inline constexpr double kPio2b = 6.07710050630396597660e-11;
inline constexpr double kPio2c = 2.02226624879595063154e-21;
// Within this bound (n <= 41) the three parts of pi/2 leave an error far below an ulp of the
// remainder even where x comes closest to a multiple of pi/2.
inline constexpr double kMaxReduced = 64.0;
// Adding and subtracting 1.5 * 2^52 rounds a double below 2^51 to the nearest integer.
inline constexpr double kRoundToInteger = 6755399441055744.0;

// sin r ~ r + r^3 (S1 + r^2 (S2 + ...)) and cos r ~ 1 - r^2/2 + r^4 (C1 + r^2 (C2 + ...)) on
// [-pi/4, pi/4] (minimax, relative error below 2^-58).
inline constexpr double kS1 = -1.66666666666666324348e-01, kS2 = 8.33333333332248946124e-03,
                        kS3 = -1.98412698298579493134e-04, kS4 = 2.75573137070700676789e-06,
                        kS5 = -2.50507602534068634195e-08, kS6 = 1.58969099521155010221e-10;
inline constexpr double kC1 = 4.16666666666666019037e-02, kC2 = -1.38888888888741095749e-03,
                        kC3 = 2.48015872894767294178e-05, kC4 = -2.75573143513906633035e-07,
                        kC5 = 2.08757232129817482790e-09, kC6 = -1.13596475577881948265e-11;

// sin(x + y) for |x| <= pi/4, |y| below half an ulp of x.
inline double Sin(double x, double y) {
  const double z = x * x, v = z * x;
  const double r = kS2 + z * (kS3 + z * (kS4 + z * (kS5 + z * kS6)));
  return x - ((z * (0.5 * y - v * r) - y) - v * kS1);
}

// cos(x + y) for |x| <= pi/4, |y| below half an ulp of x: 1 - x^2/2 + ..., with 1 - x^2/2
// split as (1 - q) - (x^2/2 - q), q = x^2/4 cut to its leading bits (exact differences),
// once x^2/2 is large enough for its rounding to matter.
inline double Cos(double x, double y) {
  const double z = x * x;
  const double r = z * (kC1 + z * (kC2 + z * (kC3 + z * (kC4 + z * (kC5 + z * kC6)))));
  const double ax = std::abs(x);
  if (ax < 0.3) return 1.0 - (0.5 * z - (z * r - x * y));
  double q = 0.28125;
  if (ax <= 0.78125) {
    // x/4 with the low 32 bits of its representation cleared.
    std::uint64_t bits;
    std::memcpy(&bits, &ax, sizeof bits);
    bits = (bits - (std::uint64_t{2} << 52)) & 0xffffffff00000000ULL;
    std::memcpy(&q, &bits, sizeof q);
  }
  const double hz = 0.5 * z - q, a = 1.0 - q;
  return a - (hz - (z * r - x * y));
}

}  // namespace local_sincos

/// cos x and sin x (see the file comment).
inline CosSin LocalCosSin(double x) {
  using namespace local_sincos;
  if (!(std::abs(x) <= kMaxReduced)) return {std::cos(x), std::sin(x)};
  const double n = (x * kTwoOverPi + kRoundToInteger) - kRoundToInteger;
  // r = x - n pi/2 as hi + lo: the first product is exact and so is its difference with x
  // (they agree in their leading bits); the error of the second difference is recovered.
  const double t = x - n * kPio2a;
  const double w1 = n * kPio2b;
  const double r = t - w1;
  const double w = n * kPio2c - ((t - r) - w1);
  const double hi = r - w;
  const double lo = (r - hi) - w;
  const double sn = Sin(hi, lo), cs = Cos(hi, lo);
  switch (static_cast<int>(static_cast<std::int64_t>(n) & 3)) {
    case 0:
      return {cs, sn};
    case 1:
      return {-sn, cs};
    case 2:
      return {-cs, -sn};
    default:
      return {sn, -cs};
  }
}

}  // namespace capsubot::detail
