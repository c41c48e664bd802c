#pragma once
// What a gait is required to keep (docs/model.md sections 7, 8 and 12), apart from the robot
// itself (robot_model.hpp): the margins of a robust gait, the force bound and the stability
// requirement. The robot's motion does not depend on them; they decide which motions count.

#include <limits>

#include "capsubot/model/params.hpp"
#include "capsubot/numerics/not_computed.hpp"

namespace capsubot {

/// The margins of a robust gait (docs/model.md section 12), which the validity of an orbit
/// reads (section 5): zero margins ask only for a physical orbit.
struct Margins {
  double clearance = 0.0;  ///< clearance d required between inner body and walls; 0 <= d < 0.5
  /// Clearance relative to the stroke d_s: the clearance from both walls is at least
  /// d_s * (x_max - x_min), x's range over the period; 0 <= d_s < 0.5.
  double clearance_stroke = 0.0;
  /// Stick margin s: while the capsule rests, |F| <= (1 - s) T0; 0 <= s < 1.
  double stick = 0.0;

  /// Whether any margin is asked for (> 0).
  bool Any() const { return clearance > 0.0 || clearance_stroke > 0.0 || stick > 0.0; }
  /// Throws std::invalid_argument naming the first bad margin, its value and the rule.
  void Validate() const;
};

/// The robust gait the commands ask for by default and the reach search starts from
/// (docs/model.md section 12): clearance d_s = 0.02 of the stroke (Margins::clearance_stroke),
/// stick margin s = 0.02 (Margins::stick), spectral radius <= 0.9 (rho_max).
inline constexpr double kRobustMarginStroke = 0.02;
inline constexpr double kRobustStickMargin = 0.02;  ///< see kRobustMarginStroke
inline constexpr double kRobustRhoMax = 0.9;        ///< see kRobustMarginStroke

/// The margins of the robust gait: kRobustMarginStroke and kRobustStickMargin.
inline Margins RobustMargins() { return Margins{0.0, kRobustMarginStroke, kRobustStickMargin}; }

/// What a gait must satisfy: the margins (which the validity of its orbit reads, docs/model.md
/// sections 5 and 12), the force bound and the stability requirement. One struct for every
/// problem, request and sweep point that asks for a gait.
struct GaitRequirements {
  static constexpr double kInf = std::numeric_limits<double>::infinity();
  /// Bound on the force, max |F| (A + c for the harmonic force) of P2, P3 and the reach
  /// search (P1 optimises the phase of a given force); NaN means T0. Must satisfy
  /// 0 < force_bound <= T0 (a larger force moves the capsule without impacts, section 6).
  double force_bound = kNaN;
  /// Largest admissible spectral radius of the impact map (docs/model.md sections 8, 12);
  /// infinity: no stability requirement; 1: stable up to marginal; > 0.
  double rho_max = kInf;
  /// The clearances d, d_s and the stick margin s of every orbit.
  Margins margins;

  /// Throws std::invalid_argument naming the first bad field, its value and the rule (the
  /// margins first).
  void Validate() const;
  /// The bound in force for these params: force_bound, or T0 when it is NaN; throws
  /// std::invalid_argument when it exceeds T0.
  double BoundFor(const Params& params) const;
};

}  // namespace capsubot
