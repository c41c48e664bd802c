#pragma once
// A robot designed in SI units (docs/design.md) as JSON: the object of `capsubot design
// --json`, as the Python module's design returns it, and the gait's numbers in the order of
// the result columns of `capsubot design --grid`.

#include <nlohmann/json.hpp>
#include <utility>
#include <vector>

#include "capsubot/design/design.hpp"
#include "capsubot/design/design_from_rest.hpp"

namespace capsubot::json {

/// The numbers of a gait or of a motion from rest (Gait and FromRestBest share these fields)
/// in the user's units (m2_kg, frequency_hz, speed_mm_s, ...), in the order of the CSV
/// columns and JSON keys.
template <class Result>
std::vector<std::pair<const char*, double>> UserUnits(const Result& g) {
  return {{"m2_kg", g.m2_kg},
          {"frequency_hz", g.frequency_hz},
          {"speed_mm_s", g.speed_mm_s},
          {"displacement_mm", g.displacement_mm},
          {"impact_velocity_m_s", g.impact_velocity_m_s},
          {"energy_mj", g.energy_mj},
          {"power_mw", g.power_mw},
          {"power_positive_mw", g.power_positive_mw},
          {"friction_loss_mj", g.friction_loss_mj},
          {"impact_loss_mj", g.impact_loss_mj},
          {"cot", g.cot},
          {"efficiency", g.efficiency}};
}

/// The dimensionless orbit of an ok gait (T0, A, c, alpha, phi0, I, spectral_radius, x_min,
/// x_max; NaN otherwise), for JSON and CSV.
std::vector<std::pair<const char*, double>> Dimensionless(const Gait& gait);

/// The gait: "status", the user's units, "dimensionless" {Dimensionless, cos and sin for a
/// Fourier force, energy when ok}, "orbits", "binding".
nlohmann::json GaitJson(const Gait& gait);

/// The design: {"status", "message", "one_impact" (GaitJson), "robots", "complete"}.
nlohmann::json DesignJson(const DesignResult& result);

/// The `from_rest_best` object: {forward, backward} each with the SI keys of the one-impact
/// gait, dimensionless {T0, A, c, alpha, phi0}, fractions of the starts going each way and the
/// attractors (each with its speed in mm/s), then the cost of the search.
nlohmann::json FromRestBestJson(const DesignInput& input, const DesignFromRestResult& result);

}  // namespace capsubot::json
