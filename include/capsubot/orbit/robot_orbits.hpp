#pragma once
// The one-impact orbits of a given robot (docs/model.md section 8, "analysis of a GIVEN robot").
//
// With the mass ratio alpha fixed, the one-impact orbits are the roots phi0 of
// alpha(phi0) = alpha over the circle, where alpha(phi0) is the mass ratio that closes the
// orbit of section 4 for the force with impact phase phi0.

#include <cstdint>
#include <functional>
#include <vector>

#include "capsubot/model/robot_model.hpp"
#include "capsubot/orbit/validity.hpp"

namespace capsubot {

/// Default work bound of FindRobotOrbits: evaluations of the orbit equation while refining
/// the circle (the search needs far fewer for every force tested; see docs/orbit.md).
inline constexpr std::int64_t kRobotOrbitsMaxEvaluations = 4000000;

/// Every one-impact orbit of a robot with fixed mass ratio alpha = robot.alpha: all roots phi0 in
/// [-pi, pi) of alpha(phi0) = alpha (docs/model.md section 8), each solved and checked (the phi0
/// of robot.forcing is ignored), validity with the `margins` (docs/model.md section 12; none:
/// the physical validity). If the work bound max_evaluations (>= 1) stops the search before
/// every part of the circle is decided, the list may miss orbits: *complete (if given) is set to
/// false then, true otherwise. Throws std::invalid_argument for bad params, margins, alpha or
/// max_evaluations. `poll` (optional) is called every kRobotOrbitsPollEvaluations evaluations: what
/// it throws stops the search and is rethrown (a caller's cancellation).
std::vector<Solution> FindRobotOrbits(const RobotModel& robot, const Margins& margins = {},
                                      bool* complete = nullptr,
                                      std::int64_t max_evaluations = kRobotOrbitsMaxEvaluations,
                                      const std::function<void()>& poll = {});

/// Evaluations between two calls of FindRobotOrbits' `poll` (about a millisecond).
inline constexpr std::int64_t kRobotOrbitsPollEvaluations = 4096;

}  // namespace capsubot
