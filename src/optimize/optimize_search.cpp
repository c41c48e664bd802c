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
  detail::RequireCount("local_evaluations", local_evaluations, kMinStageEvaluations,
                       kMaxStageEvaluations);
  detail::RequireCount("global_evaluations", global_evaluations, kMinStageEvaluations,
                       kMaxStageEvaluations);
}

void SearchOptions::Validate() const {
  effort.Validate();
  detail::AlgorithmFromName(local_algorithm, LocalAlgorithmNames(), "local_algorithm");
  OptimizeOptions::Validate();
}

}  // namespace capsubot
