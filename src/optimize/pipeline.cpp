#include "optimize/pipeline.hpp"

#include <fmt/format.h>

#include <cmath>

#include "capsubot/optimize/detail/nlopt_status.hpp"

namespace capsubot::detail {

double SetUpPipeline(Pipeline& pipeline, const Params& params, const SearchOptions& options) {
  params.Validate();
  const double bound = options.gait.BoundFor(params);
  Problem& problem = pipeline.problem;
  problem.setup = {params, bound, options.gait.rho_max, 0.0, options.gait.margins};
  // The stick condition max |F| on [phi1, tau] <= (1 - s) T0 follows from the force bound
  // (max |F| <= A + c <= bound, docs/model.md section 7) when bound <= (1 - s) T0, and at the
  // default bound T0 with s = 0 the two rows are one plane: NLopt is given the bound only.
  // COBYLA's linear subproblem can cycle forever, without evaluating, on such a repeated
  // active row. Validity (Evaluate) still checks the stick condition.
  const bool stick_implied = bound <= (1.0 - options.gait.margins.stick) * params.T0;
  problem.constraints.clear();
  for (int i = 0; i < kConstraintCount; ++i) {
    if (i == kStickIndex && stick_implied) continue;
    if (problem.setup.Applies(i)) problem.constraints.push_back(i);
  }
  problem.objective_scale = params.T0;
  return bound;
}

PipelineRun RunPipeline(Pipeline& pipeline, const SearchOptions& options,
                        const SearchEffort& effort, Tracker& tracker, BestRun best_run) {
  const Problem& problem = pipeline.problem;
  const nlopt::algorithm local =
      AlgorithmFromName(options.local_algorithm, LocalAlgorithmNames(), "local_algorithm");
  std::vector<std::vector<double>> starts;
  std::string algorithm, global_message;
  if (effort.global_algorithm == kMultistart) {
    Seeds seeds = pipeline.seed(tracker);
    starts = std::move(seeds.starts);
    algorithm = pipeline.prefix + seeds.description + "+" + options.local_algorithm;
  } else {
    const nlopt::algorithm global =
        AlgorithmFromName(effort.global_algorithm, GlobalAlgorithmNames(), "global_algorithm");
    nlopt::srand(options.seed);
    const RunResult run = RunNlopt(global, problem, pipeline.global_start, {}, effort.rel_tol,
                                   effort.global_evaluations, tracker);
    if (!tracker.best_y.empty()) starts.push_back(tracker.best_y);
    if (!run.y.empty() && run.y != tracker.best_y) starts.push_back(run.y);
    if (!run.message.empty()) global_message = "global stage: " + run.message;
    algorithm = pipeline.prefix + effort.global_algorithm + "+" + options.local_algorithm;
  }

  // Local constrained polishes from every start, then restarts from perturbations of the best
  // point so far (where the constraints are kinked, a polish stalls on ridges: restarts move
  // along them). The status is that of the run that produced the best point.
  auto polish = [&](const std::vector<double>& y0) {
    PolishLocally(local, problem, y0, pipeline.step(y0), effort.rel_tol, effort.local_evaluations,
                  tracker, best_run);
  };
  for (const std::vector<double>& y0 : starts) {
    if (tracker.deadline.Expired()) break;
    polish(y0);
  }
  std::mt19937 rng(options.seed);
  for (int h = 0; h < pipeline.restarts && !tracker.best_y.empty(); ++h) {
    if (tracker.deadline.Expired()) break;
    std::vector<double> y0 = tracker.best_y;
    pipeline.perturb(y0, rng);
    polish(y0);
  }
  if (pipeline.restart_name != nullptr && pipeline.restarts > 0) {
    algorithm += fmt::format(", {} {}", pipeline.restarts, pipeline.restart_name);
  }
  if (pipeline.refine && tracker.best.valid && !tracker.deadline.Expired()) {
    algorithm += pipeline.refine(tracker, best_run);
  }

  // The phase polish (P1) of the best shape: its optimum replaces the best point only if it
  // is valid and better, so the returned point is valid through Solve itself.
  PipelineRun out;
  out.best = PolishPhase(
      problem, [&](const Forcing& f) { return pipeline.at_phase(f, tracker); }, tracker);
  out.note = best_run.message;
  if (!global_message.empty()) out.note += (out.note.empty() ? "" : "; ") + global_message;
  OptimizeResult& result = out.result;
  result.algorithm = std::move(algorithm);
  result.evaluations = tracker.evaluations;
  result.solution = out.best.solution;
  result.spectral_radius = SpectralRadius(out.best);
  if (out.best.valid) {
    result.status = best_run.status;
    result.active_constraints = ActiveConstraints(out.best, problem.setup, options.active_tol);
    result.binding = BindingMargins(out.best, problem.setup, options.active_tol);
  } else {
    result.status = OptimizeStatus::kNoValidOrbit;
  }
  if (tracker.deadline.reached()) result.status = OptimizeStatus::kMaxTime;
  return out;
}

void WriteMessage(PipelineRun& run, const Problem& problem, const std::string& what,
                  const std::string& detail, double max_time) {
  const std::string requirements = RequirementWords(problem.setup);
  std::string& m = run.result.message;
  if (run.best.valid) {
    m = fmt::format("fastest valid gait{} {}: I = {:.10g}{}{}{}", requirements, what, run.best.I,
                    detail, run.note.empty() ? "" : "; ", run.note);
  } else {
    m = fmt::format("no valid gait{} found {}{}{}{}; nearest to valid violates {}", requirements,
                    what, run.note.empty() ? "" : " (", run.note, run.note.empty() ? "" : ")",
                    DescribeViolations(run.best, problem.setup));
  }
  if (run.result.status == OptimizeStatus::kMaxTime) {
    m += fmt::format("; time limit of {:g} s reached: the search is incomplete", max_time);
  }
}

namespace {

Forcing Scaled(const Forcing& f, double k) {
  if (f.harmonic()) return Forcing::Harmonic(k * f.amplitude(), k * f.mean(), f.phi0());
  std::vector<double> a, b;
  for (int i = 1; i <= f.harmonics(); ++i) {
    a.push_back(k * f.a(i));
    b.push_back(k * f.b(i));
  }
  return Forcing::Fourier(k * f.mean(), a, b, f.phi0());
}

}  // namespace

OptimizeResult AtReferenceScale(
    const Params& params, double bound, const OptimizeOptions& options,
    const std::function<OptimizeResult(const Params& reference, double reference_bound)>& solve) {
  const double k = params.T0 / kReferenceT0;
  Params reference = params;
  reference.T0 = kReferenceT0;
  OptimizeResult r = solve(reference, bound / k);
  if (r.solution.orbit.status == OrbitStatus::kNotRun) return r;
  // The optimum at the reference may lie on rho = rho_max: scaled, its spectral radius holds
  // the bound to rounding, as the force bound does (kForceBoundRelTol).
  const Margins& margins = options.gait.margins;
  const ConstraintSetup setup{params, bound, options.gait.rho_max, kForceBoundRelTol, margins};
  const ConstraintSetup reference_setup{reference, bound / k, options.gait.rho_max, 0.0, margins};
  // Whether a scale-dependent condition binds at the reference: then T0 may do better.
  const Evaluation at_reference = Evaluate(r.solution.orbit.forcing, reference_setup);
  const bool exact =
      !(std::abs(at_reference.g[kLeftWallIndex]) <= options.active_tol) &&
      !(margins.clearance > 0.0 && r.solution.validity.clearance == margins.clearance);
  const Evaluation ev = Evaluate(Scaled(r.solution.orbit.forcing, k), setup);
  r.solution = ev.solution;
  r.spectral_radius = SpectralRadius(ev);
  r.baseline_I *= k;
  r.active_constraints = ActiveConstraints(ev, setup, options.active_tol);
  r.binding = BindingMargins(ev, setup, options.active_tol);
  if (!ev.valid && r.status != OptimizeStatus::kMaxTime) r.status = OptimizeStatus::kNoValidOrbit;
  r.message = fmt::format(
      "solved at T0 = {:g} and scaled by {:g} (docs/model.md section 6): I = {:.10g}{}{}; at the "
      "reference: {}",
      kReferenceT0, k, ev.I, ev.valid ? "" : ", which is not valid at this T0: ",
      ev.valid ? (exact ? ""
                        : " (the left wall or the clearance d binds at the reference: "
                          "a lower bound of the optimum)")
               : DescribeViolations(ev, setup),
      r.message);
  return r;
}

}  // namespace capsubot::detail
