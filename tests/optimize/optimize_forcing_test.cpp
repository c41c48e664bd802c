// P2 (OptimizeForcing): the fastest harmonic force A sin(phi + phi0) + c, docs/model.md section 7.
// References: random valid samples and re-checks through Solve (the `solve` code path), the
// scaling law of docs/model.md section 6, and the event-driven simulator.

#include "capsubot/optimize/optimize_forcing.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <new>
#include <random>
#include <stdexcept>
#include <string>

#include "capsubot/optimize/detail/nlopt_status.hpp"
#include "capsubot/orbit/stability.hpp"
#include "capsubot/orbit/validity.hpp"
#include "capsubot/simulate/simulator.hpp"
#include "optimize_test_utils.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

constexpr double kPi = kTau / 2.0;
constexpr int kRandomValidSamples = 10000;
constexpr int kMaxRandomDraws = 5000000;  // bounded: the test fails if valid samples are rare
// Same formulas on both sides: only round-off separates equal values.
constexpr double kSameValueTol = 1e-12;
// The scaling law is exact in the model; the orbit is recomputed through root finders
// (phi1, the extrema of x) converged to ~1e-14 in phase.
constexpr double kScalingTol = 1e-10;
// Different NLopt local algorithms must agree on the optimum to the accuracy P2 promises.
constexpr double kAlgorithmAgreementTol = 1e-6;

bool Has(const std::vector<std::string>& names, const std::string& name) {
  return std::find(names.begin(), names.end(), name) != names.end();
}

struct DesignCase {
  double T0, e, margin, bound_ratio;  // bound = bound_ratio * T0
  bool stable;
};

std::ostream& operator<<(std::ostream& os, const DesignCase& k) {
  return os << "T0=" << k.T0 << " e=" << k.e << " margin=" << k.margin << " bound=" << k.bound_ratio
            << "*T0 stable=" << k.stable;
}

ForcingDesignOptions OptionsFor(const DesignCase& k) {
  ForcingDesignOptions o;
  o.gait.force_bound = k.bound_ratio * k.T0;
  o.gait.margins.clearance = k.margin;
  if (k.stable) o.gait.rho_max = 1.0;
  return o;
}

class ForcingOptimum : public ::testing::TestWithParam<DesignCase> {};

TEST_P(ForcingOptimum, BeatsTenThousandRandomValidSamples) {
  const DesignCase k = GetParam();
  const Params params{k.T0, k.e};
  const double bound = k.bound_ratio * k.T0;
  const OptimizeResult r = OptimizeForcing(params, OptionsFor(k));
  ASSERT_TRUE(r.found()) << r.message;
  // Total force A + c log-uniform in [1e-3, 1] * bound (orbit sizes scale with the force, so
  // valid samples are rare at large forces), share of c uniform, phase uniform.
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int valid = 0, draws = 0;
  double best = -HUGE_VAL;
  while (valid < kRandomValidSamples && draws < kMaxRandomDraws) {
    ++draws;
    const double s = bound * std::pow(1e-3, unit(rng)), share = unit(rng);
    const Solution sol =
        Solve(Forcing::Harmonic(s * (1.0 - share), s * share, -kPi + kTau * unit(rng)), params,
              Margins{k.margin});
    if (!sol.validity.valid()) continue;
    if (k.stable && !(ComputeStability(sol.orbit).spectral_radius <= 1.0)) continue;
    ++valid;
    best = std::max(best, sol.orbit.I);
  }
  ASSERT_EQ(valid, kRandomValidSamples) << "valid samples too rare: " << draws << " draws";
  EXPECT_GE(r.solution.orbit.I, best) << "best random sample " << best;
}

