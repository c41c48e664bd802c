#pragma once
// The numbers a design reports of a gait or of a motion from rest, named and in a fixed order:
// the keys of their JSON (src/report/design_json.cpp) and the result columns of a design grid's
// CSV (the job of `capsubot design --grid`).

#include <utility>
#include <vector>

#include "capsubot/design/design.hpp"

namespace capsubot {

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

}  // namespace capsubot
