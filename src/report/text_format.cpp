// Numbers and the force in the plain-text reports.

#include "capsubot/report/text_format.hpp"

#include <fmt/format.h>

#include <cmath>

namespace capsubot::text {

std::string Num(double value, int digits) {
  return std::isnan(value) ? "-" : fmt::format("{:.{}g}", value, digits);
}

std::string XMaxText(double x_max, int digits) {
  return std::isnan(x_max) ? "1 at the impact (no interior maximum)" : Num(x_max, digits);
}

std::string NumFixed(double value, int decimals) {
  return std::isnan(value) ? "-" : fmt::format("{:.{}f}", value, decimals);
}

std::string ForceFormula(const Forcing& f) {
  if (f.pulse()) {  // G = L_j on [s_j, s_j+1) of the motor phase t
    std::string s = "F(phi) = G(t), G =";
    for (int j = 0; j < f.pulse_levels(); ++j) {
      s += fmt::format("{} {:.6g} from t = {:.6g}", j == 0 ? "" : ",", f.level(j),
                       f.switch_phase(j));
    }
    return s + fmt::format(",  t = phi + {:.6g}", f.phi0());
  }
  if (f.harmonic()) {
    return fmt::format("F(phi) = {:.6g} sin(phi {} {:.6g}) + {:.6g}", f.amplitude(),
                       f.phi0() < 0 ? '-' : '+', std::abs(f.phi0()), f.mean());
  }
  std::string s = fmt::format("F(phi) = {:.6g}", f.mean());
  for (int k = 1; k <= f.harmonics(); ++k) {
    s += fmt::format(" + {:.6g} cos {}t + {:.6g} sin {}t", f.a(k), k, f.b(k), k);
  }
  return s + fmt::format(",  t = phi + {:.6g}", f.phi0());
}

}  // namespace capsubot::text
