#include "capsubot/attract/start_state_spec.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace capsubot {

std::optional<PhaseState> StartStateSpec::Build(bool other_given, const std::string& other,
                                                const std::string& ask_other,
                                                const FlagNames& names) const {
  const SettingNames n{names};
  const int given = (x0 ? 1 : 0) + (u0 ? 1 : 0) + (v0 ? 1 : 0) + (psi ? 1 : 0);
  if (other_given && given > 0) {
    throw std::invalid_argument(
        fmt::format("{} gives the start: do not give {}, {}, {} or {} with it", n.Name(other),
                    n.Name("x0"), n.Name("u0"), n.Name("v0"), n.Name("psi")));
  }
  if (!other_given && given < 4) {
    throw std::invalid_argument(
        fmt::format("the start is missing: give all of {}, {}, {}, {} (or {})", n.Name("x0"),
                    n.Name("u0"), n.Name("v0"), n.Name("psi"), ask_other));
  }
  if (other_given) return std::nullopt;
  return PhaseState{*x0, *u0, *v0, *psi};
}

}  // namespace capsubot
