#pragma once
// The trajectory of a one-impact orbit over one period as CSV (`capsubot solve --trajectory`).
// The command line writes it after its '#' provenance line.

#include <ostream>

#include "capsubot/job/orbit_trajectory_settings.hpp"
#include "capsubot/orbit/orbit.hpp"

namespace capsubot::text {

/// Writes the header line "phi,x,u,v" and one row per point of the grid of `options` (phi = 0
/// just after the impact, phi = tau just before the next one): the phase, the position x, the
/// relative velocity dx/dphi and the capsule's velocity v of `orbit`, numbers as FormatNumber
/// writes them. Throws std::invalid_argument for bad options (before writing) and for an orbit
/// that does not exist (not ok).
void WriteOrbitTrajectoryCsv(std::ostream& out, const Orbit& orbit,
                             const OrbitTrajectoryOptions& options);

}  // namespace capsubot::text
