#pragma once
// What every optimisation problem of docs/model.md section 7 returns: a status, the optimum as a
// solved orbit, the constraints and design margins active there and the cost.

#include <string>
#include <vector>

#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/optimize/optimize_options.hpp"
#include "capsubot/orbit/validity.hpp"

namespace capsubot {

/// Outcome of an optimisation. Every NLopt result code and exception maps to one of these.
enum class OptimizeStatus {
  kNotRun,            ///< not computed
  kOk,                ///< converged (NLopt success, stopval, ftol or xtol reached) to a valid orbit
  kNoValidOrbit,      ///< no valid (and, if required, stable) orbit was found: see `message`
  kMaxEvaluations,    ///< the evaluation budget ran out; the best valid point is returned
  kMaxTime,           ///< the time limit (max_time) was reached; the best point is returned
  kRoundoffLimited,   ///< NLopt stopped on round-off (nlopt::roundoff_limited); best point kept
  kForcedStop,        ///< NLopt was stopped (nlopt::forced_stop); best point kept
  kInvalidArguments,  ///< NLopt rejected the problem (NLOPT_INVALID_ARGS)
  kOutOfMemory,       ///< NLopt ran out of memory
  kFailure,           ///< NLopt failed (NLOPT_FAILURE or an unexpected exception)
};

/// Stable identifier of a status ("ok", "no_valid_orbit", "max_evaluations", ...).
const char* OptimizeStatusName(OptimizeStatus status);

struct OptimizeResult {
  OptimizeStatus status = OptimizeStatus::kNotRun;
  std::string message;  ///< one readable sentence: what was found, or why nothing was
  /// The optimum (force with its phi0, orbit, validity). With status kNoValidOrbit: the
  /// point nearest to validity (smallest constraint violation), whose validity says why.
  Solution solution;
  /// Spectral radius of the impact map at the returned orbit (docs/model.md section 8), computed
  /// whenever the orbit exists (< 1: stable); NaN without orbit.
  double spectral_radius = kNaN;
  /// Constraints whose slack at the optimum is within the options' active_tol, in a fixed
  /// order: validity conditions by ConditionName ("left_wall", "clearance", "stick", ...),
  /// kForceBoundName and MarginName(Margin::kRhoMax).
  std::vector<std::string> active_constraints;
  /// The design margins of docs/model.md section 12 that the optimum touches (a subset of
  /// the active constraints, saying which margin sets the clearance), in enum order.
  std::vector<Margin> binding;
  int evaluations = 0;    ///< orbit evaluations (Solve calls) spent
  std::string algorithm;  ///< what ran, e.g. "scan720+brent" or "multistart+LN_COBYLA"
  /// P3 only: I of the harmonic (P2) optimum at the same bound, the reference of the gain.
  double baseline_I = kNaN;

  /// True when `solution` is a valid orbit (statuses kOk, kMaxEvaluations, ... may have one).
  bool found() const { return solution.validity.valid(); }
};

}  // namespace capsubot