TEST_P(ForcingOptimum, SatisfiesEveryConstraintWhenRecheckedThroughSolve) {
  const DesignCase k = GetParam();
  const Params params{k.T0, k.e};
  const double bound = k.bound_ratio * k.T0;
  const OptimizeResult r = OptimizeForcing(params, OptionsFor(k));
  ASSERT_TRUE(r.found()) << r.message;
  const Forcing& f = r.solution.orbit.forcing;
  const double A = f.amplitude(), c = f.mean(), phi0 = f.phi0();
  EXPECT_GE(phi0, -kPi);
  EXPECT_LT(phi0, kPi);
  // Rebuilt from the three numbers alone, as `capsubot solve --A --c --phi0` would.
  const Solution s = Solve(Forcing::Harmonic(A, c, phi0), params, Margins{k.margin});
  EXPECT_TRUE(s.validity.valid()) << "violations: " << s.validity.violations;
  EXPECT_LE(A + c, bound * (1.0 + kSameValueTol));
  EXPECT_GT(c, 0.0);
  EXPECT_GE(s.validity.x_min, k.margin);
  if (!std::isnan(s.validity.x_max)) {
    EXPECT_LE(s.validity.x_max, 1.0 - k.margin);
  }
  EXPECT_GT(s.orbit.alpha, 0.0);
  EXPECT_LT(s.orbit.alpha, 1.0);
  // At rest |F| <= T0 up to the same rounding as A + c <= bound (the largest force is c + R).
  EXPECT_LE(s.validity.rest_force, k.T0 * (1.0 + kSameValueTol));
  EXPECT_EQ(s.orbit.I, r.solution.orbit.I);
  if (k.stable) {
    EXPECT_LE(ComputeStability(s.orbit).spectral_radius, 1.0);
  }
  // The geometric conditions bind (docs/model.md section 7): at least one wall is active, or
  // with a clearance margin the clearance from a wall.
  EXPECT_TRUE(Has(r.active_constraints, "left_wall") || Has(r.active_constraints, "right_wall") ||
              (k.margin > 0.0 && Has(r.active_constraints, "clearance")))
      << r.message;
}

INSTANTIATE_TEST_SUITE_P(Designs, ForcingOptimum,
                         ::testing::Values(DesignCase{1.0, 1.0, 0.0, 1.0, false},
                                           DesignCase{1.0, 1.0, 0.0, 1.0, true},
                                           DesignCase{0.1, 1.0, 0.0, 1.0, false},
                                           DesignCase{0.3, 0.6, 0.05, 0.8, false},
                                           // Rugged: the clearance condition jumps.
                                           DesignCase{1.0, 0.2, 0.1, 1.0, false}));

TEST(OptimizeForcing, RobustOptimumHoldsEveryMarginAndNamesTheOnesThatBind) {
  // The command's robust defaults (docs/model.md section 12), re-checked through Solve with
  // the same margins and through the stability of the orbit.
  const Params params{1.0, 1.0};
  ForcingDesignOptions o;
  o.gait.rho_max = 0.9;
  o.gait.margins = Margins{0.0, 0.02, 0.02};
  const OptimizeResult r = OptimizeForcing(params, o);
  ASSERT_EQ(r.status, OptimizeStatus::kOk) << r.message;
  const Solution s = Solve(r.solution.orbit.forcing, params, o.gait.margins);
  ASSERT_TRUE(s.validity.valid()) << s.validity.violations;
  const double rho = ComputeStability(s.orbit).spectral_radius;
  EXPECT_LE(rho, o.gait.rho_max);
  const double clearance = 0.02 * s.validity.stroke;
  EXPECT_GE(s.validity.x_min, clearance);
  // Each margin reported as binding is reached within the reporting tolerance.
  int binding = 0;
  for (Margin m : r.binding) {
    if (m == Margin::kRhoMax) {
      EXPECT_NEAR(rho, o.gait.rho_max, o.active_tol);
    } else if (m == Margin::kClearanceStroke) {
      EXPECT_NEAR(s.validity.x_min, clearance, o.active_tol);
    }
    ++binding;
  }
  EXPECT_EQ(binding, 2) << r.message;
  // Robustness costs speed: the exact stable optimum (no margins, rho <= 1) is faster.
  ForcingDesignOptions stable;
  stable.gait.rho_max = 1.0;
  EXPECT_LT(r.solution.orbit.I, OptimizeForcing(Params{}, stable).solution.orbit.I);
}

