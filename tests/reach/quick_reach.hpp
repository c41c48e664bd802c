#pragma once
// Small budgets of the reach search for tests: `starts` x `starts` starts in the search, 4 x 4 in
// the re-check, a quick robust seed.

#include "capsubot/reach/optimize_reach.hpp"

namespace capsubot::testing {

inline ReachOptions QuickReachOptions(int global_evaluations, int local_evaluations, int starts) {
  ReachOptions o;
  o.global_evaluations = global_evaluations;
  o.local_evaluations = local_evaluations;
  o.max_seconds = 60.0;
  o.search.n_x = starts;
  o.search.n_psi = starts;
  o.check.n_x = 4;
  o.check.n_psi = 4;
  o.seed_design.hops = 2;
  o.seed_design.effort.starts = 3;
  return o;
}

}  // namespace capsubot::testing
