#include "capsubot/report/attractors_json.hpp"

#include "capsubot/report/forcing_json.hpp"

namespace capsubot::json {

nlohmann::json MotionJson(const Motion& m) {
  return MotionCountsJson(MotionStatusName(m.status), m);
}

nlohmann::json AttractorsJson(const Attractors& a) {
  nlohmann::json j;
  j["starts"] = a.starts;
  j["attractors"] = nlohmann::json::array();
  for (const Attractor& at : a.attractors) {
    nlohmann::json x = MotionJson(at.motion);
    x["fraction"] = at.fraction;
    x["starts"] = at.starts;
    x["example_start"] = {{"x0", at.example.x}, {"psi", at.example.psi}};
    x["one_impact_orbit"] = at.one_impact_orbit;
    x["mean_velocity"] = at.mean_velocity;  // over its starts
    x["velocity_min"] = at.velocity_min;
    x["velocity_max"] = at.velocity_max;
    if (at.motion.status == MotionStatus::kNoPeriod) {
      x["halves_difference"] = at.halves_difference;
    }
    j["attractors"].push_back(x);
  }
  j["mean_velocity"] = a.mean_velocity;
  j["event_limit_starts"] = a.event_limit_starts;
  return j;
}

nlohmann::json AttractorsJobJson(const AttractorsJobResult& result) {
  return WithForceJson(AttractorsJson(result.attractors), result.options.robot.forcing);
}

nlohmann::json BasinsJobJson(const BasinsJobResult& result) {
  return AttractorsJobJson(result.map);
}

nlohmann::json FromRestJson(const GaitFromRest& r) {
  if (!r.checked) return nullptr;
  nlohmann::json j = AttractorsJson(r.attractors);
  j["reached"] = r.reached;
  j["summary"] = r.summary;
  return j;
}

}  // namespace capsubot::json
