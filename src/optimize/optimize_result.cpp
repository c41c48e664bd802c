#include "capsubot/optimize/optimize_result.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iterator>
#include <stdexcept>

#include "capsubot/model/detail/enum_names.hpp"

namespace capsubot {

const char* OptimizeStatusName(OptimizeStatus status) {
  static constexpr const char* kNames[] = {
      "not_run",          "ok",          "no_valid_orbit",    "max_evaluations", "max_time",
      "roundoff_limited", "forced_stop", "invalid_arguments", "out_of_memory",   "failure"};
  static_assert(std::size(kNames) == static_cast<std::size_t>(OptimizeStatus::kFailure) + 1);
  return detail::EnumName(kNames, status);
}

const char* MarginName(Margin margin) {
  static constexpr const char* kNames[] = {"clearance", "clearance_stroke", "stick_margin",
                                           "rho_max"};
  static_assert(std::size(kNames) == static_cast<std::size_t>(Margin::kCount));
  return detail::EnumName(kNames, margin);
}

void OptimizeOptions::Validate() const {
  gait.Validate();
  if (!(max_time > 0.0)) {
    throw std::invalid_argument(fmt::format(
        "max_time = {} is invalid: expected a time limit max_time > 0 [s] (infinity: none)",
        max_time));
  }
  if (!(std::isfinite(active_tol) && active_tol >= 0.0)) {
    throw std::invalid_argument(
        fmt::format("active_tol = {} is invalid: expected a finite active_tol >= 0", active_tol));
  }
}

}  // namespace capsubot
