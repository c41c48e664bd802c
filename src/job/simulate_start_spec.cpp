#include "capsubot/job/simulate_start_spec.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace capsubot {

SimulateStart SimulateStartSpec::Build(bool from_orbit, const std::string& ask_orbit,
                                       const FlagNames& names) const {
  const SettingNames n{names};
  if (from_orbit) {
    if (alpha || x0 || u0 || v0) {
      throw std::invalid_argument(fmt::format(
          "{} takes the state and alpha from the analytic orbit: do not give {}, {}, {} or {} "
          "with it",
          n.Name("from_orbit"), n.Name("alpha"), n.Name("x0"), n.Name("u0"), n.Name("v0")));
    }
    return SimulateFromOrbit{};
  }
  if (!alpha) {
    throw std::invalid_argument(
        fmt::format("{} is missing: give the mass ratio (or {})", n.Name("alpha"), ask_orbit));
  }
  if (!x0 || !u0 || !v0) {
    throw std::invalid_argument(
        fmt::format("the initial state is missing: give all of {}, {}, {} (or {})", n.Name("x0"),
                    n.Name("u0"), n.Name("v0"), ask_orbit));
  }
  return SimulateFromState{*alpha, *x0, *u0, *v0};
}

}  // namespace capsubot
