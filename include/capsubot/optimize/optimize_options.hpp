#pragma once
// What every optimiser of docs/model.md section 7 (P1, P2, P3, the sweeps' best phase) takes
// besides its own search: the stability requirement, the time limit and the tolerance of the
// report; and the design margins of a robust gait (section 12) an optimum can bind.

#include <limits>

#include "capsubot/model/gait_requirements.hpp"
#include "capsubot/model/interrupt.hpp"
#include "capsubot/numerics/not_computed.hpp"

namespace capsubot {

/// The margins of a robust gait (docs/model.md section 12), reported when the optimum touches
/// them: those of GaitRequirements::margins, and rho_max.
enum class Margin {
  kClearance,        ///< the clearance d from both walls (Margins::clearance) is reached
  kClearanceStroke,  ///< the clearance d_s * stroke (Margins::clearance_stroke) is reached
  kStickMargin,      ///< |F| reaches (1 - s) T0 during rest, s = Margins::stick > 0
  kRhoMax,           ///< the spectral radius reaches GaitRequirements::rho_max
  kCount,
};

/// Stable identifier of a margin: "clearance", "clearance_stroke", "stick_margin", "rho_max".
const char* MarginName(Margin margin);

/// Name of the force bound (P2, P3) among the active constraints; the other names are those
/// of the validity conditions (ConditionName) and MarginName(Margin::kRhoMax).
inline constexpr const char* kForceBoundName = "force_bound";

/// What every optimiser of docs/model.md section 7 (P1, P2, P3) takes besides its own search:
/// the gait asked for, the time limit and the tolerance of the report.
struct OptimizeOptions {
  static constexpr double kInf = GaitRequirements::kInf;
  /// The margins and rho_max (P1, P2, P3), the force bound (P2, P3).
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
