#include "capsubot/reach/reach_effort.hpp"

namespace capsubot {

ReachOptions ReachEffort::Options(double force_bound, double alpha,
                                  const FromRestOptions& check) const {
  ReachOptions r;
  r.force_bound = force_bound;
  r.alpha = alpha;
  r.search.n_x = n_x;
  r.search.n_psi = n_psi;
  r.search.attractor.threads = check.attractor.threads;
  r.search.attractor.interrupt = check.attractor.interrupt;
  r.check = check;
  r.global_evaluations = global_evaluations;
  r.local_evaluations = local_evaluations;
  r.max_seconds = max_seconds;
  return r;
}

}  // namespace capsubot
