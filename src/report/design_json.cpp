#include "capsubot/report/design_json.hpp"

#include <cmath>

#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/report/attractors_json.hpp"
#include "capsubot/report/continuation_json.hpp"
#include "capsubot/report/forcing_json.hpp"
#include "capsubot/report/solution_json.hpp"

namespace capsubot::json {

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

// The attractors with the speed of each in mm/s (`mm_s`: mm/s per omega L).
nlohmann::json AttractorsSiJson(const Attractors& attractors, double mm_s) {
  nlohmann::json a = AttractorsJson(attractors);
  for (std::size_t k = 0; k < attractors.attractors.size(); ++k) {
    a["attractors"][k]["speed_mm_s"] = mm_s * attractors.attractors[k].mean_velocity;
  }
  return a;
}

namespace {

// One direction's motion from rest in the user's units, with its dimensionless robot.
nlohmann::json DirectionJson(const DesignInput& in, const FromRestBest* b) {
  const double nan = kNaN;
  nlohmann::json j;
  j["status"] = FromRestStatusName(b->status);
  j["message"] = b->message;
  for (const auto& [key, value] : UserUnits(*b)) j[key] = value;  // NaN is written as null
  const DesignModel& m = b->model;
  const bool ran = b->status != FromRestStatus::kNotRun;
  nlohmann::json d;
  d["T0"] = ran ? m.robot.params.T0 : nan;
  d["A"] = ran && m.robot.forcing.harmonic() ? m.robot.forcing.amplitude() : nan;
  d["c"] = ran ? m.robot.forcing.mean() : nan;
  d["alpha"] = ran ? m.robot.alpha : nan;
  d["phi0"] = nan;  // no single impact phase: the starts cover every motor phase
  d["mean_velocity"] = b->mean_velocity;
  if (b->ok()) AddEnergyJson(d, b->energy);
  j["dimensionless"] = d;
  j["forward_fraction"] = b->forward_fraction;
  j["backward_fraction"] = b->backward_fraction;
  j["attractors"] = AttractorsSiJson(b->attractors, 1e3 * m.omega * in.L);
  return j;
}

// A drive in newtons: {"c", "cos", "sin"} or {"levels", "switches"}, and "max_abs".
nlohmann::json DriveForceJson(const DriveForce& d) {
  nlohmann::json j;
  j["c"] = d.mean;
  if (d.levels.empty()) {
    j["cos"] = d.cos;
    j["sin"] = d.sin;
  } else {
    j["levels"] = d.levels;
    j["switches"] = d.switches;
  }
  j["max_abs"] = d.max_abs;
  return j;
}

nlohmann::json DriveDesignJson(const DesignInput& in, const DriveDesignResult& r) {
  nlohmann::json j;
  j["status"] = r.found() ? "ok" : "no_motion";
  j["message"] = r.message;
  const ReachResult& best = r.reach();
  j["drive"] = best.drive.Describe();
  j["force_n"] = DriveForceJson(r.force);
  j["backward_force_n"] = DriveForceJson(r.backward_force);
  j["forward"] = DirectionJson(in, &r.forward);
  j["backward"] = DirectionJson(in, &r.backward);
  j["forward"]["dimensionless"]["force"] = ForcingJson(best.forcing);
  nlohmann::json ladder = nlohmann::json::array();
  for (const ReachResult& step : r.ladder) {
    ladder.push_back({{"drive", step.drive.Describe()},
                      {"T0", step.T0},
                      {"alpha", step.alpha},
                      {"mean_velocity", step.mean_velocity},
                      {"speed_sqrt_mu_g_L", step.mean_velocity / std::sqrt(step.T0)},
                      {"robust_to_settings", step.robust_to_settings}});
  }
  j["ladder"] = ladder;
  return j;
}

}  // namespace

nlohmann::json FromRestBestJson(const DesignInput& in, const DesignFromRestResult& r) {
  nlohmann::json out;
  for (const FromRestBest* b : {&r.forward, &r.backward})
    out[DirectionName(b->direction)] = DirectionJson(in, b);
  out["evaluations"] = r.evaluations;
  out["rejected_evaluations"] = r.rejected_evaluations;
  out["max_time"] = r.max_time;
  return out;
}

nlohmann::json DesignJobJson(const DesignJobResult& r) {
  if (r.drive) return {{"drive_design", DriveDesignJson(r.input, *r.drive)}};
  nlohmann::json j = DesignJson(r.design);
  j["robustness"] =
      r.robustness.parameters.empty() ? nlohmann::json() : RobustnessJson(r.robustness);
  if (r.gait_from_rest.checked) {
    const Gait& g = r.design.one_impact;
    nlohmann::json fr = FromRestJson(r.gait_from_rest);
    fr.update(AttractorsSiJson(r.gait_from_rest.attractors, 1e3 * g.model.omega * r.input.L));
    j["one_impact"]["from_rest"] = fr;
    j["one_impact"]["speed_from_rest_mm_s"] = GaitSpeedFromRest(r);
  }
  if (r.from_rest) j["from_rest_best"] = FromRestBestJson(r.input, *r.from_rest);
  if (!r.grid) j["build"] = DesignChoiceName(ChooseDesign(r));
  return j;
}

}  // namespace capsubot::json
