#pragma once
// The text report of the orbits job, as `capsubot orbits` prints it: the robot, then one row
// per orbit (phi0, phi1, v_mean, spectral radius, stable, valid).

#include <string>

#include "capsubot/job/orbits_job.hpp"

namespace capsubot::text {

/// Said when the search hit its work bound, with the name of the bound's option or argument.
std::string OrbitsIncompleteNote(const char* bound_name);

/// The plain-text report of `result`; `bound_name` names the work bound in the note.
std::string OrbitsJobText(const OrbitsJobResult& result, const char* bound_name);

}  // namespace capsubot::text
