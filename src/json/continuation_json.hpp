#pragma once
// A branch of periodic motions (docs/continuation.md) as JSON: the object of
// `capsubot continue --json`.

#include <nlohmann/json.hpp>
#include <string>

#include "capsubot/continue/continuation.hpp"

namespace capsubot::json {

/// {"parameter": name, "status", "message", "start_index", "ends": {"lower": {"end", name},
/// "upper": {...}}, "points": [{name, "arclength", "x", "u", "v", "psi", "mode", "period",
/// "impacts_right", "impacts_left", "mean_velocity", "spectral_radius", "multipliers" [[re,
/// im], ...], "stable", "label"}], "special_points": [{"type", name, "located", "accuracy",
/// "mean_velocity", "period", "impacts_right", "impacts_left", "state" {x, u, v, psi},
/// "multipliers", "stable"}]}; `name` is the parameter's name.
nlohmann::json BranchJson(const Branch& branch, const std::string& name);

}  // namespace capsubot::json
