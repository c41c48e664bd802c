#pragma once
// The one rule for the values of an equally spaced grid, lo + i (hi - lo)/(n - 1) for
// i = 0..n-1: every grid of the program (sweep and design axes, bifurcation values, the
// centres of the start grids) takes its values from GridValue.
//
// The values are the numbers the user asked for. A bound written with at most kDecimalDigits
// significant digits is a decimal as written (every such decimal survives the round trip
// through a double); when both bounds are, and the exact value lo + i (hi - lo)/(n - 1) is a
// terminating decimal, the value is that decimal correctly rounded: -2.8:-2.4:3 gives -2.6,
// not -2.5999999999999996. Otherwise (1/3 of a step, a bound such as pi) it is the weighted
// mean (lo (n-1-i) + hi i)/(n-1), symmetric in lo and hi, inside [lo, hi]. The ends are
// exactly lo and hi.

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstdlib>
#include <optional>
#include <string>
#include <system_error>
#include <utility>

namespace capsubot {

/// Most significant digits of a bound read as the decimal the user wrote (DBL_DIG).
inline constexpr int kDecimalDigits = 15;

namespace grid_value_internal {

/// x = m 10^e with m the integer of x's shortest round-trip digits; nullopt when those are
/// more than kDecimalDigits.
struct Decimal {
  std::int64_t m = 0;
  int e = 0;
};

inline std::optional<Decimal> ShortDecimal(double x) {
  char text[40];
  const std::to_chars_result r =
      std::to_chars(text, text + sizeof text, x, std::chars_format::scientific);
  const char* p = text;
  const bool negative = *p == '-';
  if (negative) ++p;
  Decimal d;
  int digits = 0;
  for (; p < r.ptr && *p != 'e'; ++p) {
    if (*p == '.') continue;
    if (++digits > kDecimalDigits) return std::nullopt;
    d.m = 10 * d.m + (*p - '0');
  }
  if (p == r.ptr) return std::nullopt;  // not finite: "inf", "nan"
  ++p;
  if (*p == '+') ++p;
  int exponent = 0;
  std::from_chars(p, r.ptr, exponent);
  d.e = exponent - (digits - 1);
  if (negative) d.m = -d.m;
  return d;
}

/// m 10^shift, nullopt on overflow.
inline std::optional<std::int64_t> Scaled(std::int64_t m, int shift) {
  for (int k = 0; k < shift; ++k) {
    if (__builtin_mul_overflow(m, std::int64_t{10}, &m)) return std::nullopt;
  }
  return m;
}

/// The exact value lo + i (hi - lo)/(n - 1) correctly rounded, when lo and hi are short
/// decimals and that value is a terminating decimal within 64-bit integer arithmetic.
inline std::optional<double> DecimalValue(double lo, double hi, std::int64_t n, std::int64_t i) {
  const std::optional<Decimal> a = ShortDecimal(lo), b = ShortDecimal(hi);
  if (!a || !b) return std::nullopt;
  const int e = std::min(a->e, b->e);
  const std::optional<std::int64_t> ma = Scaled(a->m, a->e - e), mb = Scaled(b->m, b->e - e);
  std::int64_t p = 0, q = n - 1, wa = 0, wb = 0;
  if (!ma || !mb || __builtin_mul_overflow(*ma, n - 1 - i, &wa) ||
      __builtin_mul_overflow(*mb, i, &wb) || __builtin_add_overflow(wa, wb, &p)) {
    return std::nullopt;
  }
  // p/q 10^e: reduced, q must divide a power of ten 10^k; then p (10^k/q) 10^(e-k).
  std::int64_t x = std::llabs(p), y = q;
  while (y != 0) x = std::exchange(y, x % y);
  if (x > 1) p /= x, q /= x;
  int twos = 0, fives = 0;
  for (; q % 2 == 0; q /= 2) ++twos;
  for (; q % 5 == 0; q /= 5) ++fives;
  if (q != 1) return std::nullopt;
  for (int k = twos; k < fives; ++k) {
    if (__builtin_mul_overflow(p, std::int64_t{2}, &p)) return std::nullopt;
  }
  for (int k = fives; k < twos; ++k) {
    if (__builtin_mul_overflow(p, std::int64_t{5}, &p)) return std::nullopt;
  }
  const std::string text = std::to_string(p) + "e" + std::to_string(e - std::max(twos, fives));
  double value = 0.0;
  const std::from_chars_result r = std::from_chars(text.data(), text.data() + text.size(), value);
  if (r.ec != std::errc()) return std::nullopt;  // beyond the range of a double
  return value;
}

}  // namespace grid_value_internal

/// The i-th of n equally spaced values from lo to hi (n >= 1, 0 <= i < n; n = 1: lo), by the
/// rule at the top of this file. Exactly lo for i = 0 and exactly hi for i = n - 1.
inline double GridValue(double lo, double hi, std::int64_t n, std::int64_t i) {
  if (n <= 1 || i <= 0) return lo;
  if (i >= n - 1) return hi;
  if (const std::optional<double> exact = grid_value_internal::DecimalValue(lo, hi, n, i)) {
    return *exact;
  }
  const double m = static_cast<double>(n - 1), t = static_cast<double>(i);
  // Rounding must not leave [lo, hi] (0.1:0.1:7).
  return std::clamp((lo * (m - t) + hi * t) / m, std::min(lo, hi), std::max(lo, hi));
}

}  // namespace capsubot
