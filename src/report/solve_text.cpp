// The one-impact orbit as plain text.

#include "capsubot/report/solve_text.hpp"

#include <fmt/format.h>

#include <cmath>

#include "capsubot/report/attractors_text.hpp"
#include "capsubot/report/from_rest_text.hpp"
#include "capsubot/report/text_format.hpp"

namespace capsubot::text {

std::string SolutionTable(const Solution& s, const Params& p, const Margins& m) {
  const Orbit& o = s.orbit;
  const Validity& v = s.validity;
  std::string t;
  t += fmt::format("one-impact periodic orbit\n");
  t += fmt::format("  force            {}\n", ForceFormula(o.forcing));
  t += fmt::format(
      "  model            T0 = {:g}, e = {:g}, margin = {:g}{}\n", p.T0, p.e, m.clearance,
      m.clearance_stroke > 0.0 || m.stick > 0.0
          ? fmt::format(", margin_stroke = {:g}, stick_margin = {:g}", m.clearance_stroke, m.stick)
          : std::string());
  t += fmt::format("  status           {}\n", StatusName(o.status));
  t += fmt::format("  stop phase       phi1   = {}\n", Num(o.phi1));
  t += fmt::format("  mass ratio       alpha  = {}   (m2/(m1+m2))\n", Num(o.alpha));
  t += fmt::format("  impact velocity  u      = {}   (omega L)\n", Num(o.u));
  t += fmt::format("  capsule kick     v_plus = {}   (omega L)\n", Num(o.v_plus));
  t += fmt::format("  step per period  I      = {}   (L)\n", Num(o.I));
  t += fmt::format("  mean velocity    v_mean = {}   (omega L)\n", Num(o.v_mean));
  t += fmt::format("  inner body       x_min  = {}, x_max = {}   (walls at 0 and 1)\n",
                   Num(v.x_min), o.ok() ? XMaxText(v.x_max) : Num(v.x_max));
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

std::string SolveJobText(const SolveJobResult& r) {
  std::string t =
      SolutionTable(r.solution, r.options.params, r.options.margins) + EnergyTable(r.energy);
  if (r.options.stability) t += StabilityTable(r.stability) + FromRestText(r.from_rest, 2);
  return t;
}

}  // namespace capsubot::text
