#pragma once
// How an orbit is shown: one JSON object (for tools) or a table (for people).

#include <nlohmann/json.hpp>
#include <string>

#include "capsubot/stability.hpp"
#include "capsubot/validity.hpp"

namespace capsubot::app {

/// JSON of a solved orbit: A, c, phi0, T0, e, phi1, alpha, u, v_plus, I, v_mean, x_min,
/// x_max, stroke, clearance, valid, violations (null for what does not exist); "cos"/"sin" for
/// a Fourier force.
nlohmann::json SolutionJson(const Solution& solution);

/// The force as a formula: "0.5 sin(phi - 2.9449) + 0.5".
std::string ForceFormula(const Forcing& forcing);

/// A readable multi-line summary of a solved orbit.
std::string SolutionTable(const Solution& solution, const Params& params);

/// Adds the stability of docs/model.md section 8 to a JSON object: "multipliers" (array of
/// {"re", "im"}), "spectral_radius" and "stable" (null, null, false when not computed).
void AddStabilityJson(nlohmann::json& j, const Stability& stability);

/// Readable lines on the stability (multipliers, spectral radius, verdict).
std::string StabilityTable(const Stability& stability);

}  // namespace capsubot::app
