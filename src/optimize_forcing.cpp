// P2 of MODEL.md section 7 (work in progress: options and names first).

#include "capsubot/optimize_forcing.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace capsubot {

std::vector<std::string> GlobalAlgorithmNames() {
  return {kMultistart, "GN_ISRES", "GN_ORIG_DIRECT", "GN_ORIG_DIRECT_L", "GN_AGS"};
}

std::vector<std::string> LocalAlgorithmNames() {
  return {"LN_COBYLA", "LD_SLSQP", "LD_MMA", "LD_CCSAQ"};
}

void ForcingDesignOptions::Validate() const {}

OptimizeResult OptimizeForcing(const Params& params, const ForcingDesignOptions& options) {
  params.Validate();
  options.Validate();
  OptimizeResult r;
  r.status = OptimizeStatus::kFailure;
  r.message = "P2 is not implemented yet";
  return r;
}

}  // namespace capsubot
