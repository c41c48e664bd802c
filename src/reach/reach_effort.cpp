#include "capsubot/reach/reach_effort.hpp"

#include <fmt/format.h>

#include "capsubot/optimize/detail/optimize_common.hpp"

namespace capsubot {

void ReachEffort::Validate() const {
  detail::Require(
      global_evaluations >= 1,
      fmt::format("reach_evaluations = {} is invalid: expected at least 1", global_evaluations));
  detail::Require(local_evaluations >= 0,
                  fmt::format("reach_local_evaluations = {} is invalid: expected at least 0",
                              local_evaluations));
  detail::Require(max_seconds > 0.0,
                  fmt::format("reach_seconds = {} is invalid: expected a time > 0 (infinity: none)",
                              max_seconds));
}

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
