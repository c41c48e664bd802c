#include "capsubot/optimize_search.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "optimize/nlopt_status.hpp"

namespace capsubot {
namespace {

void Require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument(message);
}

}  // namespace

std::vector<std::string> GlobalAlgorithmNames() {
  return {kMultistart, "GN_ISRES", "GN_ORIG_DIRECT", "GN_ORIG_DIRECT_L", "GN_AGS"};
}

std::vector<std::string> LocalAlgorithmNames() {
  return {"LN_COBYLA", "LD_SLSQP", "LD_MMA", "LD_CCSAQ"};
}

void SearchOptions::Validate() const {
  Require(std::isnan(force_bound) || (std::isfinite(force_bound) && force_bound > 0.0),
          fmt::format("force_bound = {} is invalid: expected a finite bound > 0 (or NaN for T0)",
                      force_bound));
  if (global_algorithm != kMultistart) {
    detail::AlgorithmFromName(global_algorithm, GlobalAlgorithmNames(), "global_algorithm");
  }
  detail::AlgorithmFromName(local_algorithm, LocalAlgorithmNames(), "local_algorithm");
  Require(starts >= 1, fmt::format("starts = {} is invalid: expected starts >= 1", starts));
  Require(std::isfinite(rel_tol) && rel_tol > 0.0,
          fmt::format("rel_tol = {} is invalid: expected a finite rel_tol > 0", rel_tol));
  Require(
      local_evaluations >= 10,
      fmt::format("local_evaluations = {} is invalid: expected at least 10", local_evaluations));
  Require(
      global_evaluations >= 10,
      fmt::format("global_evaluations = {} is invalid: expected at least 10", global_evaluations));
  Require(std::isfinite(rho_max) && rho_max > 0.0,
          fmt::format("rho_max = {} is invalid: expected a finite rho_max > 0", rho_max));
  Require(std::isfinite(active_tol) && active_tol >= 0.0,
          fmt::format("active_tol = {} is invalid: expected a finite active_tol >= 0", active_tol));
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
