#pragma once
// Where the analytic orbit meets the simulator: the simulator's start right after the impact
// of a one-impact orbit (docs/model.md section 4). The simulator itself never uses the orbit
// code; this bridge lives in a stage after both.

#include "capsubot/orbit/orbit.hpp"
#include "capsubot/orbit/validity.hpp"
#include "capsubot/simulate/simulator.hpp"

namespace capsubot {

/// Options that start the simulation right after the orbit's impact: mass ratio orbit.alpha,
/// x0 = 1, u0 = -e u, v0 = v_plus, y0 = 0, for `periods` periods (other options at their
/// defaults). Throws std::invalid_argument when the orbit does not exist (status not ok).
SimOptions StartAfterImpact(const Orbit& orbit, double periods = 1.0);

/// A simulation started from the analytic one-impact orbit of a robot.
struct OrbitStart {
  Solution orbit;    ///< the orbit (Solve: with its validity, which may fail)
  SimOptions start;  ///< StartAfterImpact(orbit.orbit): alpha, x0, u0, v0 (the rest defaults)
};

/// The one-impact orbit of `forcing` with T0 and e of `params` (Solve) and the start right
/// after its impact. Throws std::invalid_argument when no such orbit exists: "from_orbit: no
/// one-impact orbit exists for this force, T0 and e (non_positive_mean_force)".
OrbitStart StartFromOrbit(const Forcing& forcing, const Params& params);

}  // namespace capsubot
