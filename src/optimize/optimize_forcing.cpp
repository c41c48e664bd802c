// P2 of docs/model.md section 7: A, c, phi0 of F = A sin(phi + phi0) + c maximising I.
//
// Variables, scaled to order 1: y = (A/bound, c/bound, phi0). Constraints (NLopt inequality
// constraints g <= 0, nlopt_constraints.hpp): left wall / clearance, right wall / clearance,
// 0 < alpha < 1, stick, separation, the linear force bound (A + c - bound)/T0 and, if asked,
// stability. Where no orbit exists the orbit constraints are a large positive constant.
//
// Global stage: "multistart" scans a grid over (A + c, c/(A + c)) with a coarse phase scan at
// each cell, and polishes locally from the best valid cells; or an NLopt global algorithm,
// polished locally from its best point. Finally the phase is polished by P1 at the best
// (A, c), so that the returned orbit is valid through Solve, not just within NLopt's
// constraint tolerance.

#include "capsubot/optimize_forcing.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <stdexcept>

#include "capsubot/optimize_phase.hpp"
#include "optimize/nlopt_problem.hpp"
#include "optimize/nlopt_status.hpp"
#include "optimize/optimize_common.hpp"

namespace capsubot {
namespace {

using detail::kMinMeanFraction;
using detail::kPi;
using detail::Require;

// Smallest total force A + c (fraction of the bound) of the multistart grid, which is
// geometric in A + c: the orbit's size scales with the force (docs/model.md section 6), so valid
// gaits at a large T0 need a force far below the bound.
constexpr double kMinGridForce = 1e-3;
// Phases per grid cell in the multistart scan.
constexpr int kCellPhases = 72;
// Size of the random hops: relative change of A and c, change of phi0 [rad] (one sigma).
constexpr double kHopSize = 0.2;
// Phase scan of P1 inside the phase-exact polish, and its initial step (fraction of s, r).
constexpr int kNestedPhaseScan = 180;
constexpr double kNestedStep = 0.05;
struct Start {
  std::vector<double> y;
  double I;
};

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

}  // namespace

void ForcingDesignOptions::Validate() const {
  SearchOptions::Validate();
  Require(grid >= 2, fmt::format("grid = {} is invalid: expected grid >= 2", grid));
  Require(hops >= 0, fmt::format("hops = {} is invalid: expected hops >= 0", hops));
  Require(phase_exact_evaluations >= 0,
          fmt::format("phase_exact_evaluations = {} is invalid: expected >= 0",
                      phase_exact_evaluations));
}

OptimizeResult OptimizeForcing(const Params& params, const ForcingDesignOptions& options) {
  options.Validate();
  detail::Search search = detail::SetUpSearch(params, options);
  const double bound = search.bound;
  const nlopt::algorithm local = search.local;
  detail::Problem& problem = search.problem;
  const bool multistart = options.global_algorithm == kMultistart;
  problem.n = 3;
  problem.lower = {0.0, kMinMeanFraction, -2.0 * kPi};
  problem.upper = {1.0, 1.0, 2.0 * kPi};
  // phi0 is reduced into [-pi, pi) here, so the point NLopt sees and the orbit reported are
  // the same numbers (a wrap afterwards could flip a grazing orbit's validity in the last bit).
  problem.build = [bound](const double* y) {
    return Forcing::Harmonic(std::max(y[0], 0.0) * bound, y[1] * bound, detail::ReducePhase(y[2]));
  };
  problem.force_total = [bound](const double* y) { return (std::max(y[0], 0.0) + y[1]) * bound; };

  detail::Tracker tracker;
  std::vector<Start> starts;
  detail::BestRun best_run;    // the run that produced the best point
  std::string global_message;  // from an NLopt global stage that threw
  std::string algorithm;

  if (multistart) {
    // Grid over total force s = (A + c)/bound (geometric) and r = c/(A + c) (midpoints), with
    // a coarse phase scan per cell; the best phase of each cell is a candidate start.
    const int g = options.grid;
    std::vector<Start> cells;
    for (int i = 0; i < g; ++i) {
      const double s = kMinGridForce * std::pow(1.0 / kMinGridForce, double(i) / (g - 1));
      for (int k = 0; k < g; ++k) {
        const double r = (k + 0.5) / g;
        Start cell{{}, -HUGE_VAL};
        for (int q = 0; q < kCellPhases; ++q) {
          const double y[3] = {s * (1.0 - r), s * r, -kPi + kTau * q / kCellPhases};
          const detail::Evaluation ev = detail::EvaluateAt(problem, y, tracker);
          if (ev.valid && ev.I > cell.I) cell = {{y[0], y[1], y[2]}, ev.I};
        }
        if (!cell.y.empty()) cells.push_back(cell);
      }
    }
    std::sort(cells.begin(), cells.end(), [](const Start& a, const Start& b) { return a.I > b.I; });
    if (cells.size() > static_cast<std::size_t>(options.starts)) cells.resize(options.starts);
    starts = cells;
    if (starts.empty() && !tracker.best_y.empty()) starts.push_back({tracker.best_y, 0.0});
    algorithm = fmt::format("multistart(grid {}x{}x{}, {} starts)+{}", g, g, kCellPhases,
                            starts.size(), options.local_algorithm);
  } else {
    const nlopt::algorithm global = detail::AlgorithmFromName(
        options.global_algorithm, GlobalAlgorithmNames(), "global_algorithm");
    nlopt::srand(options.seed);
    const detail::RunResult run =
        detail::RunNlopt(global, problem, {0.25, 0.25, 0.0}, {}, options.rel_tol,
                         options.global_evaluations, tracker);
    if (!tracker.best_y.empty()) starts.push_back({tracker.best_y, tracker.best.I});
    if (!run.y.empty() && run.y != tracker.best_y) starts.push_back({run.y, 0.0});
    if (!run.message.empty()) global_message = "global stage: " + run.message;
    algorithm = options.global_algorithm + "+" + options.local_algorithm;
  }

  // Local constrained polish from every start; the status is that of the run that produced
  // the best point.
  auto polish = [&](const std::vector<double>& y0) {
    const std::vector<double> step = {0.25 * std::max(y0[0], 1e-3), 0.25 * std::max(y0[1], 1e-3),
                                      0.1};
    detail::PolishLocally(local, problem, y0, step, options.rel_tol, options.local_evaluations,
                          tracker, best_run);
  };
  for (const Start& start : starts) polish(start.y);
  // Basin hopping: where the constraints are kinked (a margin, e < 1) the local polish stalls
  // on ridges; restarts from random perturbations of the best point so far move along them.
  std::mt19937 rng(options.seed);
  std::normal_distribution<double> normal(0.0, kHopSize);
  for (int h = 0; h < options.hops && !tracker.best_y.empty(); ++h) {
    std::vector<double> y0 = tracker.best_y;
    y0[0] *= std::exp(normal(rng));
    y0[1] *= std::exp(normal(rng));
    y0[2] += normal(rng);
    polish(y0);
  }
  if (options.hops > 0) algorithm += fmt::format(", {} hops", options.hops);

  if (options.phase_exact_evaluations > 0 && tracker.best.valid) {
    const Forcing& f = tracker.best.solution.orbit.forcing;
    const double total = (f.amplitude() + f.mean()) / bound;
    std::vector<double> sr = {std::min(total, 1.0), f.mean() / (f.amplitude() + f.mean())};
    NestedContext ctx{&problem, &tracker, PhaseOptions{}, bound};
    ctx.phase.scan_points = kNestedPhaseScan;
    ctx.phase.stable = options.stable;
    ctx.phase.rho_max = options.rho_max;
    const double before = tracker.best.I;
    OptimizeStatus status = OptimizeStatus::kOk;
    std::string message;
    try {
      nlopt::opt opt(nlopt::LN_SBPLX, 2);
      opt.set_lower_bounds({kMinMeanFraction, kMinMeanFraction});
      opt.set_upper_bounds({1.0, 1.0});
      opt.set_max_objective(PhaseExactObjective, &ctx);
      opt.set_xtol_rel(options.rel_tol);
      opt.set_ftol_rel(options.rel_tol);
      opt.set_maxeval(options.phase_exact_evaluations);
      opt.set_initial_step({kNestedStep * sr[0], kNestedStep * std::min(sr[1], 1.0 - sr[1])});
      double value = 0.0;
      status = detail::StatusFromNlopt(opt.optimize(sr, value));
    } catch (...) {
      status = detail::StatusFromCurrentException(message);
    }
    if (tracker.best.I > before) best_run = {status, message};
    algorithm += fmt::format(", phase-exact LN_SBPLX");
  }

  // Final phase polish (P1) at the best (A, c): a point valid through Solve itself.
  const std::vector<double> at = tracker.best_y;
  const detail::Evaluation best = detail::PolishPhase(
      problem,
      [&](const Forcing& f) {
        const double y[3] = {at[0], at[1], f.phi0()};
        return detail::EvaluateAt(problem, y, tracker);
      },
      tracker);

  std::string nlopt_message;
  OptimizeResult result = detail::ResultAt(best, problem, tracker, best_run, global_message,
                                           algorithm, options.active_tol, nlopt_message);
  if (best.valid) {
    std::string active;
    for (const auto& a : result.active_constraints) active += (active.empty() ? "" : ", ") + a;
    result.message = fmt::format(
        "fastest valid {}gait with A + c <= {:g}: I = {:.10g} (A = {:.6g}, c = {:.6g}, phi0 = "
        "{:.6g}); active constraints: {}{}{}",
        options.stable ? "stable " : "", bound, best.I, best.solution.orbit.forcing.amplitude(),
        best.solution.orbit.forcing.mean(), best.solution.orbit.forcing.phi0(),
        active.empty() ? "none" : active, nlopt_message.empty() ? "" : "; ", nlopt_message);
  } else {
    result.message =
        fmt::format("no valid {}gait found with A + c <= {:g}{}{}; nearest to valid violates {}",
                    options.stable ? "stable " : "", bound, nlopt_message.empty() ? "" : " (",
                    nlopt_message.empty() ? "" : nlopt_message + ")",
                    detail::DescribeViolations(best, problem.setup));
  }
  return result;
}

}  // namespace capsubot
