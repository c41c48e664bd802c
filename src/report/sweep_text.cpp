#include "capsubot/report/sweep_text.hpp"

#include <fmt/format.h>

namespace capsubot::text {

std::string SweepJobText(const SweepJobResult& result) {
  const SweepSummary& s = result.summary;
  return fmt::format("{} points, {} rows written to {} in {:.3f} s on {} threads{}\n", s.points,
                     s.rows, result.output, s.seconds, s.threads,
                     s.points_resumed > 0
                         ? fmt::format(" ({} points resumed from the checkpoint)", s.points_resumed)
                         : std::string());
}

}  // namespace capsubot::text
