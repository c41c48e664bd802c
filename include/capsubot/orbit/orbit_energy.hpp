#pragma once
// The energy budget of the one-impact orbit over one period (docs/model.md section 11).

#include "capsubot/model/energy.hpp"
#include "capsubot/orbit/orbit.hpp"

namespace capsubot {

/// Motor work (net and positive part), friction and impact losses of the orbit over one period
/// tau, dimensionless (physical energy = (m1+m2) omega^2 L^2 times them). Exact: closed-form
/// antiderivatives of F x' on the pieces between the sign changes of F and of x'. Every field is
/// NaN when the orbit does not exist (!orbit.ok()); never throws, allocates nothing.
/// Over the period motor_work = friction_loss + impact_loss (energy balance).
Energy OrbitEnergy(const Orbit& orbit);

}  // namespace capsubot
