// A periodic motion as plain text.

#include "capsubot/report/periodic_text.hpp"

#include <fmt/format.h>

#include "capsubot/report/text_format.hpp"

namespace capsubot::text {

std::string PeriodicJobText(const PeriodicJobResult& r) {
  const PeriodicMotion& m = r.motion;
  std::string t = "periodic motion by Newton shooting on the stroboscopic map\n";
  t += fmt::format("  force          {}\n", ForceFormula(r.options.robot.forcing));
  t += fmt::format("  model          T0 = {}, e = {}, alpha = {}\n", r.options.robot.params.T0,
                   r.options.robot.params.e, r.options.robot.alpha);
  t += m.out_of_scale
           ? fmt::format(
                 "  status         {} (the state is out of the robot's scale: beyond 1e6 "
                 "times its velocity scale the map's rounding exceeds its change)\n",
                 ShootingStatusName(m.status))
           : fmt::format("  status         {} (residual {:.3g} after {} Newton iterations)\n",
                         ShootingStatusName(m.status), m.residual, m.iterations);
  t += fmt::format("  period         {}: {} right + {} left impacts per {} period{}\n", m.period,
                   m.impacts_right, m.impacts_left, m.period, m.period == 1 ? "" : "s");
  t += fmt::format("  mean velocity  {:.12g} (omega L)\n", m.mean_velocity);
  t += fmt::format("  state          x = {:.12g}, u = {:.12g}, v = {:.12g} at psi = {:.12g} ({})\n",
                   m.state.x, m.state.u, m.state.v, m.state.psi, SimModeName(m.mode));
  t += "  multipliers   ";
  for (const auto& l : m.multipliers) {
    t += fmt::format(" {:.10g}{}", l.real(),
                     l.imag() != 0.0 ? fmt::format("{:+.10g}i", l.imag()) : std::string());
  }
  t += fmt::format("   ({} free coordinates at the section)\n", m.dimension);
  if (m.status != ShootingStatus::kConverged) {
    t += "  verdict        none: Newton did not converge, so no periodic motion is known here\n";
  } else {
    t += fmt::format(
        "  verdict        {} (spectral radius {:.10g}{}); the largest multiplier lies {:.3g} "
        "from +1 (0: a fold) and {:.3g} from -1 (0: a period doubling)\n",
        m.stable ? "stable" : "unstable", m.spectral_radius, m.stable ? " < 1" : " >= 1",
        m.distance_to_plus_one, m.distance_to_minus_one);
  }
  return t;
}

}  // namespace capsubot::text
