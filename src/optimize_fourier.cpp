// P3 of MODEL.md section 7 (work in progress).

#include "capsubot/optimize_fourier.hpp"

namespace capsubot {

void FourierOptions::Validate() const {}

OptimizeResult OptimizeFourier(const Params& params, const FourierOptions& options) {
  params.Validate();
  options.Validate();
  OptimizeResult r;
  r.status = OptimizeStatus::kFailure;
  r.message = "P3 is not implemented yet";
  return r;
}

}  // namespace capsubot
