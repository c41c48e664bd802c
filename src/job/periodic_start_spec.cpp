#include "capsubot/job/periodic_start_spec.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace capsubot {

PeriodicStart PeriodicStartSpec::Build(const std::string& ask_rest, const FlagNames& names) const {
  const std::optional<PhaseState> given =
      state.Build(from_rest.has_value(), "from_rest", ask_rest, names);
  if (period && transient) {
    const SettingNames n{names};
    throw std::invalid_argument(
        fmt::format("{} and {} are exclusive: with the period given, Newton starts at the start "
                    "itself",
                    n.Name("period"), n.Name("transient")));
  }
  const PhaseState start = given ? *given : *from_rest;
  if (period) return PeriodicOfPeriod{start, *period};
  if (!from_rest)
    return PeriodicFromState{start, transient.value_or(PeriodicFromState{}.transient)};
  PeriodicFromRest rest;
  rest.x0 = from_rest->x;
  rest.psi = from_rest->psi;
  rest.transient = transient.value_or(rest.transient);
  return rest;
}

}  // namespace capsubot
