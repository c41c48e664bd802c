#pragma once
// The one optimisation pipeline of the force families P2 and P3 (docs/model.md section 7):
//
//   seed (a multistart scan, or an NLopt global algorithm) -> local constrained polishes from
//   the seeds -> restarts from perturbations of the best point -> an optional refinement ->
//   the phase polish by P1 -> the result, verified through Solve (every evaluation is).
//
// A problem configures it with its variables, its seeds, its perturbations and how P1's
// optimum becomes a point of the problem; the stages, budgets, time limit, statuses and the
// report are the pipeline's.

#include <functional>
#include <random>
#include <string>
#include <vector>

#include "capsubot/optimize/optimize_result.hpp"
#include "capsubot/optimize/optimize_search.hpp"
#include "optimize/nlopt_problem.hpp"

namespace capsubot::detail {

/// The starts of the local polishes (best first) and how they were found, for
/// OptimizeResult::algorithm ("multistart(grid 16x16x72, 10 starts)").
struct Seeds {
  std::vector<std::vector<double>> starts;
  std::string description;
};

struct Pipeline {
  /// Variables, bounds, build and force_total are the problem's; SetUpPipeline fills the rest.
  Problem problem;
  /// The multistart seeds, evaluated through the tracker (global_algorithm "multistart").
  std::function<Seeds(Tracker&)> seed;
  /// Where an NLopt global algorithm starts (any other global_algorithm).
  std::vector<double> global_start;
  /// Initial step of a local polish from y0.
  std::function<std::vector<double>(const std::vector<double>& y0)> step;
  /// Restarts after the starts: local polishes from perturb(best point so far, rng).
  int restarts = 0;
  std::function<void(std::vector<double>& y, std::mt19937& rng)> perturb;
  /// How the restarts are named in OptimizeResult::algorithm (nullptr: not shown).
  const char* restart_name = nullptr;
  /// Optional refinement of a valid best point (P2: the phase-exact polish); returns what it
  /// adds to OptimizeResult::algorithm.
  std::function<std::string(Tracker&, BestRun&)> refine;
  /// The final P1 optimum (a force with its phase) as a point of the problem, evaluated in
  /// its setup and counted in the tracker.
  std::function<Evaluation(const Forcing&, Tracker&)> at_phase;
  /// Put before the algorithm's description ("P2+" for P3, which starts from P2).
  std::string prefix;
};

/// For validated options: the setup (params, bound, rho_max), the constraints that apply
/// (nlopt_constraints.hpp) and I/T0 as objective. Returns the force bound in force. Throws
/// std::invalid_argument for bad params or a bound above T0.
double SetUpPipeline(Pipeline& pipeline, const Params& params, const SearchOptions& options);

/// What a pipeline run found; the problem writes result.message (WriteMessage).
struct PipelineRun {
  OptimizeResult result;
  Evaluation best;
  std::string note;  ///< NLopt's messages of the best run and of a global stage, if any
};

/// Runs the stages for `options` (the gait asked for: local algorithm, seed, rho_max,
/// active_tol) with `effort` (global stage, budgets). The status is that of the run that
/// produced the best point (`best_run` may carry an earlier stage's), kNoValidOrbit without a
/// valid point, kMaxTime when the tracker's deadline was reached.
PipelineRun RunPipeline(Pipeline& pipeline, const SearchOptions& options,
                        const SearchEffort& effort, Tracker& tracker, BestRun best_run = {});

/// The result's message: "fastest valid gait<requirements> <what>: I = ...<detail>" or "no
/// valid gait<requirements> found <what>; nearest to valid violates ...", with NLopt's note
/// and the time limit when reached.
void WriteMessage(PipelineRun& run, const Problem& problem, const std::string& what,
                  const std::string& detail, double max_time);

/// Below this T0 the force families are optimised at this T0 and the optimum scaled down
/// (AtReferenceScale): the orbits' sizes shrink with T0 (docs/model.md section 6) until the
/// search resolves them poorly.
inline constexpr double kReferenceT0 = 1e-3;

/// Optimum at params.T0 < kReferenceT0 from the one at kReferenceT0: multiplying the force
/// and T0 by k keeps every condition but the left wall and the absolute clearance d, and the
/// left wall only relaxes as T0 shrinks (docs/model.md section 6). `solve(reference params,
/// reference bound)` runs the problem at kReferenceT0; its force is scaled by k =
/// T0/kReferenceT0 and re-checked through Solve at T0 (a scaled optimum that loses validity,
/// possible only with d > 0, is reported as kNoValidOrbit). Exact when neither scale-dependent
/// condition binds at kReferenceT0; otherwise a valid gait at least k times as fast, and the
/// message says so.
OptimizeResult AtReferenceScale(
    const Params& params, double bound, const OptimizeOptions& options,
    const std::function<OptimizeResult(const Params& reference, double reference_bound)>& solve);

}  // namespace capsubot::detail
