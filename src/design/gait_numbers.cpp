#include "capsubot/design/gait_numbers.hpp"

namespace capsubot {

std::vector<std::pair<const char*, double>> Dimensionless(const Gait& g) {
  const bool ok = g.ok();
  const Orbit& o = g.solution.orbit;
  const Forcing& f = o.forcing;
  const double nan = kNaN;
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

}  // namespace capsubot
