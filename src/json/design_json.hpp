#pragma once
// A robot designed in SI units (docs/design.md) as JSON: the object of `capsubot design
// --json`, as the Python module's design returns it, and the gait's numbers in the order of
// the columns of `capsubot design --sweep`.

#include <nlohmann/json.hpp>
#include <utility>
#include <vector>

#include "capsubot/design.hpp"

namespace capsubot::json {

/// The gait's numbers in the user's units (m2_kg, frequency_hz, speed_mm_s, ...), in the
/// order of the CSV columns and JSON keys.
std::vector<std::pair<const char*, double>> UserUnits(const Gait& gait);

/// The dimensionless orbit of an ok gait (T0, A, c, alpha, phi0, I, spectral_radius, x_min,
/// x_max; NaN otherwise), for JSON and CSV.
std::vector<std::pair<const char*, double>> Dimensionless(const Gait& gait);

/// The gait: "status", the user's units, "dimensionless" {Dimensionless, cos and sin for a
/// Fourier force, energy when ok}, "orbits", "binding".
nlohmann::json GaitJson(const Gait& gait);

/// The design: {"status", "message", "one_impact" (GaitJson), "robots", "complete"}.
nlohmann::json DesignJson(const DesignResult& result);

}  // namespace capsubot::json
