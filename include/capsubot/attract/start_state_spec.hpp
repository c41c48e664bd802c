#pragma once
// A start state as a user gives it, part by part (x0, u0, v0, psi): all four, or none when
// another kind of start is given instead (from rest, the one-impact orbit). The command line
// and the Python module read their starts here, with the same rules and messages.

#include <optional>
#include <string>

#include "capsubot/attract/attractors.hpp"
#include "capsubot/model/setting_names.hpp"

namespace capsubot {

struct StartStateSpec {
  std::optional<double> x0, u0, v0, psi;

  /// The state, or none when `other_given` (the other kind of start, the setting `other`:
  /// "from_rest"). Throws std::invalid_argument for both kinds or an incomplete state; the
  /// messages name the settings (x0, u0, v0, psi, `other`) in the front end's `names` and say
  /// how to ask for the other start in its syntax, `ask_other`.
  std::optional<PhaseState> Build(bool other_given, const std::string& other,
                                  const std::string& ask_other, const FlagNames& names = {}) const;
};

}  // namespace capsubot
