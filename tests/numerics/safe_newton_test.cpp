// The private root finder: the bracketed (safeguarded) Newton iteration.

#include "capsubot/numerics/safe_newton.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <utility>

#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::Near;

constexpr double kTol = 1e-13;  // the iteration stops at 1e-14 in x

TEST(SafeNewton, FindsTheRootWithEitherSignOrder) {
  const auto f = [](double x) { return std::exp(x) - 2.0; };
  const auto df = [](double x) { return std::exp(x); };
  EXPECT_TRUE(Near(detail::SafeNewton(f, df, 0.0, 3.0), std::log(2.0), kTol));
  const auto g = [](double x) { return 2.0 - std::exp(x); };
  const auto dg = [](double x) { return -std::exp(x); };
  EXPECT_TRUE(Near(detail::SafeNewton(g, dg, 0.0, 3.0), std::log(2.0), kTol));
}

TEST(SafeNewton, StaysInTheBracketWhenNewtonWouldLeaveIt) {
  // atan: Newton diverges from far away; the bracket keeps the iteration safe.
  const auto f = [](double x) { return std::atan(x - 1.0); };
  const auto df = [](double x) { return 1.0 / (1.0 + (x - 1.0) * (x - 1.0)); };
  EXPECT_TRUE(Near(detail::SafeNewton(f, df, -20.0, 30.0), 1.0, kTol));
}

TEST(SafeNewtonBracket, FindsTheRootFromEitherStartWithTheEndValuesGiven) {
  // f and f' from one call; the ends' values come from the caller (here computed once).
  const auto f = [](double x) { return std::exp(x) - 2.0; };
  const auto fdf = [](double x) {
    return std::pair<double, double>(std::exp(x) - 2.0, std::exp(x));
  };
  int checked = 0;
  for (const detail::NewtonStart start :
       {detail::NewtonStart::kMidpoint, detail::NewtonStart::kFalsePosition}) {
    EXPECT_TRUE(
        Near(detail::SafeNewtonBracket(fdf, 0.0, 3.0, f(0.0), f(3.0), start), std::log(2.0), kTol));
    EXPECT_TRUE(
        Near(detail::SafeNewtonBracket(fdf, 3.0, 0.0, f(3.0), f(0.0), start), std::log(2.0), kTol));
    ++checked;
  }
  EXPECT_EQ(checked, 2);
}

TEST(SafeNewtonBracket, FalsePositionStartStaysSafeOnAFlatEnd) {
  // atan far from its root: the chord's zero lies near the far end, where Newton overshoots;
  // the bracket and bisection keep the iteration on the root.
  const auto fdf = [](double x) {
    return std::pair<double, double>(std::atan(x - 1.0), 1.0 / (1.0 + (x - 1.0) * (x - 1.0)));
  };
  const double lo = -20.0, hi = 300.0;
  EXPECT_TRUE(Near(detail::SafeNewtonBracket(fdf, lo, hi, std::atan(lo - 1.0), std::atan(hi - 1.0),
                                             detail::NewtonStart::kFalsePosition),
                   1.0, kTol));
}

TEST(SafeNewtonBracket, ReturnsAnEndWhoseValueIsZero) {
  const auto fdf = [](double x) { return std::pair<double, double>(x - 1.0, 1.0); };
  EXPECT_EQ(detail::SafeNewtonBracket(fdf, 1.0, 4.0, 0.0, 3.0, detail::NewtonStart::kFalsePosition),
            1.0);
  EXPECT_EQ(detail::SafeNewtonBracket(fdf, -2.0, 1.0, -3.0, 0.0), 1.0);
}

}  // namespace
}  // namespace capsubot
