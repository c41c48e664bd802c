#pragma once
// A start state as a user gives it, part by part (x0, u0, v0, psi): all four, or none when
// another kind of start is given instead (from rest, the one-impact orbit). The command line
// and the Python module read their starts here, with the same rules and messages.

#include <optional>
#include <string>

#include "capsubot/attract/attractors.hpp"

namespace capsubot {

struct StartStateSpec {
  std::optional<double> x0, u0, v0, psi;

  /// The state, or none when `other_given` (the other kind of start). Throws
  /// std::invalid_argument for both kinds or an incomplete state. Messages name the state's
  /// parameters with `prefix` ("" or "--"), the other start `other` ("from_rest",
  /// "--from-rest") and how to ask for it `ask_other` ("from_rest=(x0, psi)").
  std::optional<PhaseState> Build(bool other_given, const std::string& prefix,
                                  const std::string& other, const std::string& ask_other) const;
};

}  // namespace capsubot
