#pragma once
// The grazing condition of a periodic motion (docs/continuation.md, "Two-parameter curves"):
// how close the inner body's free flight comes to a wall between two events. Between events the
// relative motion is in closed form (docs/model.md section 3): u' = kx (F + b), so from a state
// (x0, u0) at phase q0 of a mode,
//     u(q) = u0 + kx (Pi(q) - Pi(q0) + b (q - q0)),
//     x(q) = x0 + u0 (q - q0) + kx (Phi(q) - Phi(q0) - Pi(q0) (q - q0) + b (q - q0)^2 / 2).
// The flight is continued in that closed form past the wall ("virtual"): its extremum of x is
// a smooth function of the state and the parameters on both sides of a grazing, while the
// simulated motion gains an impact on one side.

#include "capsubot/attract/detail/period_map.hpp"
#include "capsubot/continue/continuation.hpp"
#include "capsubot/model/model_parameter.hpp"

namespace capsubot::detail {

/// The interior extremum of x of one free flight of a periodic motion nearest to a wall,
/// phases measured from the motion's section.
struct WallApproach {
  bool right = true;              ///< the right wall (x = 1; a maximum of x), else the left (x = 0)
  SimMode mode = SimMode::kRest;  ///< the mode of the flight
  double start = 0.0;             ///< phase of the event that starts the flight
  double phase = 0.0;             ///< phase of the extremum
  double distance = 0.0;          ///< how far the extremum lies from the wall (>= 0)
};

/// The flight of the motion through `z` (at its section, period p) whose extremum of x comes
/// nearest to either wall (to `only` when that is not kNone). False at the work bound or when
/// no free flight turns back before such a wall.
bool FindWallApproach(const RobotModel& robot, const PhaseState& z, int p,
                      const MotionOptions& motion, WallApproach* approach, Wall only = Wall::kNone);

/// The grazing condition of the motion through `z` at the flight of `approach`: x_max - 1 at the
/// right wall, -x_min at the left (negative: the flight turns back before the wall), of the
/// virtual flight from the middle of [start, phase]. False at the work bound, when the mode
/// there is not the flight's, or when the extremum is not found near `approach.phase`.
bool GrazingCondition(const RobotModel& robot, const PhaseState& z, const WallApproach& approach,
                      const MotionOptions& motion, double* g);

}  // namespace capsubot::detail
