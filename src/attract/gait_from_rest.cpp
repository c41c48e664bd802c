// A one-impact gait checked from rest (docs/model.md section 12): the attractors of the
// robot that the gait describes, the starts that end on the gait, and the sentence that says it.

#include "capsubot/attract/gait_from_rest.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>

namespace capsubot {
namespace {

// Other attractors named one by one in the summary; the rest are summed.
constexpr std::size_t kNamedAttractors = 3;

std::string Starts(std::int64_t n) { return fmt::format("{} start{}", n, n == 1 ? "" : "s"); }

}  // namespace

std::string NoImpactWords(const Motion& m) {
  if (m.impacts_right != 0 || m.impacts_left != 0) return "";
  if (m.mode == SimMode::kOnRightWall) return "at rest against the right wall";
  if (m.mode == SimMode::kOnLeftWall) return "at rest against the left wall";
  return "clear of both walls";
}

std::string DescribeMotion(const Motion& m, int max_period, int digits) {
  switch (m.status) {
    case MotionStatus::kPeriodic:
      if (const std::string rest = NoImpactWords(m); !rest.empty()) {
        return fmt::format("the inner body {}, no impacts, at mean velocity {:.{}g}", rest,
                           m.mean_velocity, digits);
      }
      return fmt::format(
          "a motion with {} right + {} left impacts per {} at mean velocity {:.{}g}",
          m.impacts_right, m.impacts_left,
          m.period == 1 ? std::string("period") : fmt::format("{} periods", m.period),
          m.mean_velocity, digits);
    case MotionStatus::kNoPeriod:
      return fmt::format("a motion with no period up to {} (mean velocity {:.{}g})", max_period,
                         m.mean_velocity, digits);
    case MotionStatus::kEventLimit:
      return "the work bound (a Zeno sequence of impacts)";
    case MotionStatus::kNotRun:
      break;
  }
  return "no computed motion";
}

std::string AttractorsSummary(const Attractors& a, int max_period,
                              const std::vector<bool>& on_gait) {
  // Groups of the starts that are not on the gait: one per periodic attractor, one for all
  // starts without a period (each is its own class: their record averages differ), one for
  // the work bound. Each group: starts, and the smallest and largest mean velocity.
  struct Group {
    std::int64_t starts = 0;
    double v_min = HUGE_VAL, v_max = -HUGE_VAL;
    const Motion* motion = nullptr;
  };
  std::vector<Group> groups(a.attractors.size() + 2);
  const std::size_t no_period = a.attractors.size(), event_limit = no_period + 1;
  std::int64_t reached = 0;
  for (std::size_t k = 0; k < a.labels.size(); ++k) {
    if (!on_gait.empty() && on_gait[k]) {
      ++reached;
      continue;
    }
    const auto label = static_cast<std::size_t>(a.labels[k]);
    const Motion& m = a.attractors[label].motion;
    const std::size_t g = m.status == MotionStatus::kNoPeriod     ? no_period
                          : m.status == MotionStatus::kEventLimit ? event_limit
                                                                  : label;
    Group& group = groups[g];
    ++group.starts;
    group.motion = &m;
    group.v_min = std::min(group.v_min, m.mean_velocity);
    group.v_max = std::max(group.v_max, m.mean_velocity);
  }
  std::vector<std::size_t> order(groups.size());
  std::iota(order.begin(), order.end(), std::size_t{0});
  std::stable_sort(order.begin(), order.end(), [&](std::size_t x, std::size_t y) {
    return groups[x].starts > groups[y].starts;
  });

  std::string t;
  if (!on_gait.empty()) {
    t = reached == a.starts && a.starts > 0
            ? fmt::format("reached from rest in all {}", Starts(a.starts))
            : fmt::format("reached from rest in {} of {}", reached, Starts(a.starts));
  } else {
    t = fmt::format("{} from rest", Starts(a.starts));
  }
  std::int64_t rest = 0;
  std::size_t named = 0;
  for (std::size_t g : order) {
    const Group& group = groups[g];
    if (group.starts == 0) continue;
    if (named == kNamedAttractors) {
      rest += group.starts;
      continue;
    }
    const std::string who =
        on_gait.empty() && group.starts == a.starts
            ? std::string("all end")
            : fmt::format("{} end{}", Starts(group.starts), group.starts == 1 ? "s" : "");
    const std::string what =
        g == no_period && group.v_min < group.v_max
            ? fmt::format("motions with no period up to {} (mean velocity {:.3g} to {:.3g})",
                          max_period, group.v_min, group.v_max)
            : DescribeMotion(*group.motion, max_period);
    t += fmt::format("{} {} in {}", named == 0 ? (on_gait.empty() ? ":" : ";") : ";", who, what);
    ++named;
  }
  if (rest > 0) {
    t += fmt::format("; {} end{} in other motions", Starts(rest), rest == 1 ? "s" : "");
  }
  return t;
}

GaitFromRest CheckGaitFromRest(const Orbit& orbit, const Params& params,
                               const FromRestOptions& options) {
  return CheckGaitFromRest(orbit, orbit.forcing, params, options);
}

GaitFromRest CheckGaitFromRest(const Orbit& orbit, const Forcing& motor, const Params& params,
                               const FromRestOptions& options) {
  params.Validate();
  options.Validate();
  GaitFromRest out;
  if (!orbit.ok()) {
    out.summary = "not checked from rest: the gait's orbit does not exist";
    return out;
  }
  const RobotModel robot{motor, params, orbit.alpha};  // the gait's mass ratio
  out.attractors = FindAttractors(robot, options);
  std::vector<bool> on_gait(out.attractors.motions.size(), false);
  for (std::size_t k = 0; k < on_gait.size(); ++k) {
    on_gait[k] =
        MatchesOrbit(out.attractors.motions[k], motor, orbit, options.attractor.orbit_tolerance);
    out.reached += on_gait[k] ? 1 : 0;
  }
  out.summary = AttractorsSummary(out.attractors, options.attractor.motion.max_period, on_gait);
  out.checked = true;
  return out;
}

}  // namespace capsubot
