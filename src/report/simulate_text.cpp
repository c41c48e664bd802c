// An event-driven simulation as plain text.

#include "capsubot/report/simulate_text.hpp"

#include <fmt/format.h>

#include <cmath>

#include "capsubot/io/io.hpp"
#include "capsubot/report/text_format.hpp"

namespace capsubot::text {

std::string SimulateJobText(const SimulateJobResult& job) {
  const SimOptions& sim = job.sim;
  const SimResult& r = job.run;
  const Params& params = job.options.params;
  const bool from_orbit = job.orbit.has_value();
  const SimState& f = r.final_state;
  std::string t = "event-driven simulation\n";
  t += fmt::format("  force            {}\n", ForceFormula(job.options.forcing));
  t += fmt::format("  model            T0 = {}, e = {}, alpha = {}\n", params.T0, params.e,
                   std::isnan(sim.alpha) ? "-" : FormatNumber(sim.alpha));
  t += fmt::format("  start            x = {}, u = {}, v = {}{}\n", Num(sim.x0), Num(sim.u0),
                   Num(sim.v0), from_orbit ? "   (right after the analytic orbit's impact)" : "");
  t += fmt::format("  status           {}   (phase {} = {} periods)\n", SimStatusName(r.status),
                   Num(f.phi), Num(f.phi / kTau, 6));
  if (sim.transient > 0.0) {
    t += fmt::format(
        "  transient        {:g} periods: displacement {}, mean velocity {}, {} right "
        "and {} left impacts (not in the figures below)\n",
        sim.transient, Num(r.transient.displacement), Num(r.transient.v_mean),
        r.transient.impacts_right, r.transient.impacts_left);
  }
  t += fmt::format("  final state      x = {}, u = {}, v = {}, y = {} ({})\n", Num(f.x), Num(f.u),
                   Num(f.v), Num(f.y), SimModeName(f.mode));
  t += fmt::format("  displacement     {}   (L)\n", Num(r.displacement));
  t += fmt::format("  mean velocity    {}   (omega L)", Num(r.v_mean));
  if (from_orbit) t += fmt::format("   analytic: {}", Num(job.orbit->orbit.v_mean));
  t += "\n";
  t += fmt::format("  events           {} right impacts, {} left impacts, {} stops, {} break-aways",
                   r.impacts_right, r.impacts_left, r.stops, r.breakaways);
  if (r.sticks + r.releases > 0) {
    t += fmt::format(", {} sticks on a wall (chattering), {} releases", r.sticks, r.releases);
  }
  t += "\n";
  const Energy& en = r.energy;
  t += fmt::format(
      "  energy           motor work {:.10g} (positive part {:.10g}); losses: friction "
      "{:.10g}, impacts {:.10g}   ((m1+m2) omega^2 L^2)\n",
      en.motor_work, en.motor_work_positive, en.friction_loss, en.impact_loss);
  return t;
}

std::vector<std::string> SimulateJobNotes(const SimulateJobResult& r) {
  std::vector<std::string> notes;
  if (r.orbit && !r.orbit->validity.valid()) {
    std::string names;
    for (const auto& n : r.orbit->validity.ViolationNames()) {
      names += (names.empty() ? "" : ", ") + n;
    }
    notes.push_back(fmt::format("the analytic orbit is not valid ({})", names));
  }
  if (r.run.status == SimStatus::kEventLimit) {
    notes.push_back("stopped early: " + r.run.message);
  }
  return notes;
}

}  // namespace capsubot::text
