#include "capsubot/model/params.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

namespace capsubot {

void Params::Validate() const {
  if (!std::isfinite(T0) || T0 <= 0.0) {
    throw std::invalid_argument(
        fmt::format("friction bound T0 = {} is invalid: expected a finite T0 > 0", T0));
  }
  if (!(e >= 0.0 && e <= 1.0)) {
    throw std::invalid_argument(
        fmt::format("restitution e = {} is invalid: expected 0 <= e <= 1", e));
  }
  if (!(margin >= 0.0 && margin < 0.5)) {
    throw std::invalid_argument(
        fmt::format("margin d = {} is invalid: expected 0 <= d < 0.5", margin));
  }
  if (!(margin_stroke >= 0.0 && margin_stroke < 0.5)) {
    throw std::invalid_argument(
        fmt::format("stroke margin d_s = {} is invalid: expected 0 <= d_s < 0.5", margin_stroke));
  }
  if (!(stick_margin >= 0.0 && stick_margin < 1.0)) {
    throw std::invalid_argument(
        fmt::format("stick margin s = {} is invalid: expected 0 <= s < 1", stick_margin));
  }
}

}  // namespace capsubot
