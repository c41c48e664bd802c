#pragma once
// The one-impact orbits of a given robot (MODEL.md section 8, "analysis of a GIVEN robot").
//
// With the mass ratio alpha fixed, the one-impact orbits are the roots phi0 of
// alpha(phi0) = alpha over the circle, where alpha(phi0) is the mass ratio that closes the
// orbit of section 4 for the force with impact phase phi0.

#include <vector>

#include "capsubot/validity.hpp"

namespace capsubot {

/// Every one-impact orbit of a robot with fixed mass ratio alpha: all roots phi0 in [-pi, pi) of
/// alpha(phi0) = alpha (MODEL.md section 8), each solved and checked (the forcing's own phi0 is
/// ignored).
std::vector<Solution> FindRobotOrbits(const Forcing& forcing, const Params& params, double alpha);

}  // namespace capsubot
