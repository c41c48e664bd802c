#pragma once
// One constrained NLopt run on a force family (P2, P3): the objective I and the constraints
// of nlopt_constraints.hpp, evaluated once per point (a cache serves the objective and the
// constraint call at the same x), gradients by central differences for LD_* algorithms.

#include <functional>
#include <nlopt.hpp>
#include <string>
#include <vector>

#include "capsubot/optimize_result.hpp"
#include "detail/nlopt_constraints.hpp"

namespace capsubot::detail {

/// The problem in scaled variables y (each of order 1).
struct Problem {
  int n = 0;                                      ///< number of variables
  std::vector<double> lower, upper;               ///< bounds on y
  std::function<Forcing(const double* y)> build;  ///< the force at y
  ConstraintSetup setup;                          ///< T0, e, margin, force bound, stability
  std::vector<int> constraints;                   ///< ConstraintIndex values given to NLopt
  double objective_scale = 1.0;                   ///< NLopt maximises I / objective_scale
  /// If set, replaces g[kForceBoundIndex] (e.g. the linear (A + c - bound)/T0 of P2).
  std::function<double(const double* y)> force_bound;
};

/// The best point seen over every run (valid beats invalid, then larger I), and the cost.
struct Tracker {
  Evaluation best;
  std::vector<double> best_y;
  int evaluations = 0;
  void Offer(const Evaluation& ev, const double* y, int n);
};

/// Outcome of one NLopt run.
struct RunResult {
  OptimizeStatus status = OptimizeStatus::kNotRun;
  std::string message;    ///< set when NLopt threw
  std::vector<double> y;  ///< NLopt's final point
};

/// Evaluates the problem at y (counted in the tracker, offered to it).
Evaluation EvaluateAt(const Problem& problem, const double* y, Tracker& tracker);

/// Runs `algorithm` from y0 (clamped into the bounds) with relative tolerance rel_tol on y
/// and on I, at most max_evaluations evaluations; initial_step may be empty (NLopt default).
/// Every NLopt result and exception is mapped to the returned status; never throws for them.
RunResult RunNlopt(nlopt::algorithm algorithm, const Problem& problem, std::vector<double> y0,
                   const std::vector<double>& initial_step, double rel_tol, int max_evaluations,
                   Tracker& tracker);

}  // namespace capsubot::detail
