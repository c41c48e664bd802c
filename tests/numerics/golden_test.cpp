// ScanGoldenMaximize: smooth maxima, maxima at a cliff (the edge of a feasible set), at an end
// of the range, and no value at all; closed-form answers.

#include "numerics/golden.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::Near;

constexpr double kTol = 1e-10;  // bracket width asked of the refinement
// A smooth maximum is flat: f(x*) - f(x) ~ (x - x*)^2, so x is only known to ~sqrt(eps).
constexpr double kSmoothArgTol = 1e-7;

TEST(ScanGoldenMaximize, FindsASmoothInteriorMaximum) {
  const auto f = [](double x) { return -(x - 0.3141) * (x - 0.3141); };
  const detail::ScanMax r = detail::ScanGoldenMaximize(f, -1.0, 2.0, 16, kTol);
  EXPECT_TRUE(Near(r.x, 0.3141, kSmoothArgTol));
  EXPECT_LE(r.evaluations, 16 + detail::kGoldenMaxSteps);
}

TEST(ScanGoldenMaximize, ConvergesToTheEdgeOfACliff) {
  // Increasing up to x = 0.7071, undefined beyond: the supremum is at the edge.
  const auto f = [](double x) { return x <= 0.7071 ? x : std::nan(""); };
  const detail::ScanMax r = detail::ScanGoldenMaximize(f, 0.0, 1.0, 10, kTol);
  EXPECT_LE(r.x, 0.7071);
  EXPECT_TRUE(Near(r.x, 0.7071, 2.0 * kTol));
}

TEST(ScanGoldenMaximize, KeepsAMaximumAtAnEndOfTheRange) {
  const auto f = [](double x) { return -x; };
  const detail::ScanMax r = detail::ScanGoldenMaximize(f, 2.0, 5.0, 7, kTol);
  EXPECT_EQ(r.x, 2.0);  // exactly the end
  EXPECT_EQ(r.index, 0);
}

TEST(ScanGoldenMaximize, FindsANarrowIslandBetweenSamples) {
  // Defined only on [0.48, 0.52], where the scan has one sample (0.5); maximum at 0.52.
  const auto f = [](double x) { return std::abs(x - 0.5) <= 0.02 ? x : std::nan(""); };
  const detail::ScanMax r = detail::ScanGoldenMaximize(f, 0.0, 1.0, 11, kTol);
  EXPECT_TRUE(Near(r.x, 0.52, 2.0 * kTol));
}

TEST(ScanGoldenMaximize, ReportsNothingWhenTheFunctionIsNowhereDefined) {
  int calls = 0;
  const auto f = [&calls](double) {
    ++calls;
    return std::nan("");
  };
  const detail::ScanMax r = detail::ScanGoldenMaximize(f, 0.0, 1.0, 5, kTol);
  EXPECT_EQ(r.index, -1);
  EXPECT_TRUE(std::isnan(r.x));
  EXPECT_EQ(calls, 5);  // the scan only: nothing to refine
}

}  // namespace
}  // namespace capsubot
