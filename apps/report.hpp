#pragma once
// How an orbit is shown: one JSON object (for tools) or a table (for people).

#include <nlohmann/json.hpp>
#include <string>

#include "capsubot/energy.hpp"
#include "capsubot/stability.hpp"
#include "capsubot/validity.hpp"

namespace capsubot::app {

/// A number in a text table with `digits` significant digits; a missing value (NaN) is "-"
/// everywhere (JSON writes it as null, CSV as an empty cell).
std::string Num(double value, int digits = 10);

/// The same with `decimals` digits after the point (aligned columns); NaN is "-".
std::string NumFixed(double value, int decimals);

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

/// Adds the energy budget of docs/model.md section 11 to a JSON object: "energy" with the keys
/// motor_work, motor_work_positive, friction_loss, impact_loss (dimensionless, per period;
/// null when not computed).
void AddEnergyJson(nlohmann::json& j, const Energy& energy);

/// Readable lines on the energy budget per period.
std::string EnergyTable(const Energy& energy);

/// Readable lines on the stability (multipliers, spectral radius, verdict).
std::string StabilityTable(const Stability& stability);

}  // namespace capsubot::app
