#include "capsubot/report/periodic_json.hpp"

#include "capsubot/report/attractors_json.hpp"
#include "capsubot/report/forcing_json.hpp"

namespace capsubot::json {

nlohmann::json PeriodicJson(const PeriodicMotion& m) {
  nlohmann::json j = MotionCountsJson(ShootingStatusName(m.status), m);
  j["state"] = {{"x", m.state.x}, {"u", m.state.u}, {"v", m.state.v}, {"psi", m.state.psi}};
  j["mode"] = SimModeName(m.mode);
  j["dimension"] = m.dimension;
  j["multipliers"] = nlohmann::json::array();
  for (const auto& l : m.multipliers) j["multipliers"].push_back({l.real(), l.imag()});
  j["spectral_radius"] = m.spectral_radius;
  j["stable"] = m.stable;
  j["distance_to_plus_one"] = m.distance_to_plus_one;
  j["distance_to_minus_one"] = m.distance_to_minus_one;
  j["distance_to_unit_circle"] = m.distance_to_unit_circle;
  j["residual"] = m.residual;
  j["iterations"] = m.iterations;
  return j;
}

nlohmann::json PeriodicJobJson(const PeriodicJobResult& result) {
  return WithForceJson(PeriodicJson(result.motion), result.options.robot.forcing);
}

}  // namespace capsubot::json
