#pragma once
// One constrained NLopt run on a force family (P2, P3): the objective I and the constraints
// of nlopt_constraints.hpp, evaluated once per point (a cache serves the objective and the
// constraint call at the same x), gradients by central differences for LD_* algorithms.

#include <functional>
#include <nlopt.hpp>
#include <string>
#include <vector>

#include "capsubot/optimize/detail/optimize_common.hpp"
#include "capsubot/optimize/optimize_result.hpp"
#include "capsubot/optimize/optimize_search.hpp"
#include "optimize/nlopt_constraints.hpp"

namespace capsubot::detail {

/// The problem in scaled variables y (each of order 1).
struct Problem {
  int n = 0;                                      ///< number of variables
  std::vector<double> lower, upper;               ///< bounds on y
  std::function<Forcing(const double* y)> build;  ///< the force at y
  ConstraintSetup setup;                          ///< T0, e, margin, force bound, stability
  std::vector<int> constraints;                   ///< ConstraintIndex values given to NLopt
  double objective_scale = 1.0;                   ///< NLopt maximises I / objective_scale
  /// If set, replaces max |F| in the force bound by this measure of the force at y, in force
  /// units (P2: the linear A + c); held up to rounding (WithinForceBound), as max |F| is.
  std::function<double(const double* y)> force_total;
};

/// The best point seen over every run (valid beats invalid, then larger I), the cost, and the
/// time limit and the interrupt of the whole optimisation.
struct Tracker {
  Evaluation best;
  std::vector<double> best_y;
  int evaluations = 0;
  Deadline deadline;    ///< reached: the search stopped early
  Interrupt interrupt;  ///< asked at every evaluation (OptimizeOptions::interrupt)
  void Offer(const Evaluation& ev, const double* y, int n);
};

/// The run that produced the best point so far: its status and NLopt's message (if it threw),
/// which the result reports.
struct BestRun {
  OptimizeStatus status = OptimizeStatus::kOk;
  std::string message;
};

/// Outcome of one NLopt run.
struct RunResult {
  OptimizeStatus status = OptimizeStatus::kNotRun;
  std::string message;    ///< set when NLopt threw
  std::vector<double> y;  ///< NLopt's final point
};

/// Evaluates the problem at y (counted in the tracker, offered to it), after asking the
/// tracker's interrupt.
Evaluation EvaluateAt(const Problem& problem, const double* y, Tracker& tracker);

/// Runs `algorithm` from y0 (clamped into the bounds) with relative tolerance rel_tol on y
/// and on I, at most max_evaluations evaluations; initial_step may be empty (NLopt default).
/// Every NLopt result and exception is mapped to the returned status; never throws for them.
/// What an evaluation throws (the tracker's interrupt) is thrown again once NLopt stopped.
/// Stops at the tracker's deadline (status kMaxTime, deadline reached); does not start
/// after it.
RunResult RunNlopt(nlopt::algorithm algorithm, const Problem& problem, std::vector<double> y0,
                   const std::vector<double>& initial_step, double rel_tol, int max_evaluations,
                   Tracker& tracker);

/// A local polish: RunNlopt(algorithm) from y0 with initial step `step`; when it improves the
/// tracker's best valid point, its status and message go into `best_run`.
void PolishLocally(nlopt::algorithm algorithm, const Problem& problem,
                   const std::vector<double>& y0, const std::vector<double>& step, double rel_tol,
                   int max_evaluations, Tracker& tracker, BestRun& best_run);

/// The last step of P2 and P3: P1 (kFinalPhaseScan phases, with the stability requirement of
/// the problem) over the impact phase of the shape at the tracker's best point; `evaluate`
/// turns P1's optimum into a point of the problem, evaluated in its setup and counted in the
/// tracker. Returns the tracker's best point, replaced by that one only if it is valid and
/// better: a valid optimum is never lost to a re-evaluation that differs from P1's in the last
/// bit. Without a best point (no evaluation yet), returns the empty tracker.best.
Evaluation PolishPhase(const Problem& problem,
                       const std::function<Evaluation(const Forcing&)>& evaluate, Tracker& tracker);

}  // namespace capsubot::detail
