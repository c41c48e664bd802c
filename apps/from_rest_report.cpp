#include "from_rest_report.hpp"

#include <fmt/format.h>

#include <cmath>
#include <tuple>
#include <utility>

#include "attract_options.hpp"
#include "capsubot/io/io.hpp"
#include "report.hpp"

namespace capsubot::app {

FromRestOptions FromRestCliOptions::Check() const {
  FromRestOptions o;
  std::tie(o.n_x, o.n_psi) = ParseGridSize("--from-rest-starts", starts);
  o.attractor.threads = threads;
  return o;
}

ReachOptions FromRestCliOptions::Reach(double force_bound, double alpha) const {
  ReachOptions r;
  r.force_bound = force_bound;
  r.alpha = alpha;
  std::tie(r.search.n_x, r.search.n_psi) = ParseGridSize("--reach-starts", reach_starts);
  r.search.attractor.threads = threads;
  r.check = Check();
  r.global_evaluations = reach_evaluations;
  r.local_evaluations = reach_local_evaluations;
  r.max_seconds = reach_seconds;
  return r;
}

void AddFromRestStartsOption(CLI::App& cmd, FromRestCliOptions& o) {
  cmd.add_option("--from-rest-starts", o.starts,
                 "grid NXxNPSI of starts from rest on which every reported gait is checked "
                 "(docs/model.md section 12)")
      ->capture_default_str();
}

void AddFromRestOptions(CLI::App& cmd, FromRestCliOptions& o, bool reach) {
  AddFromRestStartsOption(cmd, o);
  AddThreadsOption(cmd, o.threads);
  if (!reach) return;
  AddReachBudgetOptions(cmd, o);
  cmd.add_option("--reach-seconds", o.reach_seconds,
                 "wall-clock limit of the reach search in seconds (the re-checks come on top)")
      ->capture_default_str();
}

void AddReachBudgetOptions(CLI::App& cmd, FromRestCliOptions& o) {
  cmd.add_option("--reach-starts", o.reach_starts,
                 "grid NXxNPSI of starts from rest inside the reach search (the winner is "
                 "re-checked on --from-rest-starts)")
      ->capture_default_str();
  cmd.add_option("--reach-evaluations", o.reach_evaluations,
                 "from-rest evaluations of the reach search's global stage (DIRECT-L), >= 1")
      ->capture_default_str();
  cmd.add_option("--reach-local-evaluations", o.reach_local_evaluations,
                 "from-rest evaluations of the reach search's local polish (Sbplx), >= 0")
      ->capture_default_str();
}

void WriteFromRestCsv(AtomicFile& file, const OptimizeResult& robust, const ReachResult& reach) {
  auto& out = file.stream();
  out << "gait,row,mean_velocity,fraction,period,impacts_right,impacts_left,one_impact_orbit\n";
  const auto rows = [&](const char* gait, const Attractors& a) {
    for (const Attractor& at : a.attractors) {
      const Motion& m = at.motion;
      out << gait << ",attractor," << FormatNumber(m.mean_velocity) << ','
          << FormatNumber(at.fraction) << ',' << m.period << ',' << m.impacts_right << ','
          << m.impacts_left << ',' << (at.one_impact_orbit ? 1 : 0) << '\n';
    }
  };
  if (robust.found()) {
    out << "robust,promised," << FormatNumber(robust.solution.orbit.v_mean) << ",,1,1,0,1\n";
    rows("robust", reach.seed.from_rest.attractors);
  }
  rows("reach", reach.attractors);
  file.Commit();
}

std::string ReachText(const ReachResult& r) {
  if (std::isnan(r.mean_velocity)) return fmt::format("    none: {}\n", r.message);
  std::string t;
  t += fmt::format("    force            {}\n", ForceFormula(r.forcing));
  t += fmt::format("    inner mass ratio alpha = m2/(m1+m2) = {:.5g}\n", r.alpha);
  t += fmt::format("    speed from rest  mean velocity {:.6g} omega L (over {} starts)\n",
                   r.mean_velocity, r.attractors.starts);
  t += fmt::format("    from rest        {}\n", r.summary);
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
  t += fmt::format("    settings         {} (largest relative change {:.2g})\n",
                   spread.empty() ? std::string("no re-run") : spread,
                   r.spread.max_relative_deviation);
  t += fmt::format(
      "    solver           {} ({} from-rest evaluations, {:.1f} s search, status "
      "{})\n",
      r.algorithm, r.evaluations, r.search_seconds, OptimizeStatusName(r.status));
  return t;
}

}  // namespace capsubot::app
