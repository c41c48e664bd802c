#pragma once
// `capsubot basins` as one call (docs/model.md sections 12 and 13): the attractor reached from
// every start of a plane of starts, the map of attractors_job.hpp over the starts from rest
// (x0-psi) or over starting positions and velocities (x0-u0).

#include <string>
#include <variant>
#include <vector>

#include "capsubot/job/attractors_job.hpp"
#include "capsubot/model/setting_names.hpp"

namespace capsubot {

/// Starts from rest: the inner body at x0 = (i + 0.5)/n_x, forcing phase psi = tau j/n_psi
/// (GridStarts, as `capsubot attractors`).
struct RestPlane {};

/// Starts in the x0-u0 plane: the inner body at x0 = (i + 0.5)/n_x with relative velocity
/// u0 = u_min + (j + 0.5)(u_max - u_min)/n_psi, the capsule at rest, at forcing phase psi.
struct VelocityPlane {
  double psi = 0.0;     ///< forcing phase of every start [rad]; finite (checked with the starts)
  double u_min = -1.0;  ///< smallest u0 of the plane (units of omega L); u_min < u_max
  double u_max = 1.0;   ///< largest u0 of the plane
};

/// The plane of the starts of a basin map.
using StartPlane = std::variant<RestPlane, VelocityPlane>;

/// "x0-psi" or "x0-u0".
const char* StartPlaneName(const StartPlane& plane);

/// The plane called `name` ("x0-psi" or "x0-u0"), the latter with the starts of `velocity`.
/// Throws std::invalid_argument, in `names`, for another name ("plane = ... is invalid") and for
/// velocity.u_min >= velocity.u_max in either plane (a bad range is never accepted unchecked).
StartPlane StartPlaneNamed(const std::string& name, const VelocityPlane& velocity,
                           const SettingNames& names = {});

struct BasinsJobOptions {
  /// The robot, the grid (n_x positions x n_psi phases or velocities), the motions and how
  /// the map is run, as for the attractors from rest.
  AttractorsJobOptions map;
  StartPlane plane;  ///< x0-psi (default) or x0-u0

  /// Throws std::invalid_argument naming the first bad field, its value and the rule: the
  /// plane, then AttractorsJobOptions::Validate.
  void Validate() const;
};

struct BasinsJobResult {
  AttractorsJobResult map;  ///< the map: its options (as run), attractors or shard
  StartPlane plane;         ///< the plane of its starts
};

/// The starts of the map, in its order (x0 major): n_x * n_psi of them.
std::vector<PhaseState> BasinStarts(const BasinsJobOptions& options);

/// Runs the map of BasinStarts(options) as RunAttractorsJob runs the starts from rest (the
/// CSV's second column u0 in the x0-u0 plane). Throws as RunAttractorsJob.
BasinsJobResult RunBasinsJob(const BasinsJobOptions& options);

/// The work RunBasinsJob(options) hands to its backend (AttractorsJobWork).
StartMapWork BasinsJobWork(const BasinsJobOptions& options);

}  // namespace capsubot
