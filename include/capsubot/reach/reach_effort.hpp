#pragma once
// What a user sizes of the reach search (docs/model.md section 13): its starts from rest, its
// evaluation budgets and its time limit. The rest of ReachOptions (the box, the algorithms, the
// candidates) keeps its defaults.

#include "capsubot/attract/attractors.hpp"
#include "capsubot/reach/optimize_reach.hpp"

namespace capsubot {

struct ReachEffort {
  int n_x = 4;    ///< starts from rest inside the search: positions; >= 1
  int n_psi = 4;  ///< ... and forcing phases; >= 1
  int global_evaluations = ReachOptions{}.global_evaluations;  ///< global stage; >= 1
  int local_evaluations = ReachOptions{}.local_evaluations;    ///< local polish; >= 0
  double max_seconds = ReachOptions{}.max_seconds;             ///< wall-clock limit [s]; > 0
  /// Each step K >= 2 of a drive ladder (drive_ladder.hpp) searches 2K + 2 coordinates: a
  /// wider global stage and several local polishes (its own max_seconds too).
  int drive_evaluations = 400;        ///< global stage of each step; >= 1
  int drive_polishes = 4;             ///< local polishes of each step; >= 1
  int drive_local_evaluations = 150;  ///< evaluations of each polish; >= 0
  /// Controlled random search (GN_CRS2_LM) after the Halton points, from the best of them; >= 0.
  int drive_refine_evaluations = 400;
  /// Short local screens before the polishes, a quarter of a polish's budget each; >= 0.
  int drive_screens = 16;

  /// Throws std::invalid_argument naming the first bad field by the front ends' name
  /// (reach_evaluations, reach_local_evaluations, reach_seconds, drive_evaluations,
  /// drive_polishes, drive_local_evaluations, drive_refine_evaluations, drive_screens), its
  /// value and the rule.
  void Validate() const;

  /// The reach options of this effort: the force bound (NaN: T0), alpha fixed (NaN: free), the
  /// full check of the winner (its threads and interrupt also drive the search's starts).
  ReachOptions Options(double force_bound, double alpha, const FromRestOptions& check) const;
  /// The options of the steps K >= 2 of a ladder up to `drive`: Options with the drive
  /// budgets, a Halton sampling of the box (HALTON), controlled random search from its best
  /// point, Nelder-Mead screens and polishes from the best points and the seeds, candidates
  /// from several regions.
  ReachOptions DriveOptions(const DriveFamily& drive, double force_bound, double alpha,
                            const FromRestOptions& check) const;
};

}  // namespace capsubot
