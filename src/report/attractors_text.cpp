// The long-run motions from rest as plain text.

#include "capsubot/report/attractors_text.hpp"

#include <fmt/format.h>

#include "capsubot/attract/gait_from_rest.hpp"
#include "capsubot/report/text_format.hpp"

namespace capsubot::text {

std::string AttractorWords(const Attractor& a, int max_period) {
  const Motion& m = a.motion;
  switch (m.status) {
    case MotionStatus::kPeriodic:
      if (const std::string rest = NoImpactWords(m); !rest.empty()) {
        return fmt::format("period {}: no impacts, the inner body {}", m.period, rest);
      }
      return fmt::format("period {}: {} right + {} left impacts per {}", m.period, m.impacts_right,
                         m.impacts_left,
                         m.period == 1 ? "period" : fmt::format("{} periods", m.period));
    case MotionStatus::kNoPeriod:
      return fmt::format(
          "irregular, no period up to {} (mean velocity {:.4g} to {:.4g} over its starts; the "
          "halves of a record differ by up to {:.2g} %{})",
          max_period, a.velocity_min, a.velocity_max, 100.0 * a.halves_difference,
          a.halves_difference <= kSettledHalves ? ": settled"
                                                : ": a longer --record is needed for 1 %");
    case MotionStatus::kEventLimit:
      return "event_limit: the work bound was hit (a Zeno sequence of impacts)";
    case MotionStatus::kNotRun:
      break;
  }
  return "not run";
}

std::string StartShardText(const char* command, const AttractorsJobResult& r) {
  const StartShardOptions& file = std::get<StartMapShard>(r.options.run).file;
  return fmt::format(
      "{}: shard {}/{}: {} of {} starts written to {}{}\n", command, file.shard, file.shards,
      r.shard.starts, r.options.starts.Starts(), file.output,
      r.shard.resumed > 0 ? fmt::format(" ({} resumed from the checkpoint)", r.shard.resumed) : "");
}

std::string AttractorsJobText(const AttractorsJobResult& r) {
  if (std::holds_alternative<StartMapShard>(r.options.run)) return StartShardText("attractors", r);
  const AttractorsJobOptions& o = r.options;
  const Attractors& a = r.attractors;
  const MotionOptions& mo = o.attractor.motion;
  std::string t =
      fmt::format("attractors from rest: {} starts ({} x0 x {} phases), {} + {} periods\n",
                  a.starts, o.starts.n_x, o.starts.n_psi, mo.transient, mo.record);
  t += fmt::format("  force          {}\n", ForceFormula(o.robot.forcing));
  t += fmt::format("  model          T0 = {}, e = {}, alpha = {}\n", o.robot.params.T0,
                   o.robot.params.e, o.robot.alpha);
  int k = 0;
  for (const Attractor& at : a.attractors) {
    t += fmt::format("  {:>2}. {:5.1f} % of starts  mean velocity {:<13} {}{}\n", ++k,
                     100.0 * at.fraction, Num(at.mean_velocity, 10),
                     AttractorWords(at, mo.max_period),
                     at.one_impact_orbit ? "  (the analytic one-impact orbit)" : "");
    t += fmt::format("      e.g. from x0 = {:.6g}, psi = {:.6g}\n", at.example.x, at.example.psi);
  }
  t += fmt::format("  mean velocity over the starts: {} (omega L)", Num(a.mean_velocity, 10));
  if (a.event_limit_starts > 0) {
    t += fmt::format(", {} starts hit the work bound and are left out", a.event_limit_starts);
  }
  t += "\n";
  const std::string& output = std::get<WholeStartMap>(o.run).output;
  if (!output.empty()) t += fmt::format("  the motion of every start written to {}\n", output);
  return t;
}

}  // namespace capsubot::text
