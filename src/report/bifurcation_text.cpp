#include "capsubot/report/bifurcation_text.hpp"

#include <fmt/format.h>

namespace capsubot::text {
namespace {

// "bifurcation diagram over T0 = 0.08 .. 0.12 (4 values, both)", with " for 3 values of e" in
// a two-parameter study.
std::string StudyText(const BifurcationOptions& d) {
  const char* directions = d.up && d.down ? "both" : d.up ? "up" : "down";
  std::string study =
      fmt::format("bifurcation diagram over {} = {} .. {} ({} values, {})",
                  ModelParameterName(d.param, d.harmonic), d.from, d.to, d.steps, directions);
  if (!d.over_values.empty()) {
    study += fmt::format(" for {} values of {}", d.over_values.size(),
                         ModelParameterName(d.over, d.over_harmonic));
  }
  return study;
}

}  // namespace

std::string BifurcationJobText(const BifurcationJobResult& r) {
  const BifurcationOptions& d = r.diagram;
  const std::string summary =
      r.summary.empty() ? std::string()
                        : fmt::format(", {} summary rows to {}", r.summary_rows, r.summary);
  if (d.shards < 2) {
    return fmt::format("{}: {} impacts written to {}{}\n", StudyText(d), r.impact_rows, r.impacts,
                       summary);
  }
  const std::string resumed =
      r.parts_resumed > 0
          ? fmt::format(" ({} of the shard's {} parts computed, {} resumed from the checkpoint)",
                        r.parts - r.parts_resumed, r.parts, r.parts_resumed)
          : std::string();
  return fmt::format("{}, shard {}/{} of {} continuations: {} impacts written to {}{}{}\n",
                     StudyText(d), d.shard, d.shards, BifurcationContinuations(d), r.impact_rows,
                     r.impacts, summary, resumed);
}

}  // namespace capsubot::text
