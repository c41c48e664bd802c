// The constraints shared by P1, P2 and P3 (src/optimize/nlopt_constraints.cpp, docs/model.md
// sections 5 and 7): a force touching its bound is within it up to rounding, as validity itself
// says.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "capsubot/orbit/validity.hpp"
#include "optimize/nlopt_constraints.hpp"
#include "optimize/nlopt_problem.hpp"

namespace capsubot {
namespace {

// A valid orbit (T0 = 0.1, dense scan through Solve): c = A = T0/4 at phi0 = 2.5.
const Params kParams{0.1, 1.0};
Forcing ValidForce() { return Forcing::Harmonic(0.025, 0.025, 2.5); }

TEST(ForceBoundConstraint, ForceOneUlpAboveTheBoundIsWithinIt) {
  const Forcing f = ValidForce();
  ASSERT_TRUE(Solve(f, kParams).validity.valid());
  const double max_force = Solve(f, kParams).validity.max_force;
  // The bound one ulp below the force's computed maximum: the same number up to rounding.
  const detail::ConstraintSetup setup{kParams, std::nextafter(max_force, 0.0)};
  const detail::Evaluation ev = detail::Evaluate(f, setup);
  EXPECT_TRUE(ev.valid);
  EXPECT_EQ(ev.violation, 0.0);
  EXPECT_EQ(detail::DescribeViolations(ev, setup), "");
}

TEST(ForceBoundConstraint, ForceClearlyAboveTheBoundViolatesIt) {
  const Forcing f = ValidForce();
  const double max_force = Solve(f, kParams).validity.max_force;
  // 1e-9 relative: a thousand times the rounding allowance kForceBoundRelTol.
  const detail::ConstraintSetup setup{kParams, max_force * (1.0 - 1e-9)};
  const detail::Evaluation ev = detail::Evaluate(f, setup);
  EXPECT_FALSE(ev.valid);
  EXPECT_GT(ev.violation, 0.0);
  EXPECT_NE(detail::DescribeViolations(ev, setup).find("force_bound"), std::string::npos);
}

TEST(ForceBoundConstraint, LinearBoundOfP2OneUlpAboveIsWithinIt) {
  // P2's force bound is linear in its variables, A + c <= bound: y[0] + y[1] <= 1 in units of
  // the bound. One ulp above 1 is the bound up to rounding.
  const double bound = 0.05;
  detail::Problem problem;
  problem.n = 2;
  problem.build = [bound](const double* y) {
    return Forcing::Harmonic(y[0] * bound, y[1] * bound, 2.5);
  };
  problem.setup = {kParams, bound};
  problem.force_total = [bound](const double* y) { return (y[0] + y[1]) * bound; };
  detail::Tracker tracker;
  const double touching[2] = {std::nextafter(0.5, 1.0), std::nextafter(0.5, 1.0)};
  ASSERT_GT(touching[0] + touching[1], 1.0);
  EXPECT_TRUE(detail::EvaluateAt(problem, touching, tracker).valid);
  const double above[2] = {0.5, 0.5 + 1e-9};
  EXPECT_FALSE(detail::EvaluateAt(problem, above, tracker).valid);
}

TEST(PolishPhase, NeverReplacesAValidBestByAnInvalidCandidate) {
  // The final phase polish of P2 and P3 finds a better phase by P1, then re-evaluates it in the
  // problem's own terms (P3: the series seen from the impact). If that re-evaluation is not
  // valid, the valid best point stays.
  detail::Problem problem;
  problem.n = 1;
  problem.build = [](const double* y) { return Forcing::Harmonic(0.025, 0.025, y[0]); };
  problem.setup = {kParams, 0.05};
  detail::Tracker tracker;
  // A valid, deliberately poor best point: the smallest I of a coarse valid phase scan.
  for (int i = 0; i < 72; ++i) {
    const double y = kTau * i / 72;
    const detail::Evaluation ev = detail::Evaluate(problem.build(&y), problem.setup);
    if (ev.valid && (!tracker.best.valid || ev.I < tracker.best.I)) {
      tracker.best = ev;
      tracker.best_y.assign(&y, &y + 1);
    }
  }
  ASSERT_TRUE(tracker.best.valid);
  const double poor_I = tracker.best.I;
  int calls = 0;
  auto invalid = [&](const Forcing& f) {
    ++calls;
    // The candidate judged against a bound it misses by far more than rounding.
    return detail::Evaluate(f, detail::ConstraintSetup{kParams, 0.04});
  };
  const detail::Evaluation kept = detail::PolishPhase(problem, invalid, tracker);
  EXPECT_EQ(calls, 1);
  EXPECT_TRUE(kept.valid);
  EXPECT_EQ(kept.I, poor_I);
  auto same = [&](const Forcing& f) { return detail::Evaluate(f.InImpactFrame(), problem.setup); };
  const detail::Evaluation better = detail::PolishPhase(problem, same, tracker);
  EXPECT_TRUE(better.valid);
  EXPECT_GT(better.I, poor_I);
  EXPECT_EQ(better.solution.orbit.forcing.phi0(), 0.0);
}

}  // namespace
}  // namespace capsubot
