#pragma once
// How numbers, forces and orbits read in the text reports: a number with its significant
// digits ("-" when missing), the force as a formula, the tables of an orbit, its energy budget
// and its stability.

#include <string>

#include "capsubot/model/energy.hpp"
#include "capsubot/model/forcing.hpp"
#include "capsubot/model/params.hpp"
#include "capsubot/orbit/stability.hpp"
#include "capsubot/orbit/validity.hpp"

namespace capsubot::report {

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

}  // namespace capsubot::report
