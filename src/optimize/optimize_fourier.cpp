// P3 of docs/model.md section 7: a K-harmonic force F(phi) = c + sum_k (a_k cos k phi + b_k sin k phi)
// (phi = 0 at the impact) with mean c > 0 and max |F| <= bound, maximising I.
//
// Variables, scaled by the bound: y = (c, a_1..a_K, b_1..b_K) / bound; the impact phase is
// free because the coefficients are (a rotation of the series is a change of coefficients).
// Constraints as in P2 (nlopt_constraints.hpp) with the exact max |F| <= bound. The search
// starts from the P2 optimum at the same bound (the K = 1 member of the family), so the gain
// over P2 is never negative; further starts are random perturbations of the best point so
// far. Finally the phase of the best shape is polished by P1, so that the returned orbit is
// valid through Solve.

#include "capsubot/optimize_fourier.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "capsubot/optimize_forcing.hpp"
#include "capsubot/optimize_phase.hpp"
#include "optimize/nlopt_problem.hpp"
#include "optimize/nlopt_status.hpp"
#include "optimize/optimize_common.hpp"

namespace capsubot {
namespace {

using detail::kMinMeanFraction;
using detail::Require;

// |a_k|, |b_k| <= (1/pi) integral |F| |cos k phi| <= (4/pi) max |F|: bounds on the scaled
// coefficients that cut off nothing feasible.
constexpr double kCoefficientBound = 4.0 / detail::kPi;
// Standard deviation of the random perturbations of the multistart (fraction of the bound).
constexpr double kPerturbation = 0.05;

}  // namespace

void FourierOptions::Validate() const {
  Require(
      harmonics >= 1 && harmonics <= kMaxHarmonics,
      fmt::format("harmonics K = {} is invalid: expected 1 <= K <= {}", harmonics, kMaxHarmonics));
  SearchOptions::Validate();
}

OptimizeResult OptimizeFourier(const Params& params, const FourierOptions& options) {
  options.Validate();
  detail::Search search = detail::SetUpSearch(params, options);
  const double bound = search.bound;
  const nlopt::algorithm local = search.local;
  detail::Problem& problem = search.problem;
  const int K = options.harmonics;

  // The P2 optimum at the same bound: the baseline and the first start.
  ForcingDesignOptions p2;
  p2.force_bound = bound;
  p2.local_algorithm = options.local_algorithm;
  p2.stable = options.stable;
  p2.rho_max = options.rho_max;
  p2.seed = options.seed;
  const OptimizeResult harmonic = OptimizeForcing(params, p2);

  problem.n = 2 * K + 1;
  problem.lower.assign(problem.n, -kCoefficientBound);
  problem.upper.assign(problem.n, kCoefficientBound);
  problem.lower[0] = kMinMeanFraction;
  problem.upper[0] = 1.0;
  problem.build = [bound, K](const double* y) {
    std::vector<double> a(y + 1, y + 1 + K), b(y + 1 + K, y + 1 + 2 * K);
    for (double& v : a) v *= bound;
    for (double& v : b) v *= bound;
    return Forcing::Fourier(y[0] * bound, a, b, 0.0);
  };
  problem.n = 2 * K + 1;
  detail::Tracker tracker;
  tracker.evaluations = harmonic.evaluations;
  std::vector<double> seed_y(problem.n, 0.0);
  {
    const Forcing& f = harmonic.solution.orbit.forcing;
    const double A = f.amplitude(), phi0 = f.phi0();
    seed_y[0] = std::max(f.mean() / bound, kMinMeanFraction);
    seed_y[1] = A * std::sin(phi0) / bound;      // a_1
    seed_y[1 + K] = A * std::cos(phi0) / bound;  // b_1
    detail::EvaluateAt(problem, seed_y.data(), tracker);
  }

  detail::BestRun best_run;  // the run that produced the best point
  if (!harmonic.found()) best_run.status = harmonic.status;
  std::string global_message;  // from an NLopt global stage that threw
  std::string algorithm;
  std::mt19937 rng(options.seed);
  std::normal_distribution<double> normal(0.0, kPerturbation);
  const std::vector<double> step(problem.n, kPerturbation);

  auto polish = [&](const std::vector<double>& y0) {
    detail::PolishLocally(local, problem, y0, step, options.rel_tol, options.local_evaluations,
                          tracker, best_run);
  };

  if (options.global_algorithm == kMultistart) {
    polish(seed_y);
    for (int s = 1; s < options.starts; ++s) {
      std::vector<double> y0 = tracker.best_y;
      for (int j = 1; j < problem.n; ++j) y0[j] += normal(rng);
      polish(y0);
    }
    algorithm = fmt::format("P2+multistart({} starts)+{}", options.starts, options.local_algorithm);
  } else {
    const nlopt::algorithm global = detail::AlgorithmFromName(
        options.global_algorithm, GlobalAlgorithmNames(), "global_algorithm");
    nlopt::srand(options.seed);
    const detail::RunResult run = detail::RunNlopt(global, problem, seed_y, {}, options.rel_tol,
                                                   options.global_evaluations, tracker);
    if (!run.message.empty()) global_message = "global stage: " + run.message;
    polish(tracker.best_y);
    algorithm = "P2+" + options.global_algorithm + "+" + options.local_algorithm;
  }

  // Final phase polish (P1) of the best shape; its optimum as the series seen from the impact.
  const detail::Evaluation best = detail::PolishPhase(
      problem,
      [&](const Forcing& f) {
        ++tracker.evaluations;
        return detail::Evaluate(f.InImpactFrame(), problem.setup);
      },
      tracker);

  std::string nlopt_message;
  OptimizeResult result = detail::ResultAt(best, problem, tracker, best_run, global_message,
                                           algorithm, options.active_tol, nlopt_message);
  result.baseline_I = harmonic.found() ? harmonic.solution.orbit.I : OptimizeResult::kNaN;
  if (best.valid) {
    result.message = fmt::format(
        "fastest valid {}gait with {} harmonics and max |F| <= {:g}: I = {:.10g}{}{}",
        options.stable ? "stable " : "", K, bound, best.I,
        std::isnan(result.baseline_I)
            ? std::string(" (P2 found no valid gait)")
            : fmt::format(", {:+.4g}% over the harmonic optimum I = {:.10g}",
                          100.0 * (best.I / result.baseline_I - 1.0), result.baseline_I),
        nlopt_message.empty() ? "" : "; " + nlopt_message);
  } else {
    result.message = fmt::format(
        "no valid {}gait found with {} harmonics and max |F| <= {:g}; "
        "nearest to valid violates {}",
        options.stable ? "stable " : "", K, bound, detail::DescribeViolations(best, problem.setup));
  }
  return result;
}

}  // namespace capsubot
