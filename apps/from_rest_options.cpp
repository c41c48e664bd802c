#include "from_rest_options.hpp"

#include <fmt/format.h>

#include <cmath>
#include <tuple>
#include <utility>

#include "attract_options.hpp"
#include "capsubot/io/io.hpp"

namespace capsubot::app {

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

void AddFromRestOptions(CLI::App& cmd, FromRestCliOptions& o, bool reach) {
  AddFromRestStartsOption(cmd, o);
  AddThreadsOption(cmd, o.threads);
  if (!reach) return;
  AddReachBudgetOptions(cmd, o);
  cmd.add_option(
         "--reach-seconds", o.budgets.max_seconds,
         "wall-clock limit of the reach search in seconds, looked at between two evaluations of "
         "its grid (the re-checks come on top)")
      ->capture_default_str();
}

namespace {

// A budget of the reach search: its flag, its field, its help (its default is shown).
struct BudgetFlag {
  const char* flag;
  int ReachEffort::*field;
  const char* help;
};

// The evaluation budgets of the reach search's stages, in the order of --help.
const BudgetFlag kReachBudgets[] = {
    {"--reach-evaluations", &ReachEffort::global_evaluations,
     "from-rest evaluations of the reach search's global stage (DIRECT-L), >= 1"},
    {"--reach-local-evaluations", &ReachEffort::local_evaluations,
     "from-rest evaluations of the reach search's local polish (Sbplx), >= 0"},
};

// The budgets of each Fourier drive K >= 2 and pulse drive, in the order of --help.
const BudgetFlag kDriveBudgets[] = {
    {"--drive-evaluations", &ReachEffort::drive_evaluations,
     "from-rest evaluations of the first global stage (Halton points of the box) of each "
     "Fourier drive K >= 2 (--harmonics) and pulse drive, >= 1"},
    {"--drive-polishes", &ReachEffort::drive_polishes,
     "local polishes (Nelder-Mead) of each Fourier drive K >= 2, from its best distinct points, "
     ">= 1"},
    {"--drive-local-evaluations", &ReachEffort::drive_local_evaluations,
     "from-rest evaluations of each of those polishes, >= 0"},
    {"--drive-refine-evaluations", &ReachEffort::drive_refine_evaluations,
     "from-rest evaluations of the controlled random search (GN_CRS2_LM) after the Halton "
     "points, from the best of them, >= 0"},
    {"--drive-screens", &ReachEffort::drive_screens,
     "short local screens (Nelder-Mead, a quarter of a polish's evaluations each) before the "
     "polishes, from the best distinct points, >= 0"},
};

template <std::size_t N>
void AddBudgets(CLI::App& cmd, FromRestCliOptions& o, const BudgetFlag (&budgets)[N]) {
  for (const BudgetFlag& b : budgets) {
    cmd.add_option(b.flag, o.budgets.*b.field, b.help)->capture_default_str();
  }
}

}  // namespace

void AddReachBudgetOptions(CLI::App& cmd, FromRestCliOptions& o) {
  cmd.add_option("--reach-starts", o.reach_starts,
                 "grid NXxNPSI of starts from rest inside the reach search (the winner is "
                 "re-checked on --from-rest-starts)")
      ->capture_default_str();
  AddBudgets(cmd, o, kReachBudgets);
}

void AddDriveBudgetOptions(CLI::App& cmd, FromRestCliOptions& o) {
  AddBudgets(cmd, o, kDriveBudgets);
}

}  // namespace capsubot::app
