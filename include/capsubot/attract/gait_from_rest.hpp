#pragma once
// Does the robot reach a one-impact gait from rest? (docs/model.md section 12.) The exact
// simulator is started from rest on the grid of starts of FindAttractors, with the gait's own
// force and mass ratio; the report counts the starts that end on the gait and says in words
// where the others go.

#include <cstdint>
#include <string>
#include <vector>

#include "capsubot/attract/attractors.hpp"
#include "capsubot/model/params.hpp"
#include "capsubot/orbit/orbit.hpp"

namespace capsubot {

/// A one-impact gait checked from rest.
struct GaitFromRest {
  bool checked = false;      ///< false: not computed (no orbit to check)
  Attractors attractors;     ///< the attractors reached from the starts
  std::int64_t reached = 0;  ///< starts that end on the gait (CountReached)
  /// One sentence built from the numbers, e.g. "reached from rest in 41 of 64 starts; 23 starts
  /// end in a motion with 3 right + 1 left impacts per period at mean velocity 0.0244".
  std::string summary;
};

/// The gait `orbit` checked from rest: the robot is the orbit's force (its phi0 the motor phase
/// at the impact, so the start phases psi are counted from it) and mass ratio orbit.alpha.
/// A start has reached the gait when its long-run motion is the orbit (MatchesOrbit within
/// options.attractor.orbit_tolerance). An orbit that does not exist (!orbit.ok()) gives a
/// report with checked = false and a summary saying so. Throws std::invalid_argument for bad
/// params or options.
GaitFromRest CheckGaitFromRest(const Orbit& orbit, const Params& params,
                               const FromRestOptions& options = {});

/// The same with the robot's force `motor` (the orbit's force up to its phase: a motor's own
/// force, phi0 = 0, whose phase origin then counts the start phases psi, as the design's speed
/// bands count them); the robot is that force with `params` and the orbit's alpha.
GaitFromRest CheckGaitFromRest(const Orbit& orbit, const Forcing& motor, const Params& params,
                               const FromRestOptions& options = {});

/// Where the inner body stays in a periodic motion without impacts: "at rest against the right
/// wall" (or left), or "clear of both walls"; empty for a motion with impacts.
std::string NoImpactWords(const Motion& motion);

/// A few words on a long-run motion: "a motion with 3 right + 1 left impacts per period at mean
/// velocity 0.0244", "the inner body at rest against the right wall, no impacts, at mean
/// velocity 0", "a motion with no period up to 8 (mean velocity 0.031)", "the work bound (a
/// Zeno sequence of impacts)". `digits`: significant digits of the velocity.
std::string DescribeMotion(const Motion& motion, int max_period, int digits = 3);

/// The attractors in one sentence, built from the numbers. With `on_gait` (one flag per start:
/// it ended on the gait) the sentence starts with the gait: "reached from rest in 41 of 64
/// starts; 23 starts end in ..."; without it (empty): "64 starts: 60 end in ...; 4 end in ...".
/// The other attractors follow largest first, at most three, the rest summed; the starts
/// without a period count as one group (their mean velocities as a range).
std::string AttractorsSummary(const Attractors& attractors, int max_period,
                              const std::vector<bool>& on_gait = {});

}  // namespace capsubot
