#pragma once
// Where the analytic orbit meets the simulator: the simulator's start right after the impact
// of a one-impact orbit (docs/model.md section 4). The simulator itself never uses the orbit
// code; this bridge lives in a stage after both.

#include "capsubot/orbit/orbit.hpp"
#include "capsubot/simulate/simulator.hpp"

namespace capsubot {

/// Options that start the simulation right after the orbit's impact: mass ratio orbit.alpha,
/// x0 = 1, u0 = -e u, v0 = v_plus, y0 = 0, for `periods` periods (other options at their
/// defaults). Throws std::invalid_argument when the orbit does not exist (status not ok).
SimOptions StartAfterImpact(const Orbit& orbit, double periods = 1.0);

}  // namespace capsubot
