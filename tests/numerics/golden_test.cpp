// GoldenRefine: smooth maxima, maxima at a cliff (the edge of a feasible set), at an end of the
// bracket, and a narrow island; closed-form answers.

#include "capsubot/numerics/golden.hpp"

#include <gtest/gtest.h>

#include <cmath>

#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::Near;

constexpr double kTol = 1e-10;  // bracket width asked of the refinement
// A smooth maximum is flat: f(x*) - f(x) ~ (x - x*)^2, so x is only known to ~sqrt(eps).
constexpr double kSmoothArgTol = 1e-7;

// The refinement from the point b of the bracket [a, c].
template <class Fn>
detail::ScanMax Refine(const Fn& f, double a, double b, double c) {
  detail::ScanMax best;
  best.x = b;
  const double fb = f(b);
  best.f = std::isnan(fb) ? -HUGE_VAL : fb;
  return detail::GoldenRefine(f, a, c, kTol, best);
}

TEST(GoldenRefine, FindsASmoothInteriorMaximum) {
  const auto f = [](double x) { return -(x - 0.3141) * (x - 0.3141); };
  const detail::ScanMax r = Refine(f, -1.0, 0.2, 2.0);
  EXPECT_TRUE(Near(r.x, 0.3141, kSmoothArgTol));
  EXPECT_LE(r.evaluations, detail::kGoldenMaxSteps);
}

TEST(GoldenRefine, ConvergesToTheEdgeOfACliff) {
  // Increasing up to x = 0.7071, undefined beyond: the supremum is at the edge.
  const auto f = [](double x) { return x <= 0.7071 ? x : std::nan(""); };
  const detail::ScanMax r = Refine(f, 0.5, 0.6, 0.8);
  EXPECT_LE(r.x, 0.7071);
  EXPECT_TRUE(Near(r.x, 0.7071, 2.0 * kTol));
}

TEST(GoldenRefine, KeepsAMaximumAtAnEndOfTheBracket) {
  const auto f = [](double x) { return -x; };
  const detail::ScanMax r = Refine(f, 2.0, 2.0, 3.0);
  EXPECT_EQ(r.x, 2.0);  // exactly the end
}

TEST(GoldenRefine, FindsTheEdgeOfANarrowIsland) {
  // Defined only on [0.48, 0.52], the bracket's middle 0.5 inside; maximum at 0.52.
  const auto f = [](double x) { return std::abs(x - 0.5) <= 0.02 ? x : std::nan(""); };
  const detail::ScanMax r = Refine(f, 0.4, 0.5, 0.6);
  EXPECT_TRUE(Near(r.x, 0.52, 2.0 * kTol));
}

}  // namespace
}  // namespace capsubot