TEST(OptimizeForcing, BelowTheReferenceT0TheOptimumIsTheScaledReferenceOptimum) {
  // docs/model.md section 6: A, c, T0 -> k A, k c, k T0 keeps every condition of the robust
  // problem but the left wall, which only relaxes: the robust optimum at T0 = 1e-7 is the one
  // at 1e-3 scaled by 1e-4 (the left wall does not bind there).
  const Params reference{1e-3, 1.0}, tiny{1e-7, 1.0};
  ForcingDesignOptions o;
  o.gait.rho_max = 0.9;
  o.gait.margins = Margins{0.0, 0.02, 0.02};
  const OptimizeResult at_reference = OptimizeForcing(reference, o);
  const OptimizeResult at_tiny = OptimizeForcing(tiny, o);
  ASSERT_EQ(at_tiny.status, OptimizeStatus::kOk) << at_tiny.message;
  EXPECT_TRUE(testing::NearAbsBelowOne(at_tiny.solution.orbit.I,
                                       1e-4 * at_reference.solution.orbit.I, kScalingTol));
  EXPECT_TRUE(
      testing::Near(at_tiny.solution.orbit.alpha, at_reference.solution.orbit.alpha, kScalingTol));
  EXPECT_TRUE(Solve(at_tiny.solution.orbit.forcing, tiny, o.gait.margins).validity.valid());
}

TEST(OptimizeForcing, ATinyRestitutionGivesTheAnswerOfASmallOne) {
  // The robust problem of `capsubot optimize --problem forcing` at e = 1e-300 (once NaN steps
  // of COBYLA, thrown as "A = -nan": the separation constraint -e u was below what its
  // arithmetic resolves) down to e = 1e-20 answers as at e = 1e-6: at T0 = 1 no valid
  // one-impact gait is left as e -> 0 (the valid ones need e of about 0.01 there), and the
  // nearest point breaks the same conditions.
  ForcingDesignOptions o;
  o.gait.rho_max = 0.9;
  o.gait.margins = Margins{0.0, 0.02, 0.02};
  const OptimizeResult small = OptimizeForcing(Params{1.0, 1e-6}, o);
  ASSERT_EQ(small.status, OptimizeStatus::kNoValidOrbit) << small.message;
  ASSERT_NE(small.solution.validity.violations, 0U);
  for (const double e : {1e-300, 1e-200, 1e-20}) {
    const Params params{1.0, e};
    const OptimizeResult tiny = OptimizeForcing(params, o);
    EXPECT_EQ(tiny.status, small.status) << "e = " << e << ": " << tiny.message;
    const Forcing& f = tiny.solution.orbit.forcing;
    EXPECT_TRUE(std::isfinite(f.amplitude()) && std::isfinite(f.mean())) << "e = " << e;
    EXPECT_EQ(Solve(f, params, o.gait.margins).validity.violations,
              small.solution.validity.violations)
        << "e = " << e << ": " << tiny.message;
  }
}

