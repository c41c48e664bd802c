#include "capsubot/cli/from_rest_options.hpp"

#include "capsubot/cli/attract_options.hpp"
#include "capsubot/cli/setting_options.hpp"
#include "capsubot/io/io.hpp"
#include "capsubot/job/reach_effort_settings.hpp"

namespace capsubot::cli {

FromRestOptions FromRestCliOptions::Check() const {
  FromRestOptions o;
  const StartGrid grid = ParseStartGrid("--from-rest-starts", starts);
  o.n_x = grid.n_x;
  o.n_psi = grid.n_psi;
  o.attractor.threads = threads;
  return o;
}

ReachEffort FromRestCliOptions::Effort() const {
  ReachEffort effort = budgets;
  const StartGrid grid = ParseStartGrid("--reach-starts", reach_starts);
  effort.n_x = grid.n_x;
  effort.n_psi = grid.n_psi;
  return effort;
}

void AddFromRestStartsOption(CLI::App& cmd, FromRestCliOptions& o) {
  cmd.add_option("--from-rest-starts", o.starts,
                 "grid NXxNPSI of starts from rest on which every reported gait is checked "
                 "(docs/model.md section 12)")
      ->capture_default_str();
}

namespace {

// The flags of the reach search's effort: "--" and the field, and --harmonics its helps name.
const FlagNames& ReachEffortFlags() {
  static const FlagNames names =
      WithDashedFlags({{"harmonics", DashedFlag("harmonics")}}, ReachEffortSettings());
  return names;
}

}  // namespace

void AddFromRestOptions(CLI::App& cmd, FromRestCliOptions& o, bool reach) {
  AddFromRestStartsOption(cmd, o);
  AddThreadsOption(cmd, o.threads);
  if (!reach) return;
  AddReachBudgetOptions(cmd, o);
  AddSettings(cmd, o.budgets, ReachEffortSettings(), ReachEffortFlags(), {"reach_seconds"});
}

void AddReachBudgetOptions(CLI::App& cmd, FromRestCliOptions& o) {
  cmd.add_option("--reach-starts", o.reach_starts,
                 "grid NXxNPSI of starts from rest inside the reach search (the winner is "
                 "re-checked on --from-rest-starts)")
      ->capture_default_str();
  AddSettings(cmd, o.budgets, ReachEffortSettings(), ReachEffortFlags(),
              {"reach_evaluations", "reach_local_evaluations"});
}

void AddDriveBudgetOptions(CLI::App& cmd, FromRestCliOptions& o) {
  AddSettings(cmd, o.budgets, ReachEffortSettings(), ReachEffortFlags(),
              {"drive_evaluations", "drive_polishes", "drive_local_evaluations",
               "drive_refine_evaluations", "drive_screens"});
}

}  // namespace capsubot::cli
