#include "capsubot/report/attractor_text.hpp"

#include <fmt/format.h>

namespace capsubot {

std::string AttractorWords(const Attractor& a, int max_period) {
  const Motion& m = a.motion;
  switch (m.status) {
    case MotionStatus::kPeriodic:
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

}  // namespace capsubot
