#include "capsubot/report/forcing_json.hpp"

#include <vector>

namespace capsubot::json {

nlohmann::json ForcingJson(const Forcing& f) {
  nlohmann::json j;
  if (f.pulse()) {
    std::vector<double> levels, switches;
    for (int i = 0; i < f.pulse_levels(); ++i) {
      levels.push_back(f.level(i));
      switches.push_back(f.switch_phase(i));
    }
    j["waveform"] = "pulse";
    j["levels"] = levels;
    j["switches"] = switches;
  } else if (f.harmonic()) {
    j["waveform"] = "sine";
    j["A"] = f.amplitude();
    j["c"] = f.mean();
  } else {
    std::vector<double> a, b;
    for (int k = 1; k <= f.harmonics(); ++k) {
      a.push_back(f.a(k));
      b.push_back(f.b(k));
    }
    j["waveform"] = "fourier";
    j["c"] = f.mean();
    j["cos"] = a;
    j["sin"] = b;
  }
  j["phi0"] = f.phi0();
  return j;
}

nlohmann::json WithForceJson(nlohmann::json j, const Forcing& forcing) {
  j["force"] = ForcingJson(forcing);
  return j;
}

}  // namespace capsubot::json
