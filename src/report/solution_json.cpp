#include "capsubot/report/solution_json.hpp"

#include "capsubot/orbit/orbit_energy.hpp"
#include "capsubot/report/attractors_json.hpp"
#include "capsubot/report/forcing_json.hpp"

namespace capsubot::json {

nlohmann::json SolutionJson(const Solution& s) {
  const Orbit& o = s.orbit;
  const Validity& v = s.validity;
  const Forcing& f = o.forcing;
  nlohmann::json j = ForcingJson(f);
  if (!f.harmonic() && !f.pulse()) j["A"] = nullptr;  // a Fourier force has no one amplitude
  j["T0"] = o.T0;
  j["e"] = o.e;
  j["status"] = StatusName(o.status);
  // nlohmann::json writes NaN as null: a quantity that does not exist is null.
  j["phi1"] = o.phi1;
  j["alpha"] = o.alpha;
  j["u"] = o.u;
  j["v_plus"] = o.v_plus;
  j["I"] = o.I;
  j["v_mean"] = o.v_mean;
  j["x_min"] = v.x_min;
  j["x_max"] = v.x_max;
  j["stroke"] = v.stroke;
  j["clearance"] = v.clearance;
  j["valid"] = v.valid();
  j["violations"] = v.ViolationNames();
  return j;
}

void AddStabilityJson(nlohmann::json& j, const Stability& st) {
  if (!st.computed) {
    j["multipliers"] = nullptr;
    j["spectral_radius"] = nullptr;
    j["stable"] = false;
    return;
  }
  nlohmann::json m = nlohmann::json::array();
  for (const auto& z : st.multipliers) m.push_back({{"re", z.real()}, {"im", z.imag()}});
  j["multipliers"] = m;
  j["spectral_radius"] = st.spectral_radius;
  j["stable"] = st.stable;
}

void AddEnergyJson(nlohmann::json& j, const Energy& en) {
  j["energy"] = {{"motor_work", en.motor_work},
                 {"motor_work_positive", en.motor_work_positive},
                 {"friction_loss", en.friction_loss},
                 {"impact_loss", en.impact_loss}};
}

nlohmann::json SolveJobJson(const SolveJobResult& r) {
  nlohmann::json j = SolutionJson(r.solution);
  AddEnergyJson(j, r.energy);
  if (r.options.stability) {
    AddStabilityJson(j, r.stability);
    j["from_rest"] = FromRestJson(r.from_rest);
  }
  return j;
}

nlohmann::json RobotOrbitsJson(const std::vector<Solution>& orbits, bool complete) {
  nlohmann::json all = nlohmann::json::array();
  for (const Solution& s : orbits) {
    nlohmann::json j = SolutionJson(s);
    AddEnergyJson(j, OrbitEnergy(s.orbit));
    AddStabilityJson(j, ComputeStability(s.orbit));
    j["complete"] = complete;
    all.push_back(j);
  }
  return all;
}

nlohmann::json OrbitsJobJson(const OrbitsJobResult& result) {
  return {{"orbits", RobotOrbitsJson(result.orbits, result.complete)}};
}

}  // namespace capsubot::json