TEST(OptimizeForcing, OptimumScalesWithT0AsOnlyTheLeftWallDependsOnScale) {
  // docs/model.md section 6: A, c, T0 -> k A, k c, k T0 keeps phi1, alpha and the right-wall,
  // stick and mass-ratio conditions (they depend on 1 - x only through its sign), scales I
  // and 1 - x by k. Only x >= 0, i.e. k (1 - x) <= 1, depends on k.
  const double T0 = 1.0, k = 0.5;
  const Params big{T0, 1.0}, small{k * T0, 1.0};
  const OptimizeResult at_big = OptimizeForcing(big);
  const OptimizeResult at_small = OptimizeForcing(small);
  ASSERT_TRUE(at_big.found() && at_small.found());
  const Forcing& f = at_big.solution.orbit.forcing;
  const Validity& v = at_big.solution.validity;

  // The optimum at T0 scaled to k T0: same phi1 and alpha, I and 1 - x scaled by k, and valid
  // (the left wall moves away: 1 - k (1 - x_min) > 0).
  const Solution down = Solve(Forcing::Harmonic(k * f.amplitude(), k * f.mean(), f.phi0()), small);
  EXPECT_TRUE(testing::Near(down.orbit.phi1, at_big.solution.orbit.phi1, kScalingTol));
  EXPECT_TRUE(testing::Near(down.orbit.alpha, at_big.solution.orbit.alpha, kScalingTol));
  EXPECT_TRUE(testing::NearAbsBelowOne(down.orbit.I, k * at_big.solution.orbit.I, kScalingTol));
  EXPECT_TRUE(testing::Near(1.0 - down.validity.x_min, k * (1.0 - v.x_min), kScalingTol));
  EXPECT_TRUE(down.validity.valid()) << down.validity.violations;
  // So the optimum at k T0 is at least k times the one at T0; it is strictly better because
  // the left wall binds at T0 and relaxing it pays.
  ASSERT_TRUE(Has(at_big.active_constraints, "left_wall")) << at_big.message;
  EXPECT_GT(at_small.solution.orbit.I, k * at_big.solution.orbit.I * (1.0 + 1e-6));

  // The optimum at k T0 scaled up to T0: every condition but the left wall still holds.
  const Forcing& g = at_small.solution.orbit.forcing;
  const Solution up = Solve(Forcing::Harmonic(g.amplitude() / k, g.mean() / k, g.phi0()), big);
  EXPECT_TRUE(testing::NearAbsBelowOne(up.orbit.I, at_small.solution.orbit.I / k, kScalingTol));
  EXPECT_EQ(up.validity.violations & ~(1U << static_cast<unsigned>(Condition::kLeftWall)), 0U)
      << "violated: " << up.validity.violations;
  EXPECT_TRUE(up.validity.violated(Condition::kLeftWall));  // else it would beat at_big
}

TEST(OptimizeForcing, OptimumIsAPeriodicOrbitOfTheSimulator) {
  // Away from degenerate contacts: T0 = 0.1 with bound 0.9 T0, so that the optimum touches
  // only the left wall (x_min = 0, no interior maximum) and the force stays below the friction
  // bound at rest (with A + c = T0 the capsule sits exactly at breakaway, which a simulation
  // resolves only by chattering). One simulated period from the post-impact state returns.
  const Params params{0.1, 1.0};
  ForcingDesignOptions options;
  options.gait.force_bound = 0.09;
  const OptimizeResult r = OptimizeForcing(params, options);
  ASSERT_TRUE(r.found()) << r.message;
  const Orbit& o = r.solution.orbit;
  const SimResult s = testing::SimulateOnePeriodFromImpact(o, params);
  ASSERT_EQ(s.status, SimStatus::kOk) << s.message;
  EXPECT_EQ(s.impacts_right, 1);
  EXPECT_EQ(s.impacts_left, 0);
  EXPECT_TRUE(testing::NearAbsBelowOne(s.displacement, o.I, 1e-9));
  EXPECT_TRUE(testing::Near(s.final_state.u, -o.e * o.u, 1e-9));
}

TEST(OptimizeForcing, ReturnsWhereTheStickConditionAndTheForceBoundCoincide) {
  // Grid point 111 of `capsubot sweep --grid T0=0.01:1:65:log --grid e=0:1:41 --optimize
  // forcing` (the sweep's options: no margins, bound T0). There max |F| <= T0 (stick, s = 0)
  // and A + c <= T0 (force bound) are the same plane; given both, COBYLA's linear subproblem
  // cycled without evaluating, past every evaluation and time limit (the test's ctest TIMEOUT
  // catches that). Within the time limit the search ends with a valid optimum.
  const Params params{0.011547819846894581, 0.725};
  const OptimizeResult r = OptimizeForcing(params);
  EXPECT_EQ(r.status, OptimizeStatus::kOk) << r.message;
  ASSERT_TRUE(r.found()) << r.message;
  EXPECT_TRUE(r.solution.validity.valid());
}

