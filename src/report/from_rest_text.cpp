#include "capsubot/report/from_rest_text.hpp"

#include <fmt/format.h>

#include <cmath>
#include <utility>

#include "capsubot/report/solve_text.hpp"
#include "capsubot/report/text_format.hpp"

namespace capsubot::text {

std::string FromRestText(const GaitFromRest& r, int indent) {
  return fmt::format("{:{}}from rest        {}\n", "", indent, r.summary);
}

std::string ReachText(const ReachResult& r) {
  if (std::isnan(r.mean_velocity)) return fmt::format("    none: {}\n", r.message);
  std::string t;
  t += fmt::format("    force            {}\n", ForceFormula(r.forcing));
  if (!r.drive.sine()) {
    t +=
        fmt::format("    force bound      max |F| = {:.9g} <= {:g} (exact: F at the zeros of F')\n",
                    r.max_abs_force, r.force_bound);
  }
  t += fmt::format("    inner mass ratio alpha = m2/(m1+m2) = {:.5g}\n", r.alpha);
  t += fmt::format("    speed from rest  mean velocity {:.6g} omega L (over {} starts)\n",
                   r.mean_velocity, r.attractors.starts);
  t += fmt::format("    from rest        {}\n", r.summary);
  if (!std::isnan(r.physical_speed)) {
    t += fmt::format(
        "    frequency        T0 = {:.6g}: speed {:.6g} sqrt(mu g L) (v_mean/sqrt(T0), the "
        "bound tied to T0)\n",
        r.T0, r.physical_speed);
  }
  std::string spread;
  for (const auto& [name, v] :
       {std::pair<const char*, double>{"chatter/100", r.spread.chatter_small},
        {"chatter*100", r.spread.chatter_large},
        {"e = 0.999", r.spread.e_0999}}) {
    if (!std::isnan(v)) spread += fmt::format("{}{} {:.6g}", spread.empty() ? "" : ", ", name, v);
  }
  if (r.spread.event_limit_starts > 0) {
    spread += fmt::format("{}{} starts of the re-runs hit the work bound (null above)",
                          spread.empty() ? "" : "; ", r.spread.event_limit_starts);
  }
  t += fmt::format("    settings         {} (largest relative change {})\n",
                   spread.empty() ? std::string("no re-run") : spread,
                   Num(r.spread.max_relative_deviation, 2));
  t += fmt::format(
      "    solver           {} ({} from-rest evaluations, {:.1f} s search, status "
      "{})\n",
      r.algorithm, r.evaluations, r.search_seconds, OptimizeStatusName(r.status));
  return t;
}

}  // namespace capsubot::text
