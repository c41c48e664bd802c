// MaximiseOverWindows: windows far narrower than the scan's spacing, found beside an infeasible
// local maximum of the measure and next to a fold where the branches end; the budget and the
// halt; closed-form answers.

#include "capsubot/numerics/windows.hpp"

#include <gtest/gtest.h>

#include <cmath>

namespace capsubot {
namespace {

constexpr double kTol = 1e-10;  // bracket width asked of the refinement in a window
constexpr double kNone = -INFINITY;

detail::WindowOptions Options(int n) {
  detail::WindowOptions o;
  o.scan_points = n;
  o.resolution = 1e-6;
  o.fold_resolution = 1e-3;
  o.max_refinements = 8 * n;
  o.tol = kTol;
  return o;
}

detail::Probe At(double slack, int branches, double value) {
  detail::Probe p;
  p.feasible = slack >= 0.0;
  p.slack = slack;
  p.branches = branches;
  p.value = p.feasible ? value : NAN;
  return p;
}

const auto kNever = [] { return false; };

TEST(MaximiseOverWindows, FindsANarrowWindowBesideAnInfeasibleLocalMaximum) {
  // Feasible on [0.6 - 0.00316, 0.6 + 0.00316] only; the scan's samples are 0.25 apart.
  const auto probe = [](double x) { return At(1e-5 - (x - 0.6) * (x - 0.6), 2, x); };
  const detail::WindowSearch r = detail::MaximiseOverWindows(probe, kNever, 0.0, 1.0, Options(5));
  ASSERT_EQ(r.windows.size(), 1u);
  EXPECT_NEAR(r.best.x, 0.6 + std::sqrt(1e-5), 2.0 * kTol);  // the objective's cliff
  EXPECT_FALSE(r.exhausted);
  EXPECT_LE(r.evaluations, 5 + 8 * 5 + detail::kGoldenMaxSteps);
}

TEST(MaximiseOverWindows, FindsAWindowThatEndsAtAFold) {
  // Two branches below x = 0.7071, none above; feasible on (0.705, 0.7071) only, and the
  // measure falls toward the fold at every sample: only the fold's bisection finds the window.
  const auto probe = [](double x) {
    if (x >= 0.7071) return At(kNone, 0, NAN);
    return At(x > 0.705 ? x - 0.705 : -0.1 - x, 2, -x);
  };
  const detail::WindowSearch r = detail::MaximiseOverWindows(probe, kNever, 0.0, 1.0, Options(5));
  ASSERT_EQ(r.windows.size(), 1u);
  EXPECT_NEAR(r.best.x, 0.705, 2.0 * kTol);
  // Without the bracketing budget the scan alone misses it, and says so.
  detail::WindowOptions none = Options(5);
  none.max_refinements = 0;
  const detail::WindowSearch scan = detail::MaximiseOverWindows(probe, kNever, 0.0, 1.0, none);
  EXPECT_TRUE(scan.windows.empty());
  EXPECT_TRUE(scan.exhausted);
  EXPECT_EQ(scan.evaluations, 5);
}

TEST(MaximiseOverWindows, KeepsTheBestOfSeveralWindows) {
  // Feasible on [0.1, 0.3] (objective up to 0.3) and on a narrow [0.8, 0.8005] (up to 1.8005).
  const auto probe = [](double x) {
    const double slack = std::max(std::min(x - 0.1, 0.3 - x), std::min(x - 0.8, 0.8005 - x));
    return At(slack, 1, x < 0.5 ? x : 1.0 + x);
  };
  const detail::WindowSearch r = detail::MaximiseOverWindows(probe, kNever, 0.0, 1.0, Options(9));
  ASSERT_EQ(r.windows.size(), 2u);
  EXPECT_NEAR(r.best.f, 1.8005, 2.0 * kTol);
}

TEST(MaximiseOverWindows, StopsWhenHalted) {
  int calls = 0;
  const auto probe = [&calls](double x) {
    ++calls;
    return At(-1.0 - (x - 0.5) * (x - 0.5), 1, x);
  };
  const detail::WindowSearch r = detail::MaximiseOverWindows(
      probe, [&calls] { return calls >= 7; }, 0.0, 1.0, Options(5));
  EXPECT_TRUE(r.halted);
  EXPECT_EQ(calls, 7);
  EXPECT_EQ(r.evaluations, 7);
}

}  // namespace
}  // namespace capsubot
