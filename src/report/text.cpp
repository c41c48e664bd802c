#include "capsubot/report/text.hpp"

#include <fmt/format.h>

#include <cmath>

namespace capsubot::report {

std::string Num(double value, int digits) {
  return std::isnan(value) ? "-" : fmt::format("{:.{}g}", value, digits);
}

std::string NumFixed(double value, int decimals) {
  return std::isnan(value) ? "-" : fmt::format("{:.{}f}", value, decimals);
}

std::string ForceFormula(const Forcing& f) {
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

std::string SolutionTable(const Solution& s, const Params& p) {
  const Orbit& o = s.orbit;
  const Validity& v = s.validity;
  std::string t;
  t += fmt::format("one-impact periodic orbit\n");
  t += fmt::format("  force            {}\n", ForceFormula(o.forcing));
  t += fmt::format("  model            T0 = {:g}, e = {:g}, margin = {:g}{}\n", p.T0, p.e, p.margin,
                   p.margin_stroke > 0.0 || p.stick_margin > 0.0
                       ? fmt::format(", margin_stroke = {:g}, stick_margin = {:g}", p.margin_stroke,
                                     p.stick_margin)
                       : std::string());
  t += fmt::format("  status           {}\n", StatusName(o.status));
  t += fmt::format("  stop phase       phi1   = {}\n", Num(o.phi1));
  t += fmt::format("  mass ratio       alpha  = {}   (m2/(m1+m2))\n", Num(o.alpha));
  t += fmt::format("  impact velocity  u      = {}   (omega L)\n", Num(o.u));
  t += fmt::format("  capsule kick     v_plus = {}   (omega L)\n", Num(o.v_plus));
  t += fmt::format("  step per period  I      = {}   (L)\n", Num(o.I));
  t += fmt::format("  mean velocity    v_mean = {}   (omega L)\n", Num(o.v_mean));
  t += fmt::format("  inner body       x_min  = {}, x_max = {}   (walls at 0 and 1)\n",
                   Num(v.x_min), Num(v.x_max));
  if (v.clearance > 0.0) {
    t += fmt::format("  clearance        {} required from both walls (stroke {})\n",
                     Num(v.clearance), Num(v.stroke));
  }
  if (v.valid()) {
    t += "  valid            yes: every condition of docs/model.md section 5 holds\n";
  } else {
    std::string names;
    for (const auto& n : v.ViolationNames()) names += (names.empty() ? "" : ", ") + n;
    t += fmt::format("  valid            no: violated {}\n", names);
  }
  return t;
}

std::string EnergyTable(const Energy& en) {
  std::string t;
  t += fmt::format("  motor work       W = {}, positive part W+ = {}   ((m1+m2) omega^2 L^2)\n",
                   Num(en.motor_work), Num(en.motor_work_positive));
  t += fmt::format("  losses           friction = {}, impacts = {}   (per period, same unit)\n",
                   Num(en.friction_loss), Num(en.impact_loss));
  return t;
}

std::string StabilityTable(const Stability& st) {
  if (!st.computed) return "  stability        not computed (no orbit)\n";
  std::string t;
  for (int i = 0; i < 2; ++i) {
    const auto& z = st.multipliers[i];
    t += fmt::format("  multiplier {}     {} {} {}i\n", i + 1, Num(z.real()),
                     z.imag() < 0 ? '-' : '+', Num(std::abs(z.imag())));
  }
  t += fmt::format("  spectral radius  {}   ({}: docs/model.md section 8)\n",
                   Num(st.spectral_radius), st.stable ? "stable, < 1" : "unstable, >= 1");
  return t;
}

}  // namespace capsubot::report
