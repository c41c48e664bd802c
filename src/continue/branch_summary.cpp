// The plain-words summary of a branch (Branch::Summary).

#include <fmt/format.h>

#include <algorithm>
#include <string>

#include "capsubot/continue/continuation.hpp"

namespace capsubot {
namespace {

std::string Plural(std::int64_t n, const char* word) {
  return fmt::format("{} {}{}", n, word, n == 1 ? "" : "s");
}

std::string Signature(const PeriodicMotion& m) {
  return fmt::format("period {}: {} right + {} left impacts per {}", m.period, m.impacts_right,
                     m.impacts_left, Plural(m.period, "period"));
}

std::string Multipliers(const PeriodicMotion& m) {
  std::string t;
  for (const auto& mu : m.multipliers) {
    t += fmt::format(" {:.6g}{}", mu.real(),
                     mu.imag() != 0.0 ? fmt::format("{:+.6g}i", mu.imag()) : std::string());
  }
  return t.empty() ? " none" : t;
}

// `wall`: the grazing's, at an end at a grazing.
std::string EndText(BranchEnd end, const std::string& name, double lambda, Wall wall) {
  switch (end) {
    case BranchEnd::kGrazing:
      return fmt::format(
          "ended at {} = {:.12g}: a grazing, a free flight touches the {} wall and beyond it the "
          "motion with these impacts does not exist",
          name, lambda, WallName(wall));
    case BranchEnd::kRangeEnd:
      return fmt::format("reached the end of the range, {} = {:.12g}", name, lambda);
    case BranchEnd::kLost:
      return fmt::format("lost at {} = {:.12g}: the corrector failed at the smallest step", name,
                         lambda);
    case BranchEnd::kMaxPoints:
      return fmt::format("stopped at {} = {:.12g}: the most points were reached", name, lambda);
    case BranchEnd::kEventChange:
      return fmt::format("stopped at {} = {:.12g}: the motion's events change there", name, lambda);
    case BranchEnd::kHalfPeriod:
      return fmt::format(
          "ended at {} = {:.12g}: next the branch passes through the motion of half its period "
          "(the period doubling it is born at) and beyond retraces itself",
          name, lambda);
    case BranchEnd::kNotRun:
      break;
  }
  return "not followed";
}

}  // namespace

std::string Branch::Summary(const std::string& name) const {
  if (status != ContinuationStatus::kOk) {
    return fmt::format("continuation in {}: {} ({})\n", name, ContinuationStatusName(status),
                       message);
  }
  const BranchPoint& s = points[static_cast<std::size_t>(start_index)];
  std::string t = fmt::format("continuation in {} of the periodic motion found at {} = {:.12g}\n",
                              name, name, s.parameter);
  t += fmt::format("  start          {}, mean velocity {:.10g}, {}\n", Signature(s.motion),
                   s.motion.mean_velocity, s.motion.stable ? "stable" : "unstable");
  const auto [lo, hi] = std::minmax_element(
      points.begin(), points.end(),
      [](const BranchPoint& a, const BranchPoint& b) { return a.parameter < b.parameter; });
  t += fmt::format("  branch         {} over {} = {:.12g} .. {:.12g}\n",
                   Plural(static_cast<std::int64_t>(points.size()), "point"), name, lo->parameter,
                   hi->parameter);
  const auto fastest = std::max_element(points.begin(), points.end(),
                                        [](const BranchPoint& a, const BranchPoint& b) {
                                          return a.motion.mean_velocity < b.motion.mean_velocity;
                                        });
  const auto stable = std::count_if(points.begin(), points.end(),
                                    [](const BranchPoint& p) { return p.motion.stable; });
  // A located speed extremum lies between points: when faster than every point, it is the
  // fastest motion of the branch.
  const PeriodicMotion* top = &fastest->motion;
  double at = fastest->parameter;
  for (const SpecialPoint& sp : special_points) {
    if (sp.type == SpecialPointType::kSpeedExtremum &&
        sp.motion.mean_velocity > top->mean_velocity) {
      top = &sp.motion;
      at = sp.parameter;
    }
  }
  t += fmt::format("  fastest        mean velocity {:.10g} at {} = {:.12g} ({})\n",
                   top->mean_velocity, name, at, top->stable ? "stable" : "unstable");
  t += fmt::format("  stable points  {} of {}\n", stable, points.size());
  const auto wall = [&](bool forward) {
    if (special_points.empty()) return Wall::kNone;
    return (forward ? special_points.back() : special_points.front()).wall;
  };
  t += fmt::format("  towards {:<6} {}\n", "lower",
                   EndText(backward_end, name, backward_parameter, wall(false)));
  t += fmt::format("  towards {:<6} {}\n", "upper",
                   EndText(forward_end, name, forward_parameter, wall(true)));
  t += fmt::format("  special points {}\n", special_points.size());
  for (const SpecialPoint& sp : special_points) {
    const std::string type =
        sp.wall == Wall::kNone
            ? SpecialPointTypeName(sp.type)
            : fmt::format("{} ({})", SpecialPointTypeName(sp.type), WallName(sp.wall));
    t += fmt::format("    {:<16} {} = {:.12g}{}  mean velocity {:.10g}  {}  multipliers{}\n", type,
                     name, sp.parameter,
                     sp.located ? "" : fmt::format(" (not located: +-{:.2g})", sp.accuracy),
                     sp.motion.mean_velocity, Signature(sp.motion), Multipliers(sp.motion));
  }
  return t;
}

}  // namespace capsubot
