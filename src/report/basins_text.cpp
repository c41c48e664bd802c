// Basins of attraction as plain text.

#include "capsubot/report/basins_text.hpp"

#include <fmt/format.h>

#include "capsubot/report/attractors_text.hpp"
#include "capsubot/report/text_format.hpp"

namespace capsubot::text {

std::string BasinLegend(const Attractor& a, int max_period) {
  return fmt::format("{:.1f} %: {}, mean velocity {}", 100.0 * a.fraction,
                     AttractorWords(a, max_period), Num(a.mean_velocity, 4));
}

std::string BasinsJobText(const BasinsJobResult& r) {
  if (std::holds_alternative<StartMapShard>(r.map.options.run)) {
    return StartShardText("basins", r.map);
  }
  const AttractorsJobOptions& o = r.map.options;
  const Attractors& a = r.map.attractors;
  const std::string& output = std::get<WholeStartMap>(o.run).output;
  std::string t = fmt::format("basins: {} starts ({} x {}, plane {}){}\n", a.starts, o.starts.n_x,
                              o.starts.n_psi, StartPlaneName(r.plane),
                              output.empty() ? "" : " written to " + output);
  int k = 0;
  for (const Attractor& at : a.attractors) {
    t += fmt::format("  {:>2}. {}{}\n", ++k, BasinLegend(at, o.attractor.motion.max_period),
                     at.one_impact_orbit ? " (the analytic one-impact orbit)" : "");
  }
  return t;
}

}  // namespace capsubot::text
