#include "json/design_json.hpp"

#include "json/solution_json.hpp"

namespace capsubot::json {

std::vector<std::pair<const char*, double>> UserUnits(const Gait& g) {
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

std::vector<std::pair<const char*, double>> Dimensionless(const Gait& g) {
  const bool ok = g.ok();
  const Orbit& o = g.solution.orbit;
  const Forcing& f = o.forcing;
  const double nan = Gait::kNaN;
  return {{"T0", ok ? o.T0 : nan},
          {"A", ok && f.harmonic() ? f.amplitude() : nan},
          {"c", ok ? f.mean() : nan},
          {"alpha", ok ? o.alpha : nan},
          {"phi0", ok ? f.phi0() : nan},
          {"I", ok ? o.I : nan},
          {"spectral_radius", ok ? g.stability.spectral_radius : nan},
          {"x_min", ok ? g.solution.validity.x_min : nan},
          {"x_max", ok ? g.solution.validity.x_max : nan}};
}

nlohmann::json GaitJson(const Gait& g) {
  nlohmann::json j;
  j["status"] = GaitStatusName(g.status);
  for (const auto& [key, value] : UserUnits(g)) j[key] = value;  // NaN is written as null
  nlohmann::json d;
  for (const auto& [key, value] : Dimensionless(g)) d[key] = value;
  if (g.ok() && !g.solution.orbit.forcing.harmonic()) {
    const Forcing& f = g.solution.orbit.forcing;
    std::vector<double> a, b;
    for (int k = 1; k <= f.harmonics(); ++k) {
      a.push_back(f.a(k));
      b.push_back(f.b(k));
    }
    d["cos"] = a;
    d["sin"] = b;
  }
  if (g.ok()) AddEnergyJson(d, g.energy);
  j["dimensionless"] = d;
  j["orbits"] = g.orbits;
  j["binding"] = g.binding;
  return j;
}

nlohmann::json DesignJson(const DesignResult& r) {
  nlohmann::json j;
  j["status"] = DesignStatusName(r.status);
  j["message"] = r.message;
  j["one_impact"] = GaitJson(r.one_impact);
  j["robots"] = r.robots;
  j["complete"] = r.complete;
  return j;
}

}  // namespace capsubot::json
