#include "capsubot/report/optimize_json.hpp"

#include <cmath>
#include <string>
#include <vector>

#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/report/attractors_json.hpp"
#include "capsubot/report/continuation_json.hpp"
#include "capsubot/report/solution_json.hpp"

namespace capsubot::json {
namespace {

std::vector<std::string> BindingNames(const OptimizeResult& r) {
  std::vector<std::string> names;
  for (Margin m : r.binding) names.emplace_back(MarginName(m));
  return names;
}

}  // namespace

nlohmann::json OptimizeResultJson(const OptimizeResult& r, const char* problem) {
  const Forcing& f = r.solution.orbit.forcing;
  nlohmann::json j = SolutionJson(r.solution);
  j["problem"] = problem;
  j["status"] = OptimizeStatusName(r.status);
  j["message"] = r.message;
  j["active_constraints"] = r.active_constraints;
  j["binding"] = BindingNames(r);
  j["evaluations"] = r.evaluations;
  j["algorithm"] = r.algorithm;
  if (!std::isnan(r.spectral_radius)) {
    j["spectral_radius"] = r.spectral_radius;
    j["stable"] = r.spectral_radius < 1.0;
  }
  if (!f.harmonic()) {
    j["coefficients"] = {{"c", f.mean()}, {"cos", j["cos"]}, {"sin", j["sin"]}};
  }
  return j;
}

void AddRequirementsJson(nlohmann::json& j, const Params& p, const GaitRequirements& gait) {
  j["T0"] = p.T0;
  j["e"] = p.e;
  j["margin"] = gait.margins.clearance;
  j["margin_stroke"] = gait.margins.clearance_stroke;
  j["stick_margin"] = gait.margins.stick;
  j["rho_max"] = gait.rho_max;  // nlohmann::json writes infinity as null
}

namespace {

nlohmann::json Json(const ProblemJobResult& pr) {
  const OptimizeResult& r = pr.result;
  nlohmann::json j = OptimizeResultJson(r, pr.problem.c_str());
  j["from_rest"] = FromRestJson(pr.from_rest);
  AddRequirementsJson(j, pr.params, pr.gait);
  if (pr.problem == "fourier") {
    j["baseline_I"] = r.baseline_I;
    j["gain"] = r.found() ? r.solution.orbit.I / r.baseline_I - 1.0 : kNaN;
  }
  return j;
}

// The winner's drive as the force flags name it: the mean c, the series --cos and --sin (base
// coefficients in the motor phase) and phi0, the motor phase at phi = 0.
nlohmann::json DriveJson(const ReachResult& r) {
  const Forcing& f = r.forcing;
  if (f.pulse()) {
    std::vector<double> levels, switches;
    for (int j = 0; j < f.pulse_levels(); ++j) {
      levels.push_back(f.level(j));
      switches.push_back(f.switch_phase(j));
    }
    return {{"waveform", "pulse"}, {"levels", levels}, {"switches", switches}, {"phi0", f.phi0()}};
  }
  std::vector<double> a, b;
  for (int k = 1; k <= f.harmonics(); ++k) {
    a.push_back(f.a(k));
    b.push_back(f.b(k));
  }
  return {{"waveform", WaveformName(r.drive.waveform)},
          {"harmonics", f.harmonics()},
          {"c", f.mean()},
          {"cos", a},
          {"sin", b},
          {"phi0", f.phi0()}};
}

nlohmann::json ReachJson(const ReachResult& r) {
  const bool found = !std::isnan(r.mean_velocity);
  nlohmann::json j;
  j["status"] = OptimizeStatusName(r.status);
  j["message"] = r.message;
  if (r.drive.sine()) {
    j["A"] = found ? r.forcing.amplitude() : kNaN;
    j["c"] = found ? r.forcing.mean() : kNaN;
    j["phi0"] = found ? r.forcing.phi0() : kNaN;
  }
  j["drive"] = found ? DriveJson(r) : nlohmann::json(nullptr);
  j["force_bound"] = r.force_bound;
  j["max_abs_force"] = r.max_abs_force;
  if (!std::isnan(r.physical_speed)) {
    j["frequency"] = {{"T0", r.T0}, {"physical_speed", r.physical_speed}};
  }
  j["alpha"] = r.alpha;
  j["mean_velocity"] = r.mean_velocity;
  j["attractors"] = found ? AttractorsJson(r.attractors) : nlohmann::json(nullptr);
  j["summary"] = r.summary;
  j["spread"] = {{"chatter_small", r.spread.chatter_small},
                 {"chatter_large", r.spread.chatter_large},
                 {"e_0999", r.spread.e_0999},
                 {"max_relative_deviation", r.spread.max_relative_deviation},
                 {"event_limit_starts", r.spread.event_limit_starts}};
  j["seed_won"] = r.seed_won;
  j["robust_to_settings"] = r.robust_to_settings;
  j["evaluations"] = r.evaluations;
  j["rejected_evaluations"] = r.rejected_evaluations;
  j["algorithm"] = r.algorithm;
  const Orbit& seed_orbit = r.seed.gait.solution.orbit;
  if (r.seed.from_rest.checked) {
    j["seed"] = {{"A", seed_orbit.forcing.amplitude()},
                 {"c", seed_orbit.forcing.mean()},
                 {"phi0", seed_orbit.forcing.phi0()},
                 {"alpha", seed_orbit.alpha},
                 {"I", seed_orbit.I},
                 {"v_mean", seed_orbit.v_mean},
                 {"mean_velocity_from_rest", r.seed.from_rest.attractors.mean_velocity},
                 {"reached", r.seed.from_rest.reached}};
  } else {
    j["seed"] = nullptr;
  }
  return j;
}

// The winners of a drive ladder, K = 1 (the sine) first, each with its speed against the sine's.
nlohmann::json LadderJson(const std::vector<ReachResult>& ladder) {
  nlohmann::json j = nlohmann::json::array();
  if (ladder.empty()) return j;
  const double sine = ladder.front().mean_velocity;
  for (const ReachResult& step : ladder) {
    const bool found = !std::isnan(step.mean_velocity);
    j.push_back({{"waveform", WaveformName(step.drive.waveform)},
                 {"harmonics", step.drive.sine() ? 1 : step.drive.harmonics},
                 {"mean_velocity", step.mean_velocity},
                 {"speed_ratio_to_sine", step.mean_velocity / sine},
                 {"alpha", step.alpha},
                 {"max_abs_force", step.max_abs_force},
                 {"drive", found ? DriveJson(step) : nlohmann::json(nullptr)},
                 {"attractors", found ? AttractorsJson(step.attractors) : nlohmann::json(nullptr)},
                 {"summary", step.summary},
                 {"robust_to_settings", step.robust_to_settings},
                 {"status", OptimizeStatusName(step.status)}});
  }
  return j;
}

nlohmann::json Json(const ReachJobResult& r) {
  nlohmann::json j = ReachJson(r.reach);
  AddRequirementsJson(j, r.params, r.gait);
  if (r.ladder.empty()) return j;
  j["speed_ratio_to_sine"] = r.reach.mean_velocity / r.ladder.front().mean_velocity;
  j["ladder"] = LadderJson(r.ladder);
  return j;
}

nlohmann::json Json(const MainJobResult& r) {
  nlohmann::json j;
  AddRequirementsJson(j, r.params, r.gait);
  j["force_bound"] = r.gait.force_bound;
  j["paper"] = OptimizeResultJson(r.paper, "phase");
  j["paper"]["note"] =
      "P1: F = A sin(phi + phi0) + c with c = A = T0/2, best phi0 over valid orbits (no margins)";
  j["robust"] = OptimizeResultJson(r.robust, "forcing");
  j["robust"]["note"] =
      "P2: A, c, phi0 free with A + c <= force_bound, the margins and spectral radius <= "
      "rho_max; checked from rest";
  j["robust"]["from_rest"] = FromRestJson(r.reach.seed.from_rest);
  j["reach"] = ReachJson(r.reach);
  j["reach"]["robustness"] =
      r.reach_robustness.parameters.empty() ? nlohmann::json() : RobustnessJson(r.reach_robustness);
  j["drives"] = LadderJson(r.drives);
  j["pulse"] = ReachJson(r.pulse);
  j["fastest"] = OptimizeResultJson(r.fastest, "forcing");
  j["fastest"]["note"] = "P2 without margins or stability requirement: grazes the walls";
  j["fastest_stable"] = OptimizeResultJson(r.stable, "forcing");
  j["fastest_stable"]["note"] = "P2 without margins, spectral radius <= 1";
  j["robustness"] =
      r.robustness.parameters.empty() ? nlohmann::json() : RobustnessJson(r.robustness);
  return j;
}

}  // namespace

nlohmann::json OptimizeJobJson(const OptimizeJobResult& result) {
  return std::visit([](const auto& r) { return Json(r); }, result);
}

}  // namespace capsubot::json
