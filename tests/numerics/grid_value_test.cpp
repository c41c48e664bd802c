// GridValue: the ends are exactly lo and hi; a value that is a terminating decimal of decimal
// bounds is that decimal (computed here in integer arithmetic and read by strtod, the
// correctly rounded reading); other values are the weighted mean, inside [lo, hi], in order.

#include "capsubot/numerics/grid_value.hpp"

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

namespace capsubot {
namespace {

TEST(GridValue, MidpointOfDecimalBoundsIsTheDecimal) {
  // (-2.8 - 2.4)/2 in doubles is -2.5999999999999996.
  EXPECT_EQ(GridValue(-2.8, -2.4, 3, 1), -2.6);
  EXPECT_EQ(GridValue(0.1, 0.5, 5, 2), 0.3);  // 0.1 + 0.4 * 2/4 is 0.30000000000000004
  EXPECT_EQ(GridValue(0.05, 0.95, 19, 1), 0.1);
}

TEST(GridValue, EndsAreExactlyTheBounds) {
  for (const double lo : {-2.8, 0.1, M_PI, 1e-300, -7.0}) {
    for (const double hi : {-2.4, 0.7, 2 * M_PI, 1e300, 3.0}) {
      for (const std::int64_t n : {2, 3, 7, 1000000000}) {
        EXPECT_EQ(GridValue(lo, hi, n, 0), lo);
        EXPECT_EQ(GridValue(lo, hi, n, n - 1), hi);
      }
    }
  }
  EXPECT_EQ(GridValue(0.3, 0.9, 1, 0), 0.3);
}

// Every grid lo = L/1000 : hi = H/1000 : n with n - 1 dividing 10^4: its values are the
// decimals (L (n-1-i) + H i) 10^4/(n-1) x 10^-7, read by strtod.
TEST(GridValue, EveryTerminatingDecimalIsExact) {
  int checked = 0;
  for (std::int64_t L = -3000; L <= 3000; L += 737) {
    for (std::int64_t H = -2900; H <= 3100; H += 611) {
      for (const std::int64_t steps : {1, 2, 4, 5, 8, 10, 16, 25}) {
        for (std::int64_t i = 0; i <= steps; ++i) {
          const std::int64_t digits = (L * (steps - i) + H * i) * 10000 / steps;
          const double expected = std::strtod(fmt::format("{}e-7", digits).c_str(), nullptr);
          const double lo = std::strtod(fmt::format("{}e-3", L).c_str(), nullptr);
          const double hi = std::strtod(fmt::format("{}e-3", H).c_str(), nullptr);
          ASSERT_EQ(GridValue(lo, hi, steps + 1, i), expected)
              << lo << ":" << hi << ":" << steps + 1 << " i = " << i;
          ++checked;
        }
      }
    }
  }
  EXPECT_GT(checked, 1000);
}

TEST(GridValue, ANonTerminatingValueIsTheCorrectlyRoundedMean) {
  EXPECT_EQ(GridValue(0.0, 1.0, 4, 1), 1.0 / 3.0);
  EXPECT_EQ(GridValue(0.0, 1.0, 4, 2), 2.0 / 3.0);
  // Bounds of 16 or 17 digits (pi) are not decimals as written: the weighted mean.
  EXPECT_EQ(GridValue(0.0, 2 * M_PI, 9, 3), 2 * M_PI * 3 / 8);
  EXPECT_EQ(GridValue(-M_PI, M_PI, 3, 1), 0.0);
}

TEST(GridValue, ValuesIncreaseInsideTheBounds) {
  for (const auto& [lo, hi] : {std::pair{0.1, 0.1}, std::pair{-M_PI, M_PI}, std::pair{1e-300, 3.0},
                               std::pair{0.123456789012345, 0.9}}) {
    double previous = lo;
    for (std::int64_t i = 1; i < 97; ++i) {
      const double value = GridValue(lo, hi, 97, i);
      EXPECT_GE(value, previous) << lo << ":" << hi << " i = " << i;
      EXPECT_LE(value, hi);
      previous = value;
    }
  }
}

TEST(GridValue, CellCentresOfTheStartGridAreTheRationals) {
  // (i + 1/2)/n_x: both operands exact, so the quotient is the correctly rounded rational.
  for (const int n : {1, 3, 8, 10, 12}) {
    for (int i = 0; i < n; ++i) EXPECT_EQ(GridValue(0.0, 1.0, 2 * n + 1, 2 * i + 1), (i + 0.5) / n);
  }
}

}  // namespace
}  // namespace capsubot