class LocalAlgorithm : public ::testing::TestWithParam<std::string> {};

TEST_P(LocalAlgorithm, AgreesWithTheDefaultOnTheOptimum) {
  const Params params{1.0, 1.0};
  ForcingDesignOptions o;
  o.local_algorithm = GetParam();
  const OptimizeResult r = OptimizeForcing(params, o);
  const OptimizeResult reference = OptimizeForcing(params);
  ASSERT_TRUE(r.found()) << r.message;
  EXPECT_NE(r.algorithm.find(GetParam()), std::string::npos) << r.algorithm;
  EXPECT_TRUE(testing::NearAbsBelowOne(r.solution.orbit.I, reference.solution.orbit.I,
                                       kAlgorithmAgreementTol));
}

INSTANTIATE_TEST_SUITE_P(Names, LocalAlgorithm, ::testing::ValuesIn(LocalAlgorithmNames()));

class GlobalAlgorithm : public ::testing::TestWithParam<std::string> {};

TEST_P(GlobalAlgorithm, ReturnsAValidGaitNoBetterThanTheMultistartOptimum) {
  // NLopt's global algorithms are stochastic or coarse: they must return a valid gait, which
  // cannot beat the multistart optimum (up to its accuracy).
  const Params params{0.1, 1.0};
  ForcingDesignOptions o;
  o.effort.global_algorithm = GetParam();
  o.effort.global_evaluations = 3000;  // keeps GN_ORIG_DIRECT (quadratic bookkeeping) fast
  const OptimizeResult r = OptimizeForcing(params, o);
  const OptimizeResult reference = OptimizeForcing(params);
  ASSERT_TRUE(r.found()) << r.message;
  EXPECT_NE(r.algorithm.find(GetParam()), std::string::npos) << r.algorithm;
  EXPECT_EQ(r.message.find("global stage"), std::string::npos) << "NLopt threw: " << r.message;
  EXPECT_LE(r.solution.orbit.I, reference.solution.orbit.I * (1.0 + kAlgorithmAgreementTol));
  EXPECT_TRUE(Solve(r.solution.orbit.forcing, params).validity.valid());
}

INSTANTIATE_TEST_SUITE_P(Names, GlobalAlgorithm, ::testing::ValuesIn(GlobalAlgorithmNames()));

