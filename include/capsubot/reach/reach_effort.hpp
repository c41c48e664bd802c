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

  /// Throws std::invalid_argument naming the first bad field by the front ends' name
  /// (reach_evaluations, reach_local_evaluations, reach_seconds), its value and the rule.
  void Validate() const;

  /// The reach options of this effort: the force bound (NaN: T0), alpha fixed (NaN: free), the
  /// full check of the winner (its threads and interrupt also drive the search's starts).
  ReachOptions Options(double force_bound, double alpha, const FromRestOptions& check) const;
};

}  // namespace capsubot
