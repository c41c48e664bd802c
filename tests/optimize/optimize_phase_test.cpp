// P1 (OptimizePhase): the best impact phase for a given force shape, docs/model.md section 7.
// References come from an independent dense scan of phi0 through Solve (the `solve` code path).

#include "capsubot/optimize/optimize_phase.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "capsubot/orbit/stability.hpp"
#include "capsubot/orbit/validity.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

constexpr double kPi = kTau / 2.0;
// The dense reference scan: 10 times the optimiser's default scan, so arcs and maxima it
// resolves are found by the optimiser's own scan plus bisection and polish.
constexpr int kDenseScan = 7200;
// The optimiser returns a point at least as good as the best valid scan point; both are
// computed by the same formulas, so only round-off separates equal values.
constexpr double kSameValueTol = 1e-12;
// Two bisections of the same arc edge to phase_tol = 1e-12 rad in differently rounded
// coordinates: I, whose slope in phi0 is O(1), agrees far below this.
constexpr double kBisectedEdgeTol = 1e-9;

struct ScanBest {
  double I = -HUGE_VAL;
  double phi0 = NAN;
  int valid = 0;
};

ScanBest DenseScan(const Forcing& shape, const Params& params, const Margins& margins = {},
                   bool stable = false, double rho_max = 1.0) {
  ScanBest best;
  for (int i = 0; i < kDenseScan; ++i) {
    const double phi0 = -kPi + kTau * i / kDenseScan;
    const Solution s = Solve(shape.WithPhase(phi0), params, margins);
    if (!s.validity.valid()) continue;
    if (stable && !(ComputeStability(s.orbit).spectral_radius <= rho_max)) continue;
    ++best.valid;
    if (s.orbit.I > best.I) {
      best.I = s.orbit.I;
      best.phi0 = phi0;
    }
  }
  return best;
}

struct PhaseCase {
  double A_ratio, c_ratio, T0, e, margin;  // A = A_ratio T0, c = c_ratio T0
  double margin_stroke = 0.0, stick_margin = 0.0;
  Params params() const { return Params{T0, e}; }
  PhaseOptions options() const {
    PhaseOptions o;
    o.gait.margins = Margins{margin, margin_stroke, stick_margin};
    return o;
  }
};

class PhaseOptimum : public ::testing::TestWithParam<PhaseCase> {};

TEST_P(PhaseOptimum, IsAtLeastTheBestValidPointOfADenseScan) {
  const PhaseCase k = GetParam();
  const Params params = k.params();
  const Forcing shape = Forcing::Harmonic(k.A_ratio * k.T0, k.c_ratio * k.T0, 0.0);
  const ScanBest scan = DenseScan(shape, params, k.options().gait.margins);
  ASSERT_GT(scan.valid, 0) << "test case without valid orbits";
  const OptimizeResult r = OptimizePhase(shape, params, k.options());
  ASSERT_EQ(r.status, OptimizeStatus::kOk) << r.message;
  EXPECT_GE(r.solution.orbit.I, scan.I - kSameValueTol * std::abs(scan.I))
      << "scan best at phi0 = " << scan.phi0 << ", optimiser at "
      << r.solution.orbit.forcing.phi0();
}

TEST_P(PhaseOptimum, IsValidWhenRecheckedThroughSolve) {
  const PhaseCase k = GetParam();
  const Params params = k.params();
  const Forcing shape = Forcing::Harmonic(k.A_ratio * k.T0, k.c_ratio * k.T0, 0.0);
  const OptimizeResult r = OptimizePhase(shape, params, k.options());
  ASSERT_TRUE(r.found()) << r.message;
  const double phi0 = r.solution.orbit.forcing.phi0();
  EXPECT_GE(phi0, -kPi);
  EXPECT_LT(phi0, kPi);
  // Rebuild the force from the numbers alone and solve it as `capsubot solve` does.
  const Solution again = Solve(Forcing::Harmonic(shape.amplitude(), shape.mean(), phi0), params,
                               k.options().gait.margins);
  EXPECT_TRUE(again.validity.valid()) << "violations: " << again.validity.violations;
  EXPECT_EQ(again.orbit.I, r.solution.orbit.I);
  EXPECT_GE(again.validity.x_min, k.margin);
}

// Cases: the paper's shape c = A = T0/2 at a T0 where it fits, other ratios, e < 1, a margin.
INSTANTIATE_TEST_SUITE_P(
    Shapes, PhaseOptimum,
    ::testing::Values(PhaseCase{0.5, 0.5, 0.02, 1.0, 0.0}, PhaseCase{0.5, 0.5, 0.1, 1.0, 0.0},
                      PhaseCase{0.3, 0.1, 1.0, 1.0, 0.0}, PhaseCase{0.6, 0.3, 0.05, 1.0, 0.1},
                      PhaseCase{0.2, 0.1, 0.3, 0.7, 0.0}, PhaseCase{0.8, 0.2, 0.01, 0.3, 0.0},
                      // The robust margins of docs/model.md section 12.
                      PhaseCase{0.5, 0.4, 0.05, 1.0, 0.0, 0.02, 0.02},
                      PhaseCase{0.3, 0.1, 0.3, 0.8, 0.01, 0.05, 0.1}));

