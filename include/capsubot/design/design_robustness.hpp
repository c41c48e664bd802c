#pragma once
// How far the friction coefficient mu, the restitution e and the inner mass m2 of a designed
// robot can move, the rest of the robot fixed (m1, L, g, the motor force in newtons, the
// frequency), before its gait's periodic motion is lost (docs/design.md, "Robustness"): the
// gait's motion continued in each of them, both ways, up to the nearest special point, as
// ComputeGaitRobustness does in T0, e and alpha for the dimensionless model.

#include "capsubot/continue/continuation.hpp"
#include "capsubot/continue/gait_robustness.hpp"
#include "capsubot/design/design.hpp"

namespace capsubot {

/// The robots of the one-parameter family over the inner mass of the robot `input` at
/// frequency `frequency` [Hz]: at lambda, the robot with inner mass lambda m2 [kg] (lambda the
/// relative inner mass, 1 at m2), as the design maps it (MapToModel): alpha = lambda m2/(m1 +
/// lambda m2) and the force in units of (m1 + lambda m2) omega^2 L, T0 and e unchanged. The
/// parameter is relative so that the continuation's steps suit every mass scale. The family
/// holds copies; it validates nothing.
RobotFamily InnerMassFamily(const DesignInput& input, double m2, double frequency);

/// The gait `gait` (a one-impact gait of the robot `input`, Gait::ok) continued in mu, e and
/// m2, in that order, named "mu", "e" and "m2_kg", every value in the user's units (mu, e, kg):
/// mu through T0 = mu g/(omega^2 L), over [T0 / t0_factor, T0 t0_factor] (the T0 entry of
/// ComputeGaitRobustness of the gait's orbit, converted); e over [0, 1]; m2 over
/// [m2 / t0_factor, m2 t0_factor] along InnerMassFamily, from the orbit's impact state. Throws
/// std::invalid_argument for a gait that is not ok or bad options.
GaitRobustness ComputeDesignRobustness(const DesignInput& input, const Gait& gait,
                                       const RobustnessOptions& options);
/// The same with the default RobustnessOptions.
GaitRobustness ComputeDesignRobustness(const DesignInput& input, const Gait& gait);

}  // namespace capsubot
