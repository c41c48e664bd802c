#pragma once
// A branch of periodic motions (docs/continuation.md) as JSON: the object of
// `capsubot continue --json`.

#include <nlohmann/json.hpp>
#include <string>

#include "capsubot/continue/continuation.hpp"
#include "capsubot/continue/gait_robustness.hpp"
#include "capsubot/job/continue_job.hpp"

namespace capsubot::json {

/// {"parameter": name, "status", "message", "start_index", "ends": {"lower": {"end", name},
/// "upper": {...}}, "points": [{name, "arclength", "x", "u", "v", "psi", "mode", "period",
/// "impacts_right", "impacts_left", "mean_velocity", "spectral_radius", "multipliers" [[re,
/// im], ...], "stable", "label"}], "special_points": [{"type", name, "located", "accuracy",
/// "mean_velocity", "period", "impacts_right", "impacts_left", "state" {x, u, v, psi},
/// "multipliers", "stable"}]}; `name` is the parameter's name.
nlohmann::json BranchJson(const Branch& branch, const std::string& name);

/// The object of `capsubot continue --json` (the provenance aside): BranchJson(result.branch,
/// param); with switch_at "switched": BranchJson of the branch switched to (null without a
/// located period doubling, or without a grazing); with follow "follow": {"type", "parameter2",
/// "status", "message", "start" {param, param2}, "start_index", "ends": {"backward": {"end", param,
/// param2}, "forward": {...}}} and "curve": [{param, param2, "arclength", "condition", "x", "u",
/// "v", "psi", "mode", "period", "impacts_right", "impacts_left", "mean_velocity",
/// "spectral_radius", "multipliers" [[re, im], ...], "stable"}].
nlohmann::json ContinueJobJson(const ContinueJobResult& result);

/// {name: {"value", "from", "to", "status", "message", "down": limit, "up": limit}} for T0, e,
/// alpha, each limit {"type": a special point's type or the branch end's ("range_end",
/// "lost", "max_points"), name: its value, "located", and for a special point "accuracy" and
/// "multipliers" [[re, im], ...]}.
nlohmann::json RobustnessJson(const GaitRobustness& robustness);

}  // namespace capsubot::json
