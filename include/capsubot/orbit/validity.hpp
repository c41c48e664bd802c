#pragma once
// When a constructed orbit is real: the conditions of docs/model.md section 5, each by name,
// with the exact extrema of the inner body's position.

#include <string>
#include <vector>

#include "capsubot/model/gait_requirements.hpp"
#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/orbit/orbit.hpp"

namespace capsubot {

enum class Condition {
  kPositiveMeanForce,   ///< 1. Pi(tau) > 0, so u > 0
  kMassRatio,           ///< 1. 0 < alpha < 1
  kForceBelowFriction,  ///< max |F| <= T0: the motor alone cannot move the capsule (A + c <= T0)
  kStick,               ///< 2. the capsule stays at rest on [phi1, tau]: |F| <= (1 - s) T0 there
  kLeftWall,            ///< 3. x >= 0 on [0, tau]
  kRightWall,           ///< 4. x <= 1 on (0, tau): no early second impact
  kSeparation,          ///< 5. the inner body leaves the wall after the impact
  /// 6. clearance <= x_min and x_max <= 1 - clearance, clearance = max(d, d_s * stroke)
  /// (checked only when d > 0 or d_s > 0)
  kClearance,
  /// Every quantity of the orbit and of these checks is a finite number in double precision
  /// (fails with OrbitStatus::kNonFinite, or extrema or forces that overflow).
  kFinite,
  kCount,
};

/// Stable identifier of a condition ("left_wall", ...), used in JSON and CSV output.
const char* ConditionName(Condition condition);

struct Validity {
  bool checked = false;      ///< false: not computed
  unsigned violations = 0;   ///< bit (1 << Condition) set for each violated condition
  double x_min = kNaN;       ///< exact minimum of x over the period (NaN without orbit)
  double phi_x_min = kNaN;   ///< where it is reached
  double x_max = kNaN;       ///< highest interior local maximum of x (NaN if there is none)
  double phi_x_max = kNaN;   ///< where it is reached
  double rest_force = kNaN;  ///< max |F| on [phi1, tau], the rest phase
  double max_force = kNaN;   ///< max |F| over the period
  /// x's range over the period, max(1, x_max) - x_min (x = 1 at the impact); NaN without orbit
  double stroke = kNaN;
  /// The clearance required from both walls, max(d, d_s * stroke) (docs/model.md section 12)
  double clearance = kNaN;

  bool valid() const { return checked && violations == 0; }
  bool violated(Condition c) const { return (violations >> static_cast<unsigned>(c)) & 1U; }
  /// Names of the violated conditions, in the order of the enum.
  std::vector<std::string> ViolationNames() const;
};

/// Relative rounding allowance of a force bound: a force whose extremum touches the bound
/// (A + c = T0, the paper's boundary) is within it, whatever the last bit of its evaluation.
inline constexpr double kForceBoundRelTol = 1e-12;

/// force <= bound up to kForceBoundRelTol: the one test of every |F| <= bound condition.
inline bool WithinForceBound(double force, double bound) {
  return force <= bound * (1.0 + kForceBoundRelTol);
}

/// Checks every condition of docs/model.md section 5, with the `margins` (section 12): the
/// clearance max(d, d_s * stroke) from both walls and |F| <= (1 - s) T0 at rest. The margins
/// must be valid; none (the default): the orbit's physical validity alone.
Validity CheckValidity(const Orbit& orbit, const Margins& margins = {});

/// An orbit together with its validity: what `capsubot solve` computes.
struct Solution {
  Orbit orbit;
  Validity validity;
};

/// ComputeOrbit + CheckValidity (params, then margins validated; throws std::invalid_argument
/// if bad).
Solution Solve(const Forcing& forcing, const Params& params, const Margins& margins = {});

}  // namespace capsubot
