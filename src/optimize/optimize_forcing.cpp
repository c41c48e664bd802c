// P2 of docs/model.md section 7: A, c, phi0 of F = A sin(phi + phi0) + c maximising I.
//
// Variables, scaled to order 1: y = (A/bound, c/bound, phi0). Constraints (NLopt inequality
// constraints g <= 0, nlopt_constraints.hpp): the conditions of section 5 with the margins of
// section 12, the linear force bound (A + c - bound)/T0 and, if asked, rho <= rho_max. Where
// no orbit exists the orbit constraints are a large positive constant.
//
// The pipeline (pipeline.hpp) configured for P2: the multistart seeds come from a grid over
// (A + c, c/(A + c)) with a coarse phase scan at each cell; restarts ("hops") perturb A and c
// by relative and phi0 by absolute steps; a phase-exact polish refines the best point.

#include "capsubot/optimize/optimize_forcing.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <random>

#include "capsubot/optimize/detail/nlopt_status.hpp"
#include "capsubot/optimize/detail/optimize_common.hpp"
#include "capsubot/optimize/optimize_phase.hpp"
#include "optimize/pipeline.hpp"

namespace capsubot {
namespace {

using detail::kMinMeanFraction;
using detail::kPi;

// Smallest total force A + c (fraction of the bound) of the multistart grid at T0 <= 1, which
// is geometric in A + c: the orbit's size scales with the force (docs/model.md section 6), so
// valid gaits at a large T0 need a force far below the bound. Above T0 = 1 the grid (and the
// lower bound of c) reaches down by a further factor 1/T0.
constexpr double kMinGridForce = 1e-3;
// Phases per grid cell in the multistart scan.
constexpr int kCellPhases = 72;
// Size of the random hops: relative change of A and c, change of phi0 [rad] (one sigma).
constexpr double kHopSize = 0.2;
// Phase scan of P1 inside the phase-exact polish, and its initial step (fraction of s, r).
constexpr int kNestedPhaseScan = 180;
constexpr double kNestedStep = 0.05;

struct Cell {
  std::vector<double> y;
  double I;
};

// The multistart seeds: a grid over total force s = (A + c)/bound (geometric from min_force)
// and r = c/(A + c) (midpoints), with a coarse phase scan per cell; the best phase of each
// cell with a valid one is a candidate, the `starts` best are the seeds.
detail::Seeds GridSeeds(const detail::Problem& problem, const ForcingDesignOptions& options,
                        double min_force, detail::Tracker& tracker) {
  const int g = options.grid;
  std::vector<Cell> cells;
  for (int i = 0; i < g && !tracker.deadline.Expired(); ++i) {
    const double s = min_force * std::pow(1.0 / min_force, double(i) / (g - 1));
    for (int k = 0; k < g; ++k) {
      const double r = (k + 0.5) / g;
      Cell cell{{}, -HUGE_VAL};
      for (int q = 0; q < kCellPhases; ++q) {
        const double y[3] = {s * (1.0 - r), s * r, -kPi + kTau * q / kCellPhases};
        const detail::Evaluation ev = detail::EvaluateAt(problem, y, tracker);
        if (ev.valid && ev.I > cell.I) cell = {{y[0], y[1], y[2]}, ev.I};
      }
      if (!cell.y.empty()) cells.push_back(cell);
    }
  }
  std::sort(cells.begin(), cells.end(), [](const Cell& a, const Cell& b) { return a.I > b.I; });
  if (cells.size() > static_cast<std::size_t>(options.effort.starts)) {
    cells.resize(options.effort.starts);
  }
  detail::Seeds seeds;
  for (Cell& cell : cells) seeds.starts.push_back(std::move(cell.y));
  if (seeds.starts.empty() && !tracker.best_y.empty()) seeds.starts.push_back(tracker.best_y);
  seeds.description =
      fmt::format("multistart(grid {}x{}x{}, {} starts)", g, g, kCellPhases, seeds.starts.size());
  return seeds;
}

// The phase-exact polish: J(s, r) = the P1 optimum (best valid phase) of the force with
// A + c = s bound and c/(A + c) = r, maximised by LN_SBPLX over the box (0, 1]^2. Validity is
// enforced exactly inside P1 (arc edges bisected), the force bound by the box: no penalty.
// It moves along the thin kinked ridges that stall the 3-D constrained polish when a margin
// or e < 1 makes the clearance condition jump.
struct NestedContext {
  const detail::Problem* problem;
  detail::Tracker* tracker;
  PhaseOptions phase;
  double bound;
};

double PhaseExactObjective(unsigned, const double* sr, double*, void* data) {
  auto* ctx = static_cast<NestedContext*>(data);
  const double A = sr[0] * (1.0 - sr[1]) * ctx->bound, c = sr[0] * sr[1] * ctx->bound;
  if (!(c > 0.0)) return 0.0;
  const OptimizeResult p1 =
      OptimizePhase(Forcing::Harmonic(A, c, 0.0), ctx->problem->setup.params, ctx->phase);
  ctx->tracker->evaluations += p1.evaluations;
  if (!p1.found()) return 0.0;  // no valid phase: below every valid gait (I > 0)
  const double y[3] = {A / ctx->bound, c / ctx->bound, p1.solution.orbit.forcing.phi0()};
  const detail::Evaluation ev = detail::EvaluateAt(*ctx->problem, y, *ctx->tracker);
  return ev.valid ? ev.I / ctx->problem->objective_scale : 0.0;
}

std::string PhaseExactPolish(const detail::Problem& problem, const ForcingDesignOptions& options,
                             double bound, double min_mean, detail::Tracker& tracker,
                             detail::BestRun& best_run) {
  const Forcing& f = tracker.best.solution.orbit.forcing;
  const double total = (f.amplitude() + f.mean()) / bound;
  std::vector<double> sr = {std::min(total, 1.0), f.mean() / (f.amplitude() + f.mean())};
  NestedContext ctx{&problem, &tracker, PhaseOptions{}, bound};
  ctx.phase.scan_points = kNestedPhaseScan;
  ctx.phase.gait.rho_max = options.gait.rho_max;
  ctx.phase.gait.margins = options.gait.margins;
  ctx.phase.interrupt = tracker.interrupt;
  const double before = tracker.best.I;
  OptimizeStatus status = OptimizeStatus::kOk;
  std::string message;
  detail::NloptCallbacks callbacks;
  try {
    nlopt::opt opt(nlopt::LN_SBPLX, 2);
    opt.set_lower_bounds({min_mean, min_mean});
    opt.set_upper_bounds({1.0, 1.0});
    opt.set_max_objective(detail::NloptCallbacks::Call, callbacks.Wrap(PhaseExactObjective, &ctx));
    opt.set_xtol_rel(options.effort.rel_tol);
    opt.set_ftol_rel(options.effort.rel_tol);
    opt.set_maxeval(options.phase_exact_evaluations);
    const double remaining = tracker.deadline.Remaining();
    if (remaining < HUGE_VAL) opt.set_maxtime(remaining);
    opt.set_initial_step({kNestedStep * sr[0], kNestedStep * std::min(sr[1], 1.0 - sr[1])});
    double value = 0.0;
    status = detail::StatusFromNlopt(opt.optimize(sr, value));
  } catch (...) {
    status = detail::StatusFromCurrentException(message);
  }
  callbacks.Rethrow();
  if (status == OptimizeStatus::kMaxTime) tracker.deadline.MarkReached();
  if (tracker.best.I > before) best_run = {status, message};
  return ", phase-exact LN_SBPLX";
}

}  // namespace

void ForcingDesignOptions::Validate() const {
  SearchOptions::Validate();
  detail::RequireCount("grid", grid, 2, kMaxGrid);
  detail::RequireCount("hops", hops, 0, kMaxStarts);
  detail::RequireCount("phase_exact_evaluations", phase_exact_evaluations, 0,
                       kMaxPhaseExactEvaluations);
}

OptimizeResult OptimizeForcing(const Params& params, const ForcingDesignOptions& options) {
  options.Validate();
  params.Validate();
  if (params.T0 < detail::kReferenceT0) {
    return detail::AtReferenceScale(params, options.gait.BoundFor(params), options,
                                    [&](const Params& reference, double bound) {
                                      ForcingDesignOptions o = options;
                                      o.gait.force_bound = bound;
                                      return OptimizeForcing(reference, o);
                                    });
  }
  detail::Tracker tracker;
  tracker.deadline = detail::Deadline(options.max_time);
  tracker.interrupt = options.interrupt;
  detail::Pipeline pipeline;
  const double bound = detail::SetUpPipeline(pipeline, params, options);
  detail::Problem& problem = pipeline.problem;
  // Above T0 = 1 valid orbits need forces of order bound/T0 (docs/model.md section 6).
  const double reach_down = std::min(1.0, 1.0 / params.T0);
  const double min_mean = kMinMeanFraction * reach_down;
  problem.n = 3;
  problem.lower = {0.0, min_mean, -2.0 * kPi};
  problem.upper = {1.0, 1.0, 2.0 * kPi};
  // phi0 is reduced into [-pi, pi) here, so the point NLopt sees and the orbit reported are
  // the same numbers (a wrap afterwards could flip a grazing orbit's validity in the last bit).
  problem.build = [bound](const double* y) {
    return Forcing::Harmonic(std::max(y[0], 0.0) * bound, y[1] * bound, detail::ReducePhase(y[2]));
  };
  problem.force_total = [bound](const double* y) { return (std::max(y[0], 0.0) + y[1]) * bound; };

  pipeline.seed = [&](detail::Tracker& t) {
    return GridSeeds(problem, options, kMinGridForce * reach_down, t);
  };
  pipeline.global_start = {0.25, 0.25, 0.0};
  pipeline.step = [](const std::vector<double>& y0) {
    return std::vector<double>{0.25 * std::max(y0[0], 1e-3), 0.25 * std::max(y0[1], 1e-3), 0.1};
  };
  pipeline.restarts = options.hops;
  pipeline.restart_name = "hops";
  pipeline.perturb = [normal = std::normal_distribution<double>(0.0, kHopSize)](
                         std::vector<double>& y, std::mt19937& rng) mutable {
    y[0] *= std::exp(normal(rng));
    y[1] *= std::exp(normal(rng));
    y[2] += normal(rng);
  };
  if (options.phase_exact_evaluations > 0) {
    pipeline.refine = [&](detail::Tracker& t, detail::BestRun& best_run) {
      return PhaseExactPolish(problem, options, bound, min_mean, t, best_run);
    };
  }
  // P1's optimum at the best (A, c).
  pipeline.at_phase = [&problem](const Forcing& f, detail::Tracker& t) {
    const std::vector<double> at = t.best_y;
    const double y[3] = {at[0], at[1], f.phi0()};
    return detail::EvaluateAt(problem, y, t);
  };

  detail::PipelineRun run = detail::RunPipeline(pipeline, options, options.effort, tracker);
  std::string detail_text;
  if (run.best.valid) {
    const Forcing& f = run.best.solution.orbit.forcing;
    std::string active;
    for (const auto& a : run.result.active_constraints) {
      active += (active.empty() ? "" : ", ") + a;
    }
    detail_text = fmt::format(" (A = {:.6g}, c = {:.6g}, phi0 = {:.6g}); active constraints: {}",
                              f.amplitude(), f.mean(), f.phi0(), active.empty() ? "none" : active);
  }
  detail::WriteMessage(run, problem, fmt::format("with A + c <= {:g}", bound), detail_text,
                       options.max_time);
  return run.result;
}

}  // namespace capsubot
