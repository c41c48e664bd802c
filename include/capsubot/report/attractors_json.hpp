#pragma once
// The long-run motions from rest as JSON (docs/model.md sections 12 and 13): the objects of
// `capsubot attractors --json` and the `from_rest` check of a gait, as the command line prints
// them and the Python module returns them.

#include <nlohmann/json.hpp>

#include "capsubot/attract/attractors.hpp"
#include "capsubot/attract/gait_from_rest.hpp"
#include "capsubot/job/attractors_job.hpp"
#include "capsubot/job/basins_job.hpp"

namespace capsubot::json {

/// {"status", "period", "impacts_right", "impacts_left", "mean_velocity"}: what a motion of
/// any kind says of itself (a Motion of the map, a PeriodicMotion found by shooting), with its
/// status named `status`; NaN is written as null.
template <class AnyMotion>
nlohmann::json MotionCountsJson(const char* status, const AnyMotion& m) {
  return {{"status", status},
          {"period", m.period},
          {"impacts_right", m.impacts_right},
          {"impacts_left", m.impacts_left},
          {"mean_velocity", m.mean_velocity}};
}

/// MotionCountsJson of a motion of the map (null for what was not found).
nlohmann::json MotionJson(const Motion& motion);

/// The attractors object: {"starts", "attractors": [...], "mean_velocity",
/// "event_limit_starts"}; each attractor is a MotionJson with "fraction", "starts",
/// "example_start" {"x0", "psi"} and "one_impact_orbit".
nlohmann::json AttractorsJson(const Attractors& attractors);

/// What `capsubot attractors --json` prints (without provenance): AttractorsJson of the whole
/// map's attractors, with "force" (ForcingJson).
nlohmann::json AttractorsJobJson(const AttractorsJobResult& result);

/// What `capsubot basins --json` prints (without provenance): the same object.
nlohmann::json BasinsJobJson(const BasinsJobResult& result);

/// The `from_rest` object: the attractors object plus "reached" and "summary"; null when the
/// gait was not checked (no orbit).
nlohmann::json FromRestJson(const GaitFromRest& report);

}  // namespace capsubot::json
