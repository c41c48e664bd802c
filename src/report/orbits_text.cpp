#include "capsubot/report/orbits_text.hpp"

#include <fmt/format.h>

#include "capsubot/orbit/stability.hpp"
#include "capsubot/report/solve_text.hpp"
#include "capsubot/report/text_format.hpp"

namespace capsubot::text {

std::string OrbitsIncompleteNote(const char* bound_name) {
  return fmt::format("the search stopped at its work bound ({}): orbits may be missing",
                     bound_name);
}

std::string OrbitsJobText(const OrbitsJobResult& r, const char* bound_name) {
  const OrbitsJobOptions& o = r.options;
  std::string t =
      fmt::format("one-impact orbits of the robot with alpha = {}\n", Num(o.robot.alpha));
  t += fmt::format("  force   {}   (phi0 = impact phase, solved for)\n",
                   ForceFormula(o.robot.forcing.WithPhase(0.0)));
  t += fmt::format("  model   T0 = {:g}, e = {:g}, margins d = {:g}, d_s = {:g}, s = {:g}\n",
                   o.robot.params.T0, o.robot.params.e, o.margins.clearance,
                   o.margins.clearance_stroke, o.margins.stick);
  t += fmt::format("  {} orbit(s)\n", r.orbits.size());
  if (!r.complete) t += fmt::format("  note: {}\n", OrbitsIncompleteNote(bound_name));
  if (!r.orbits.empty()) {
    t += fmt::format("  {:>14}  {:>10}  {:>14}  {:>15}  {:>8}  {}\n", "phi0", "phi1", "v_mean",
                     "spectral_radius", "stable", "valid");
  }
  for (const Solution& s : r.orbits) {
    const Stability st = ComputeStability(s.orbit);
    std::string valid = "yes";
    if (!s.validity.valid()) {
      valid = "no:";
      for (const auto& n : s.validity.ViolationNames()) valid += " " + n;
    }
    t += fmt::format("  {:>14}  {:>10}  {:>14}  {:>15}  {:>8}  {}\n",
                     NumFixed(s.orbit.forcing.phi0(), 10), NumFixed(s.orbit.phi1, 6),
                     Num(s.orbit.v_mean, 8), Num(st.spectral_radius, 6), st.stable ? "yes" : "no",
                     valid);
  }
  return t;
}

}  // namespace capsubot::text
