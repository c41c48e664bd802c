#include "capsubot/optimize/optimize_search.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "capsubot/optimize/detail/nlopt_status.hpp"
#include "capsubot/optimize/detail/optimize_common.hpp"

namespace capsubot {

using detail::Require;

std::vector<std::string> GlobalAlgorithmNames() {
  return {kMultistart, "GN_ISRES", "GN_ORIG_DIRECT", "GN_ORIG_DIRECT_L", "GN_AGS"};
}

std::vector<std::string> LocalAlgorithmNames() {
  return {"LN_COBYLA", "LD_SLSQP", "LD_MMA", "LD_CCSAQ"};
}

void SearchEffort::Validate() const {
  if (global_algorithm != kMultistart) {
    detail::AlgorithmFromName(global_algorithm, GlobalAlgorithmNames(), "global_algorithm");
  }
  detail::RequireCount("starts", starts, 1, kMaxStarts);
  Require(std::isfinite(rel_tol) && rel_tol > 0.0,
          fmt::format("rel_tol = {} is invalid: expected a finite rel_tol > 0", rel_tol));
  detail::RequireCount("local_evaluations", local_evaluations, 10, kMaxStageEvaluations);
  detail::RequireCount("global_evaluations", global_evaluations, 10, kMaxStageEvaluations);
}

void SearchOptions::Validate() const {
  Require(std::isnan(force_bound) || (std::isfinite(force_bound) && force_bound > 0.0),
          fmt::format("force_bound = {} is invalid: expected a finite bound > 0 (or NaN for T0)",
                      force_bound));
  SearchEffort::Validate();
  detail::AlgorithmFromName(local_algorithm, LocalAlgorithmNames(), "local_algorithm");
  OptimizeOptions::Validate();
}

double SearchOptions::BoundFor(const Params& params) const {
  const double bound = std::isnan(force_bound) ? params.T0 : force_bound;
  Require(bound <= params.T0,
          fmt::format("force_bound = {} is invalid: expected force_bound <= T0 = {} (a force "
                      "above the friction bound moves the capsule without impacts, docs/model.md "
                      "section 6)",
                      bound, params.T0));
  return bound;
}

}  // namespace capsubot