std::string ErrorOf(const Params& params, const ForcingDesignOptions& o) {
  try {
    OptimizeForcing(params, o);
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(OptimizeForcing, BadOptionsAreRejectedWithTheRule) {
  ForcingDesignOptions unknown_local;
  unknown_local.local_algorithm = "LN_FOO";
  EXPECT_EQ(ErrorOf(Params{}, unknown_local),
            "local_algorithm = \"LN_FOO\" is invalid: expected one of LN_COBYLA, LD_SLSQP, "
            "LD_MMA, LD_CCSAQ");
  ForcingDesignOptions unconstrained_global;
  unconstrained_global.effort.global_algorithm = "GN_CRS2_LM";  // an NLopt name without constraints
  const std::string message = ErrorOf(Params{}, unconstrained_global);
  EXPECT_NE(message.find("global_algorithm = \"GN_CRS2_LM\" is invalid: expected one of "
                         "multistart, GN_ISRES, GN_ORIG_DIRECT, GN_ORIG_DIRECT_L, GN_AGS"),
            std::string::npos)
      << message;
  EXPECT_NE(message.find("cannot take nonlinear inequality constraints"), std::string::npos);
  ForcingDesignOptions negative;
  negative.gait.force_bound = -1.0;
  EXPECT_EQ(ErrorOf(Params{}, negative),
            "force_bound = -1 is invalid: expected a finite bound > 0 (not given: T0)");
  ForcingDesignOptions above;  // bound above T0: inverted relative to the friction bound
  above.gait.force_bound = 2.0;
  EXPECT_EQ(ErrorOf(Params{}, above),
            "force_bound = 2 is invalid: expected at most the friction bound T0 = 1 (a force "
            "above it moves the capsule without impacts, docs/model.md section 6)");
  ForcingDesignOptions wide;
  wide.gait.margins.clearance = 0.5;
  EXPECT_EQ(ErrorOf(Params{}, wide), "margin d = 0.5 is invalid: expected 0 <= d < 0.5");
  ForcingDesignOptions many_hops;
  many_hops.hops = 2000000000;
  EXPECT_EQ(ErrorOf(Params{}, many_hops),
            "hops = 2000000000 is invalid: expected 0 <= hops <= 1000");
  ForcingDesignOptions no_time;
  no_time.max_time = 0.0;
  EXPECT_EQ(ErrorOf(Params{}, no_time),
            "max_time = 0 is invalid: expected a time limit max_time > 0 [s] (infinity: none)");
  ForcingDesignOptions no_starts;
  no_starts.effort.starts = 0;
  EXPECT_EQ(ErrorOf(Params{}, no_starts), "starts = 0 is invalid: expected 1 <= starts <= 1000");
}

TEST(NloptStatus, MapsEveryResultCode) {
  using detail::StatusFromNlopt;
  EXPECT_EQ(StatusFromNlopt(nlopt::SUCCESS), OptimizeStatus::kOk);
  EXPECT_EQ(StatusFromNlopt(nlopt::STOPVAL_REACHED), OptimizeStatus::kOk);
  EXPECT_EQ(StatusFromNlopt(nlopt::FTOL_REACHED), OptimizeStatus::kOk);
  EXPECT_EQ(StatusFromNlopt(nlopt::XTOL_REACHED), OptimizeStatus::kOk);
  EXPECT_EQ(StatusFromNlopt(nlopt::MAXEVAL_REACHED), OptimizeStatus::kMaxEvaluations);
  EXPECT_EQ(StatusFromNlopt(nlopt::MAXTIME_REACHED), OptimizeStatus::kMaxTime);
  EXPECT_EQ(StatusFromNlopt(nlopt::ROUNDOFF_LIMITED), OptimizeStatus::kRoundoffLimited);
  EXPECT_EQ(StatusFromNlopt(nlopt::FORCED_STOP), OptimizeStatus::kForcedStop);
  EXPECT_EQ(StatusFromNlopt(nlopt::INVALID_ARGS), OptimizeStatus::kInvalidArguments);
  EXPECT_EQ(StatusFromNlopt(nlopt::OUT_OF_MEMORY), OptimizeStatus::kOutOfMemory);
  EXPECT_EQ(StatusFromNlopt(nlopt::FAILURE), OptimizeStatus::kFailure);
}

template <class E>
OptimizeStatus StatusOfThrown(const E& error, std::string& message) {
  try {
    throw error;
  } catch (...) {
    return detail::StatusFromCurrentException(message);
  }
}

TEST(NloptStatus, MapsEveryExceptionNlopt271Throws) {
  std::string m;
  EXPECT_EQ(StatusOfThrown(nlopt::roundoff_limited(), m), OptimizeStatus::kRoundoffLimited);
  EXPECT_NE(m.find("round-off"), std::string::npos);
  EXPECT_EQ(StatusOfThrown(nlopt::forced_stop(), m), OptimizeStatus::kForcedStop);
  EXPECT_EQ(StatusOfThrown(std::invalid_argument("bad"), m), OptimizeStatus::kInvalidArguments);
  EXPECT_EQ(m, "NLopt rejected the problem: bad");
  EXPECT_EQ(StatusOfThrown(std::bad_alloc(), m), OptimizeStatus::kOutOfMemory);
  EXPECT_EQ(StatusOfThrown(std::runtime_error("nlopt failure"), m), OptimizeStatus::kFailure);
  EXPECT_EQ(m, "NLopt failed: nlopt failure");
}

}  // namespace
}  // namespace capsubot