// The force touching the friction bound, A + c = T0 (the paper's boundary, and a diagonal of
// `capsubot sweep --optimize phi0`): max |F| equals T0 up to the last bit of its evaluation,
// which validity accepts (kForceBoundRelTol), so P1 must find the valid phases `solve` finds.
struct DiagonalCase {
  double A, c, T0;  // A + c = T0 in exact arithmetic
};

class PhaseOnFrictionBoundDiagonal : public ::testing::TestWithParam<DiagonalCase> {};

TEST_P(PhaseOnFrictionBoundDiagonal, FindsTheValidPhasesSolveFinds) {
  const DiagonalCase k = GetParam();
  const Params params{k.T0, 1.0};
  const Forcing shape = Forcing::Harmonic(k.A, k.c, 0.0);
  const ScanBest scan = DenseScan(shape, params);
  ASSERT_GT(scan.valid, 0) << "test case without valid orbits";
  const OptimizeResult r = OptimizePhase(shape, params);
  ASSERT_EQ(r.status, OptimizeStatus::kOk) << r.message;
  EXPECT_GE(r.solution.orbit.I, scan.I - kSameValueTol * std::abs(scan.I));
  const Solution again =
      Solve(Forcing::Harmonic(k.A, k.c, r.solution.orbit.forcing.phi0()), params);
  EXPECT_TRUE(again.validity.valid()) << "violations: " << again.validity.violations;
}

// 0.006 + 0.003 is 0.009 plus one ulp in floating point; the others
// are diagonal points of a sweep over (A, c) at T0 = 0.1 and 0.05.
INSTANTIATE_TEST_SUITE_P(Shapes, PhaseOnFrictionBoundDiagonal,
                         ::testing::Values(DiagonalCase{0.006, 0.003, 0.009},
                                           DiagonalCase{0.07, 0.03, 0.1},
                                           DiagonalCase{0.05, 0.05, 0.1},
                                           DiagonalCase{0.03, 0.02, 0.05}));

TEST(OptimizePhase, PaperExampleAtT0OneHasNoValidOrbitAndSaysWhy) {
  // docs/model.md section 6: c = A = T0/2 violates the left-wall condition at T0 = 1.
  const Params params{1.0, 1.0};
  const OptimizeResult r = OptimizePhase(Forcing::Harmonic(0.5, 0.5, 0.0), params);
  EXPECT_EQ(r.status, OptimizeStatus::kNoValidOrbit);
  EXPECT_STREQ(OptimizeStatusName(r.status), "no_valid_orbit");
  EXPECT_FALSE(r.found());
  EXPECT_TRUE(r.solution.validity.violated(Condition::kLeftWall));
  EXPECT_LT(r.solution.validity.x_min, 0.0);
  EXPECT_NE(r.message.find("left_wall"), std::string::npos) << r.message;
  EXPECT_EQ(DenseScan(Forcing::Harmonic(0.5, 0.5, 0.0), params).valid, 0);
}

TEST(OptimizePhase, EdgeOptimumReportsTheGrazedWallAsActive) {
  // At T0 = 0.1 the optimum of c = A = T0/2 grazes the left wall (x_min = 0 within the
  // bisection tolerance); the dense scan's best point lies next to an invalid one.
  const Params params{0.1, 1.0};
  const OptimizeResult r = OptimizePhase(Forcing::Harmonic(0.05, 0.05, 0.0), params);
  ASSERT_TRUE(r.found()) << r.message;
  EXPECT_NEAR(r.solution.validity.x_min, 0.0, 1e-9);
  EXPECT_NE(std::find(r.active_constraints.begin(), r.active_constraints.end(), "left_wall"),
            r.active_constraints.end());
}

