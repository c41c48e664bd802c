#pragma once
// The robot as one value (docs/architecture.md, "The robot as one value"): its force, its
// parameters and its mass ratio travel together through every stage, so that a parameter
// added to the robot changes this type and the functions that read it, not every signature.

#include "capsubot/model/forcing.hpp"
#include "capsubot/model/params.hpp"
#include "capsubot/numerics/not_computed.hpp"

namespace capsubot {

/// One robot (docs/model.md section 2): its force, its parameters and its mass ratio; the robot
/// at one point of a study (one value of a diagram's or a branch's parameter, one point of a
/// grid) too.
struct RobotModel {
  Forcing forcing;      ///< the motor force
  Params params;        ///< T0, e (what a gait must keep is apart: GaitRequirements)
  double alpha = kNaN;  ///< mass ratio, 0 < alpha < 1
};

}  // namespace capsubot
