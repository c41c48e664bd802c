#pragma once
// What every optimiser of docs/model.md section 7 (P1, P2, P3, the sweeps' best phase) takes
// besides its own search: the stability requirement, the time limit and the tolerance of the
// report; and the design margins of a robust gait (section 12) an optimum can bind.

#include <limits>

#include "capsubot/model/interrupt.hpp"
#include "capsubot/model/params.hpp"
#include "capsubot/numerics/not_computed.hpp"

namespace capsubot {

/// The margins of a robust gait (docs/model.md section 12), reported when the optimum touches
/// them. The clearances and the stick margin are in Params, rho_max in GaitRequirements.
enum class Margin {
  kClearance,        ///< the clearance d from both walls (Params::margin) is reached
  kClearanceStroke,  ///< the clearance d_s * stroke (Params::margin_stroke) is reached
  kStickMargin,      ///< |F| reaches (1 - s) T0 during rest, s = Params::stick_margin > 0
  kRhoMax,           ///< the spectral radius reaches GaitRequirements::rho_max
  kCount,
};

/// Stable identifier of a margin: "clearance", "clearance_stroke", "stick_margin", "rho_max".
const char* MarginName(Margin margin);

/// Name of the force bound (P2, P3) among the active constraints; the other names are those
/// of the validity conditions (ConditionName) and MarginName(Margin::kRhoMax).
inline constexpr const char* kForceBoundName = "force_bound";

/// The robust gait the commands ask for by default and the reach search starts from
/// (docs/model.md section 12): clearance d_s = 0.02 of the stroke (Params::margin_stroke),
/// stick margin s = 0.02 (Params::stick_margin), spectral radius <= 0.9 (rho_max).
inline constexpr double kRobustMarginStroke = 0.02;
inline constexpr double kRobustStickMargin = 0.02;  ///< see kRobustMarginStroke
inline constexpr double kRobustRhoMax = 0.9;        ///< see kRobustMarginStroke

/// What a gait must satisfy besides the margins d, d_s, s of its Params (which the validity of
/// every orbit reads, docs/model.md sections 5 and 12): the force bound and the stability
/// requirement. One struct for every problem, request and sweep point that asks for a gait.
struct GaitRequirements {
  static constexpr double kInf = std::numeric_limits<double>::infinity();
  /// Bound on the force, max |F| (A + c for the harmonic force) of P2, P3 and the reach
  /// search (P1 optimises the phase of a given force); NaN means T0. Must satisfy
  /// 0 < force_bound <= T0 (a larger force moves the capsule without impacts, section 6).
  double force_bound = kNaN;
  /// Largest admissible spectral radius of the impact map (docs/model.md sections 8, 12);
  /// infinity: no stability requirement; 1: stable up to marginal; > 0.
  double rho_max = kInf;

  /// Throws std::invalid_argument naming the first bad field, its value and the rule.
  void Validate() const;
  /// The bound in force for these params: force_bound, or T0 when it is NaN; throws
  /// std::invalid_argument when it exceeds T0.
  double BoundFor(const Params& params) const;
};

/// What every optimiser of docs/model.md section 7 (P1, P2, P3) takes besides its own search:
/// the gait asked for, the time limit and the tolerance of the report.
struct OptimizeOptions {
  static constexpr double kInf = GaitRequirements::kInf;
  /// The force bound (P2, P3) and rho_max (P1, P2, P3).
  GaitRequirements gait;
  /// Wall-clock limit of the whole optimisation [s]; when reached, the best point so far is
  /// returned with status kMaxTime; > 0 (infinity: none).
  double max_time = 60.0;
  /// A constraint is reported active when its slack is at most this (units of L, or of T0
  /// when T0 < 1, for positions; of T0 for forces; plain for alpha and rho); >= 0.
  double active_tol = 1e-7;
  /// Asked at every evaluation of the objective (interrupt.hpp); throws to abandon the run.
  Interrupt interrupt;

  /// Throws std::invalid_argument naming the first bad field, its value and the rule.
  void Validate() const;
};

}  // namespace capsubot
