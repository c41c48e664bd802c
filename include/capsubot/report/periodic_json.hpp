#pragma once
// A periodic motion found by Newton shooting (docs/model.md section 13) as JSON: the object of
// `capsubot periodic --json`, as the Python module's periodic returns it.

#include <nlohmann/json.hpp>

#include "capsubot/attract/periodic.hpp"
#include "capsubot/job/periodic_job.hpp"

namespace capsubot::json {

/// {"status", "period", "impacts_right", "impacts_left", "mean_velocity", "state" {x, u, v,
/// psi}, "mode", "dimension", "multipliers" [[re, im], ...], "spectral_radius", "stable",
/// "distance_to_plus_one", "distance_to_minus_one", "distance_to_unit_circle", "residual",
/// "iterations"}.
nlohmann::json PeriodicJson(const PeriodicMotion& motion);

/// What `capsubot periodic --json` prints (without provenance): PeriodicJson of the motion, with
/// "force" (ForcingJson).
nlohmann::json PeriodicJobJson(const PeriodicJobResult& result);

}  // namespace capsubot::json
