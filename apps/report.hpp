#pragma once
// How an orbit is shown: one JSON object (for tools) or a table (for people).

#include <nlohmann/json.hpp>
#include <string>

#include "capsubot/model/energy.hpp"
#include "capsubot/orbit/stability.hpp"
#include "capsubot/orbit/validity.hpp"
#include "capsubot/report/solution_json.hpp"

namespace capsubot::app {

// The JSON of an orbit is the shared layer's (src/report/), the same for the Python module.
using json::AddEnergyJson;
using json::AddStabilityJson;
using json::SolutionJson;

/// A number in a text table with `digits` significant digits; a missing value (NaN) is "-"
/// everywhere (JSON writes it as null, CSV as an empty cell).
std::string Num(double value, int digits = 10);

/// The same with `decimals` digits after the point (aligned columns); NaN is "-".
std::string NumFixed(double value, int decimals);

/// The force as a formula: "0.5 sin(phi - 2.9449) + 0.5".
std::string ForceFormula(const Forcing& forcing);

/// A readable multi-line summary of a solved orbit.
std::string SolutionTable(const Solution& solution, const Params& params);

/// Readable lines on the energy budget per period.
std::string EnergyTable(const Energy& energy);

/// Readable lines on the stability (multipliers, spectral radius, verdict).
std::string StabilityTable(const Stability& stability);

}  // namespace capsubot::app
