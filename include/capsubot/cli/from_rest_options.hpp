#pragma once
// What the robot reaches from rest (docs/model.md sections 12 and 13): the options that size the
// check of a gait from rest and the reach search. Shared by optimize, solve, design and sweep.

#include <CLI/CLI.hpp>
#include <string>

#include "capsubot/attract/gait_from_rest.hpp"
#include "capsubot/attract/start_grid.hpp"
#include "capsubot/io/io.hpp"
#include "capsubot/reach/optimize_reach.hpp"
#include "capsubot/reach/reach_effort.hpp"

namespace capsubot::cli {

/// How gaits are checked from rest and how the reach search is sized, from the command line.
struct FromRestCliOptions {
  std::string starts = StartGrid{}.Text();  ///< --from-rest-starts: the full grid NXxNPSI
  /// --reach-starts: the grid inside the reach search
  std::string reach_starts = StartGrid{ReachEffort{}.n_x, ReachEffort{}.n_psi}.Text();
  /// The budgets and time limit of the reach search: --reach-evaluations,
  /// --reach-local-evaluations, --reach-seconds and the --drive-* budgets (its grid: the
  /// default; --reach-starts gives it).
  ReachEffort budgets;
  int threads = 0;  ///< --threads

  /// The full from-rest settings (grid of --from-rest-starts); throws std::invalid_argument
  /// naming the option for a bad grid.
  FromRestOptions Check() const;
  /// The effort of the reach search (grid of --reach-starts, budgets, time limit); throws
  /// std::invalid_argument naming the option for a bad grid.
  ReachEffort Effort() const;
};

/// Adds --from-rest-starts and --threads; with `reach` also --reach-starts,
/// --reach-evaluations, --reach-local-evaluations, --reach-seconds.
void AddFromRestOptions(CLI::App& cmd, FromRestCliOptions& options, bool reach);
/// Adds --from-rest-starts alone.
void AddFromRestStartsOption(CLI::App& cmd, FromRestCliOptions& options);
/// Adds the budgets of each Fourier drive K >= 2 of the reach search: --drive-evaluations,
/// --drive-polishes, --drive-local-evaluations.
void AddDriveBudgetOptions(CLI::App& cmd, FromRestCliOptions& options);

/// Adds the evaluation budgets of the reach search: --reach-starts, --reach-evaluations,
/// --reach-local-evaluations (not its wall-clock limit --reach-seconds).
void AddReachBudgetOptions(CLI::App& cmd, FromRestCliOptions& options);

}  // namespace capsubot::cli
