#pragma once
// The CSV tables of the optimize job: the recommended force over one period, and for the main
// job what the robot reaches from rest (the figure of promised and reached speeds).

#include <ostream>

#include "capsubot/job/optimize_job.hpp"

namespace capsubot::text {

/// Rows of the force CSV: phi = 0 (the impact) to 2 pi.
inline constexpr int kForceCsvRows = 1001;

/// Columns phi,F: `forcing` at kForceCsvRows phases over one period (header included).
void WriteForceCsv(const Forcing& forcing, std::ostream& out);

/// Columns gait,row,mean_velocity,fraction,period,impacts_right,impacts_left,one_impact_orbit:
/// the robust gait's promised mean velocity (row "promised", empty fraction) and its
/// attractors from rest, then the reach winner's attractors (header included).
void WriteFromRestCsv(const MainJobResult& result, std::ostream& out);

}  // namespace capsubot::text
