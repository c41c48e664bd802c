#include "optimize/nlopt_problem.hpp"

#include <algorithm>
#include <cmath>

#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/optimize/detail/nlopt_status.hpp"
#include "capsubot/optimize/detail/optimize_common.hpp"
#include "capsubot/optimize/optimize_phase.hpp"

namespace capsubot::detail {
namespace {

// Central-difference step for LD_* algorithms, in the scaled variables (of order 1): about
// the cube root of the machine epsilon, the usual choice for central differences.
constexpr double kGradientStep = 6e-6;
// Constraint tolerance handed to NLopt; the returned optimum is re-checked exactly anyway.
constexpr double kConstraintTol = 1e-12;

struct Context {
  const Problem* problem;
  Tracker* tracker;
  std::vector<double> last_y;  // the cache: the point last evaluated and its values
  double last_f = 0.0;
  std::vector<double> last_g;
  std::vector<double> grad_f;  // gradients at last_y (filled on demand)
  std::vector<double> grad_g;  // m x n, row-major
  bool has_grad = false;

  // Objective and constraint values at y.
  void Values(const double* y, double& f, double* g) {
    const Problem& p = *problem;
    const Evaluation ev = EvaluateAt(p, y, *tracker);
    f = std::isfinite(ev.I) ? ev.I / p.objective_scale : 0.0;
    for (std::size_t i = 0; i < p.constraints.size(); ++i) {
      const int c = p.constraints[i];
      g[i] = ev.g[c];
    }
  }

