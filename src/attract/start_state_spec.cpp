#include "capsubot/attract/start_state_spec.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace capsubot {

std::optional<PhaseState> StartStateSpec::Build(bool other_given, const std::string& p,
                                                const std::string& other,
                                                const std::string& ask_other) const {
  const int given = (x0 ? 1 : 0) + (u0 ? 1 : 0) + (v0 ? 1 : 0) + (psi ? 1 : 0);
  if (other_given && given > 0) {
    throw std::invalid_argument(fmt::format(
        "{1} gives the start: do not give {0}x0, {0}u0, {0}v0 or {0}psi with it", p, other));
  }
  if (!other_given && given < 4) {
    throw std::invalid_argument(fmt::format(
        "the start is missing: give all of {0}x0, {0}u0, {0}v0, {0}psi (or {1})", p, ask_other));
  }
  if (other_given) return std::nullopt;
  return PhaseState{*x0, *u0, *v0, *psi};
}

}  // namespace capsubot
