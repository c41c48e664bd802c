#pragma once
// Continuation of a periodic motion in one named model parameter of a given robot
// (docs/continuation.md): the job behind `capsubot continue` and capsubot.continue_branch.

#include <string>

#include "capsubot/continue/continuation.hpp"
#include "capsubot/continue/special_curve.hpp"
#include "capsubot/model/forcing.hpp"
#include "capsubot/model/robot_model.hpp"
#include "capsubot/orbit/orbit.hpp"

namespace capsubot {

/// The state right after the impact of a one-impact orbit (docs/model.md section 4): the
/// inner body on the right wall (x = 1) with u = -e u_impact, the capsule at v+, at the phase
/// of the robot's force `forcing` where the orbit's impact falls (psi = phi0_orbit - phi0).
PhaseState OrbitImpactState(const Orbit& orbit, const Forcing& forcing);

/// The start on the robot's valid one-impact orbit with the smallest spectral radius
/// (FindRobotOrbits, docs/orbit.md), right after its impact. Throws std::invalid_argument
/// ("from_orbit is invalid for this robot: ...") when the robot has none.
PhaseState OneImpactOrbitStart(const RobotModel& robot);

/// The robot at each value of the parameter named `param` (A, c, alpha, T0, e, phi0, a1..a16,
/// b1..b16: the robot parameters of ModelParameter), the rest as given. Throws
/// std::invalid_argument for a name it does not know or a parameter the force does not have. The
/// family holds copies.
RobotFamily NamedParameterFamily(const RobotModel& robot, const std::string& param);

/// One end of a parameter's range with the name a message gives it ("from", "to2").
struct RangeEnd {
  const char* name;
  double value;
};

/// The robot's own value of the parameter named `param` (a robot parameter, as
/// NamedParameterFamily), which must lie in [from, to]: else std::invalid_argument "the robot's
/// <param> = <value> is outside the range: expected from = .. <= <param> <= to = .. (the <what>
/// starts at the robot's value)".
double RobotValueInRange(const RobotModel& robot, const std::string& param, const RangeEnd& from,
                         const RangeEnd& to, const char* what);

/// The robot at each pair of values of the parameters named `param` and `param2` (two different
/// robot parameters, as NamedParameterFamily), the rest as given. Throws std::invalid_argument
/// as NamedParameterFamily does for either name (for param2 the message begins "param2 = "
/// instead of "parameter = "), and when both name the same parameter
/// ("param2 = A is invalid: expected a parameter other than param = A").
RobotSurface NamedParameterSurface(const RobotModel& robot, const std::string& param,
                                   const std::string& param2);

/// Follows the periodic motion near `start` in the parameter named `param` (A, c, alpha, T0,
/// e, phi0, a1..a16, b1..b16: the robot parameters of ModelParameter) over [options.from,
/// options.to], from the robot's own value of it (which sets options.start). Throws
/// std::invalid_argument for a parameter the force does not have, bad params, bad options or the
/// robot's value outside the range; outcomes are statuses of the Branch (ContinueBranch).
Branch ContinueParameter(const RobotModel& robot, const std::string& param, const PhaseState& start,
                         ContinuationOptions options);

}  // namespace capsubot