  void Update(const double* y, bool need_grad) {
    const int n = problem->n;
    const std::size_t m = problem->constraints.size();
    const bool same = !last_y.empty() && std::equal(last_y.begin(), last_y.end(), y);
    if (!same) {
      last_y.assign(y, y + n);
      last_g.assign(m, 0.0);
      Values(y, last_f, last_g.data());
      has_grad = false;
    }
    if (need_grad && !has_grad) {
      grad_f.assign(n, 0.0);
      grad_g.assign(m * n, 0.0);
      std::vector<double> yp(y, y + n), gp(m), gm(m);
      for (int j = 0; j < n; ++j) {
        const double h = kGradientStep * std::max(1.0, std::abs(y[j]));
        double fp, fm;
        yp[j] = y[j] + h;
        Values(yp.data(), fp, gp.data());
        yp[j] = y[j] - h;
        Values(yp.data(), fm, gm.data());
        yp[j] = y[j];
        grad_f[j] = (fp - fm) / (2.0 * h);
        for (std::size_t i = 0; i < m; ++i) grad_g[i * n + j] = (gp[i] - gm[i]) / (2.0 * h);
      }
      has_grad = true;
    }
  }
};

double Objective(unsigned n, const double* y, double* grad, void* data) {
  auto* ctx = static_cast<Context*>(data);
  ctx->Update(y, grad != nullptr);
  if (grad != nullptr) std::copy(ctx->grad_f.begin(), ctx->grad_f.begin() + n, grad);
  return ctx->last_f;
}

// One scalar constraint: GN_AGS accepts only scalar constraints (no mconstraint), and the
// cache makes m scalar calls at the same point cost one evaluation.
struct ConstraintRef {
  Context* ctx;
  unsigned index;
};

double Constraint(unsigned n, const double* y, double* grad, void* data) {
  const auto* ref = static_cast<const ConstraintRef*>(data);
  Context* ctx = ref->ctx;
  ctx->Update(y, grad != nullptr);
  if (grad != nullptr) {
    std::copy(ctx->grad_g.begin() + ref->index * n, ctx->grad_g.begin() + (ref->index + 1) * n,
              grad);
  }
  return ctx->last_g[ref->index];
}

}  // namespace

void Tracker::Offer(const Evaluation& ev, const double* y, int n) {
  if (best_y.empty() || Better(ev, best)) {
    best = ev;
    best_y.assign(y, y + n);
  }
}

Evaluation EvaluateAt(const Problem& problem, const double* y, Tracker& tracker) {
  Poll(tracker.interrupt);
  ++tracker.evaluations;
  const double force = problem.force_total ? problem.force_total(y) : kNaN;
  Evaluation ev = Evaluate(problem.build(y), problem.setup, force);
  tracker.Offer(ev, y, problem.n);
  return ev;
}

RunResult RunNlopt(nlopt::algorithm algorithm, const Problem& problem, std::vector<double> y0,
                   const std::vector<double>& initial_step, double rel_tol, int max_evaluations,
                   Tracker& tracker) {
  RunResult run;
  if (tracker.deadline.Expired()) {
    run.status = OptimizeStatus::kMaxTime;
    return run;
  }
  for (int j = 0; j < problem.n; ++j) y0[j] = std::clamp(y0[j], problem.lower[j], problem.upper[j]);
  Context ctx{&problem, &tracker, {}, 0.0, {}, {}, {}, false};
  std::vector<ConstraintRef> refs;
  NloptCallbacks callbacks;
  try {
    // Configured once and never copied (nlopt::opt copies share callback data).
    nlopt::opt opt(algorithm, static_cast<unsigned>(problem.n));
    opt.set_lower_bounds(problem.lower);
    opt.set_upper_bounds(problem.upper);
    opt.set_max_objective(NloptCallbacks::Call, callbacks.Wrap(Objective, &ctx));
    for (unsigned i = 0; i < problem.constraints.size(); ++i) refs.push_back({&ctx, i});
    for (ConstraintRef& ref : refs) {
      opt.add_inequality_constraint(NloptCallbacks::Call, callbacks.Wrap(Constraint, &ref),
                                    kConstraintTol);
    }
    opt.set_xtol_rel(rel_tol);
    opt.set_ftol_rel(rel_tol);
    opt.set_maxeval(max_evaluations);
    if (!initial_step.empty()) opt.set_initial_step(initial_step);
    const double remaining = tracker.deadline.Remaining();
    if (remaining < HUGE_VAL) opt.set_maxtime(remaining);
    double f = 0.0;
    run.y = y0;
    run.status = StatusFromNlopt(opt.optimize(run.y, f));
  } catch (...) {
    run.status = StatusFromCurrentException(run.message);
  }
  callbacks.Rethrow();  // an Interrupt asked by the evaluations abandons the whole search
  if (run.status == OptimizeStatus::kMaxTime) tracker.deadline.MarkReached();
  return run;
}

void PolishLocally(nlopt::algorithm algorithm, const Problem& problem,
                   const std::vector<double>& y0, const std::vector<double>& step, double rel_tol,
                   int max_evaluations, Tracker& tracker, BestRun& best_run) {
  const double before = tracker.best.valid ? tracker.best.I : -HUGE_VAL;
  const RunResult run = RunNlopt(algorithm, problem, y0, step, rel_tol, max_evaluations, tracker);
  if (tracker.best.valid && tracker.best.I > before) best_run = {run.status, run.message};
}

Evaluation PolishPhase(const Problem& problem,
                       const std::function<Evaluation(const Forcing&)>& evaluate,
                       Tracker& tracker) {
  Evaluation best = tracker.best;
  if (tracker.best_y.empty()) return best;
  PhaseOptions phase;
  phase.scan_points = kFinalPhaseScan;
  phase.gait.rho_max = problem.setup.rho_max;
  phase.gait.margins = problem.setup.margins;
  phase.interrupt = tracker.interrupt;
  const OptimizeResult p1 =
      OptimizePhase(problem.build(tracker.best_y.data()), problem.setup.params, phase);
  tracker.evaluations += p1.evaluations;
  if (!p1.found() || (best.valid && !(p1.solution.orbit.I > best.I))) return best;
  Evaluation candidate = evaluate(p1.solution.orbit.forcing);
  if (candidate.valid && (!best.valid || candidate.I > best.I)) best = std::move(candidate);
  return best;
}

}  // namespace capsubot::detail
