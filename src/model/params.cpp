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
}

}  // namespace capsubot
