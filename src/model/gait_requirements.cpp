#include "capsubot/model/gait_requirements.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace capsubot {

void Margins::Validate() const {
  if (!(clearance >= 0.0 && clearance < 0.5)) {
    throw std::invalid_argument(
        fmt::format("margin d = {} is invalid: expected 0 <= d < 0.5", clearance));
  }
  if (!(clearance_stroke >= 0.0 && clearance_stroke < 0.5)) {
    throw std::invalid_argument(fmt::format(
        "stroke margin d_s = {} is invalid: expected 0 <= d_s < 0.5", clearance_stroke));
  }
  if (!(stick >= 0.0 && stick < 1.0)) {
    throw std::invalid_argument(
        fmt::format("stick margin s = {} is invalid: expected 0 <= s < 1", stick));
  }
}

void GaitRequirements::Validate() const {
  margins.Validate();
  if (!(std::isnan(force_bound) || (std::isfinite(force_bound) && force_bound > 0.0))) {
    throw std::invalid_argument(fmt::format(
        "force_bound = {} is invalid: expected a finite bound > 0 (not given: T0)", force_bound));
  }
  if (!(rho_max > 0.0)) {
    throw std::invalid_argument(fmt::format(
        "rho_max = {} is invalid: expected rho_max > 0 (infinity: no stability requirement)",
        rho_max));
  }
}

double GaitRequirements::BoundFor(const Params& params) const {
  const double bound = std::isnan(force_bound) ? params.T0 : force_bound;
  if (!(bound <= params.T0)) {
    throw std::invalid_argument(
        fmt::format("force_bound = {} is invalid: expected at most the friction bound T0 = {} (a "
                    "force above it moves the capsule without impacts, docs/model.md section 6)",
                    bound, params.T0));
  }
  return bound;
}

}  // namespace capsubot
