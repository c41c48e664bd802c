#pragma once
// What every optimisation problem of docs/model.md section 7 returns: a status, the optimum as a
// solved orbit, the constraints active there and the cost.

#include <limits>
#include <string>
#include <vector>

#include "capsubot/validity.hpp"

namespace capsubot {

/// Outcome of an optimisation. Every NLopt result code and exception maps to one of these.
enum class OptimizeStatus {
  kNotRun,            ///< not computed
  kOk,                ///< converged (NLopt success, stopval, ftol or xtol reached) to a valid orbit
  kNoValidOrbit,      ///< no valid (and, if required, stable) orbit was found: see `message`
  kMaxEvaluations,    ///< the evaluation budget ran out; the best valid point is returned
  kMaxTime,           ///< the time budget ran out; the best valid point is returned
  kRoundoffLimited,   ///< NLopt stopped on round-off (nlopt::roundoff_limited); best point kept
  kForcedStop,        ///< NLopt was stopped (nlopt::forced_stop); best point kept
  kInvalidArguments,  ///< NLopt rejected the problem (NLOPT_INVALID_ARGS)
  kOutOfMemory,       ///< NLopt ran out of memory
  kFailure,           ///< NLopt failed (NLOPT_FAILURE or an unexpected exception)
};

/// Stable identifier of a status ("ok", "no_valid_orbit", "max_evaluations", ...).
const char* OptimizeStatusName(OptimizeStatus status);

/// Names of the constraints reported in OptimizeResult::active_constraints (docs/model.md s. 5, 7).
namespace constraint_names {
inline constexpr const char* kLeftWall = "left_wall";        ///< x_min >= margin
inline constexpr const char* kRightWall = "right_wall";      ///< x_max <= 1 - margin
inline constexpr const char* kMassRatioLow = "alpha_low";    ///< alpha > 0 (alpha >= alpha_min)
inline constexpr const char* kMassRatioHigh = "alpha_high";  ///< alpha < 1 (alpha <= alpha_max)
inline constexpr const char* kStick = "stick";               ///< max |F| on rest phase <= T0
inline constexpr const char* kForceBound = "force_bound";    ///< A + c (max |F|) <= bound
inline constexpr const char* kSeparation = "separation";     ///< inner body leaves the wall
inline constexpr const char* kStability = "stability";       ///< spectral radius <= rho_max
}  // namespace constraint_names

struct OptimizeResult {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

  OptimizeStatus status = OptimizeStatus::kNotRun;
  std::string message;  ///< one readable sentence: what was found, or why nothing was
  /// The optimum (force with its phi0, orbit, validity). With status kNoValidOrbit: the
  /// point nearest to validity (smallest constraint violation), whose validity says why.
  Solution solution;
  /// Spectral radius of the impact map at the returned orbit (docs/model.md section 8), computed
  /// whenever the orbit exists (< 1: stable); NaN without orbit.
  double spectral_radius = kNaN;
  /// Constraints whose slack at the optimum is within the options' active_tol (names from
  /// capsubot::constraint_names), in a fixed order.
  std::vector<std::string> active_constraints;
  int evaluations = 0;    ///< orbit evaluations (Solve calls) spent
  std::string algorithm;  ///< what ran, e.g. "scan720+brent" or "multistart+LN_COBYLA"
  /// P3 only: I of the harmonic (P2) optimum at the same bound, the reference of the gain.
  double baseline_I = kNaN;

  /// True when `solution` is a valid orbit (statuses kOk, kMaxEvaluations, ... may have one).
  bool found() const { return solution.validity.valid(); }
};

}  // namespace capsubot
