#pragma once
// The start of Newton's method for a periodic motion as a user gives it: a state (x0, u0, v0,
// psi) or a start at rest (from_rest), with a transient or the period when known. The command
// line and the Python module read their starts here, with the same rules and messages.

#include <optional>
#include <string>

#include "capsubot/attract/start_state_spec.hpp"
#include "capsubot/job/periodic_job.hpp"
#include "capsubot/model/setting_names.hpp"

namespace capsubot {

struct PeriodicStartSpec {
  StartStateSpec state;                  ///< the parts of the state given
  std::optional<PhaseState> from_rest;   ///< the start at rest (RestStart), when given
  std::optional<int> transient, period;  ///< when given

  /// The start: from the period (Newton from the state itself) when `period` is given, else
  /// from the state or from rest after the transient given (or the start's default). Throws
  /// std::invalid_argument for both starts or neither (StartStateSpec) and for a period with a
  /// transient, naming the settings (x0, u0, v0, psi, from_rest, transient, period) in the
  /// front end's `names`; `ask_rest` says how to ask for the start at rest in its syntax.
  PeriodicStart Build(const std::string& ask_rest, const FlagNames& names = {}) const;
};

}  // namespace capsubot
