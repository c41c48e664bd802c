// P3 of docs/model.md section 7: a K-harmonic force F(phi) = c + sum_k (a_k cos k phi + b_k sin k
// phi) (phi = 0 at the impact) with mean c > 0 and max |F| <= bound, maximising I.
//
// Variables, scaled by the bound: y = (c, a_1..a_K, b_1..b_K) / bound; the impact phase is
// free because the coefficients are (a rotation of the series is a change of coefficients).
// Constraints as in P2 (nlopt_constraints.hpp) with the exact max |F| <= bound. The pipeline
// (pipeline.hpp) configured for P3: the one seed is the P2 optimum for the same request (the
// K = 1 member of the family), so the gain over P2 is never negative; restarts are random
// perturbations of the best point so far; P1's optimum is the series seen from the impact.

#include "capsubot/optimize/optimize_fourier.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/optimize/detail/optimize_common.hpp"
#include "optimize/pipeline.hpp"

namespace capsubot {
namespace {

using detail::kMinMeanFraction;

// |a_k|, |b_k| <= (1/pi) integral |F| |cos k phi| <= (4/pi) max |F|: bounds on the scaled
// coefficients that cut off nothing feasible.
constexpr double kCoefficientBound = 4.0 / detail::kPi;
// Standard deviation of the random perturbations of the multistart (fraction of the bound).
constexpr double kPerturbation = 0.05;

// The P2 optimum as a point of P3: c, a_1 = A sin phi0, b_1 = A cos phi0 (scaled).
std::vector<double> SeedFromHarmonic(const OptimizeResult& harmonic, int K, double bound) {
  std::vector<double> y(2 * K + 1, 0.0);
  const Forcing& f = harmonic.solution.orbit.forcing;
  const double A = f.amplitude(), phi0 = f.phi0();
  y[0] = std::max(f.mean() / bound, kMinMeanFraction);
  y[1] = A * std::sin(phi0) / bound;
  y[1 + K] = A * std::cos(phi0) / bound;
  return y;
}

}  // namespace

void FourierOptions::Validate() const {
  detail::Require(
      harmonics >= 1 && harmonics <= kMaxHarmonics,
      fmt::format("harmonics K = {} is invalid: expected 1 <= K <= {}", harmonics, kMaxHarmonics));
  harmonic.Validate();
  search.Validate();
}

OptimizeResult OptimizeFourier(const Params& params, const FourierOptions& options) {
  options.Validate();
  params.Validate();
  if (params.T0 < detail::kReferenceT0) {
    return detail::AtReferenceScale(params, options.harmonic.gait.BoundFor(params),
                                    options.harmonic, [&](const Params& reference, double bound) {
                                      FourierOptions o = options;
                                      o.harmonic.gait.force_bound = bound;
                                      return OptimizeFourier(reference, o);
                                    });
  }
  detail::Tracker tracker;
  tracker.deadline = detail::Deadline(options.harmonic.max_time);
  tracker.interrupt = options.harmonic.interrupt;
  const OptimizeResult harmonic = OptimizeForcing(params, options.harmonic);
  detail::Pipeline pipeline;
  const double bound = detail::SetUpPipeline(pipeline, params, options.harmonic);
  detail::Problem& problem = pipeline.problem;
  const int K = options.harmonics;
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
  tracker.evaluations = harmonic.evaluations;
  const std::vector<double> seed_y = SeedFromHarmonic(harmonic, K, bound);
  detail::EvaluateAt(problem, seed_y.data(), tracker);

  const bool multistart = options.search.global_algorithm == kMultistart;
  pipeline.prefix = "P2+";
  pipeline.seed = [&](detail::Tracker&) {
    return detail::Seeds{{seed_y}, fmt::format("multistart({} starts)", options.search.starts)};
  };
  pipeline.global_start = seed_y;
  pipeline.step = [n = problem.n](const std::vector<double>&) {
    return std::vector<double>(n, kPerturbation);
  };
  pipeline.restarts = multistart ? options.search.starts - 1 : 0;
  pipeline.perturb = [normal = std::normal_distribution<double>(0.0, kPerturbation)](
                         std::vector<double>& y, std::mt19937& rng) mutable {
    for (std::size_t j = 1; j < y.size(); ++j) y[j] += normal(rng);
  };
  // P1's optimum as the series seen from the impact (the same values to the bit).
  pipeline.at_phase = [&problem](const Forcing& f, detail::Tracker& t) {
    ++t.evaluations;
    return detail::Evaluate(f.InImpactFrame(), problem.setup);
  };

  detail::BestRun best_run;  // the run that produced the best point
  if (!harmonic.found()) best_run.status = harmonic.status;
  detail::PipelineRun run =
      detail::RunPipeline(pipeline, options.harmonic, options.search, tracker, best_run);
  OptimizeResult& result = run.result;
  result.baseline_I = harmonic.found() ? harmonic.solution.orbit.I : kNaN;
  const std::string gain =
      std::isnan(result.baseline_I)
          ? std::string(" (P2 found no valid gait)")
          : fmt::format(", {:+.4g}% over the harmonic optimum I = {:.10g}",
                        100.0 * (run.best.I / result.baseline_I - 1.0), result.baseline_I);
  detail::WriteMessage(run, problem, fmt::format("with {} harmonics and max |F| <= {:g}", K, bound),
                       run.best.valid ? gain : std::string(), options.harmonic.max_time);
  return result;
}

}  // namespace capsubot