TEST(OptimizePhase, EdgeOptimumAcrossMinusPiIsReportedExactlyAsEvaluated) {
  // The edge optimum of c = A = T0/2 at T0 = 0.1 (left wall grazed), with the shape turned so
  // that the edge lies just outside [-pi, pi) as the scan sees it (the bisection from scan
  // point 0 or 719 crosses -pi or pi): the optimum is the same, and its reported phi0 in
  // [-pi, pi) is where it was evaluated, so Solve at that phase gives the very same orbit.
  const Params params{0.1, 1.0};
  const OptimizeResult upright = OptimizePhase(Forcing::Harmonic(0.05, 0.05, 0.0), params);
  ASSERT_TRUE(upright.found()) << upright.message;
  const double star = upright.solution.orbit.forcing.phi0();
  const double h = kTau / PhaseOptions{}.scan_points;
  for (double edge : {-kPi - 0.3 * h, -kPi + 0.3 * h, kPi - 0.3 * h}) {
    // A sin(s + d) + c: the optimum moves from phi0 = star to phi0 = star - d = edge.
    const double d = star - edge;
    const Forcing shape = Forcing::Fourier(0.05, {0.05 * std::sin(d)}, {0.05 * std::cos(d)}, 0.0);
    const OptimizeResult r = OptimizePhase(shape, params);
    ASSERT_EQ(r.status, OptimizeStatus::kOk) << "edge " << edge << ": " << r.message;
    EXPECT_TRUE(
        testing::NearAbsBelowOne(r.solution.orbit.I, upright.solution.orbit.I, kBisectedEdgeTol));
    const double phi0 = r.solution.orbit.forcing.phi0();
    EXPECT_GE(phi0, -kPi);
    EXPECT_LT(phi0, kPi);
    const Solution again = Solve(shape.WithPhase(phi0), params);
    EXPECT_TRUE(again.validity.valid()) << "violations: " << again.validity.violations;
    EXPECT_EQ(again.orbit.I, r.solution.orbit.I);
    EXPECT_EQ(again.validity.x_min, r.solution.validity.x_min);
  }
}

TEST(OptimizePhase, FindsAValidArcNarrowerThanItsScanSpacing) {
  // c = A = T0/2 at T0 = 0.108: the only valid arc is about 0.12 rad wide (dense scan), far
  // narrower than the 0.39 rad spacing of a 16-point scan, which sees no valid point; the
  // search from the local minima of the violation finds it.
  const Params params{0.108, 1.0};
  const Forcing shape = Forcing::Harmonic(0.054, 0.054, 0.0);
  const ScanBest scan = DenseScan(shape, params);
  ASSERT_GT(scan.valid, 0);
  ASSERT_LT(scan.valid, kDenseScan / 40);  // narrower than tau/40 = 0.157 rad
  PhaseOptions coarse;
  coarse.scan_points = 16;
  const OptimizeResult r = OptimizePhase(shape, params, coarse);
  ASSERT_EQ(r.status, OptimizeStatus::kOk) << r.message;
  EXPECT_GE(r.solution.orbit.I, scan.I - kSameValueTol * std::abs(scan.I));
}

TEST(OptimizePhase, StableOptimumIsStableAndBeatsTheStableDenseScan) {
  // At T0 = 0.3 this shape has stable and unstable valid phases (a scan finds both).
  const Params params{0.3, 1.0};
  const Forcing shape = Forcing::Harmonic(0.09, 0.03, 0.0);
  PhaseOptions options;
  options.gait.rho_max = 1.0;
  const ScanBest scan = DenseScan(shape, params, {}, true, 1.0);
  const OptimizeResult r = OptimizePhase(shape, params, options);
  ASSERT_GT(scan.valid, 0) << "test case without stable valid orbits";
  ASSERT_TRUE(r.found()) << r.message;
  EXPECT_LE(r.spectral_radius, 1.0);
  EXPECT_LE(ComputeStability(r.solution.orbit).spectral_radius, 1.0);
  EXPECT_GE(r.solution.orbit.I, scan.I - kSameValueTol * std::abs(scan.I));
  const OptimizeResult any = OptimizePhase(shape, params);
  EXPECT_LE(r.solution.orbit.I, any.solution.orbit.I);
}

TEST(OptimizePhase, BadOptionsAreRejectedWithTheRule) {
  const Forcing shape = Forcing::Harmonic(0.3, 0.1, 0.0);
  PhaseOptions few;
  few.scan_points = 3;
  try {
    OptimizePhase(shape, Params{}, few);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "scan_points = 3 is invalid: expected 16 <= scan_points <= 1000000");
  }
  PhaseOptions rho;
  rho.gait.rho_max = 0.0;
  try {
    OptimizePhase(shape, Params{}, rho);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()),
              "rho_max = 0 is invalid: expected rho_max > 0 (infinity: no stability "
              "requirement)");
  }
  PhaseOptions wide;
  wide.gait.margins.clearance = 0.5;
  try {
    OptimizePhase(shape, Params{}, wide);
    FAIL() << "expected std::invalid_argument";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()), "margin d = 0.5 is invalid: expected 0 <= d < 0.5");
  }
}

TEST(OptimizeStatusName, NamesEveryStatus) {
  EXPECT_STREQ(OptimizeStatusName(OptimizeStatus::kNotRun), "not_run");
  EXPECT_STREQ(OptimizeStatusName(OptimizeStatus::kOk), "ok");
  EXPECT_STREQ(OptimizeStatusName(OptimizeStatus::kMaxEvaluations), "max_evaluations");
  EXPECT_STREQ(OptimizeStatusName(OptimizeStatus::kRoundoffLimited), "roundoff_limited");
  EXPECT_STREQ(OptimizeStatusName(OptimizeStatus::kForcedStop), "forced_stop");
  EXPECT_STREQ(OptimizeStatusName(OptimizeStatus::kFailure), "failure");
}

}  // namespace
}  // namespace capsubot
