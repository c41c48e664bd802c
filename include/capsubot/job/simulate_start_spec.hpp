#pragma once
// The start of a simulation as a user gives it, part by part: the mass ratio and the state
// (alpha, x0, u0, v0), or the analytic one-impact orbit instead. The command line and the
// Python module read their starts here, with the same rules and messages.

#include <optional>
#include <string>

#include "capsubot/job/simulate_job.hpp"
#include "capsubot/model/setting_names.hpp"

namespace capsubot {

struct SimulateStartSpec {
  std::optional<double> alpha, x0, u0, v0;

  /// The orbit's start when `from_orbit` (then no part may be given), else the state (all four
  /// given). Throws std::invalid_argument naming the settings (alpha, x0, u0, v0, from_orbit)
  /// in the front end's `names`; `ask_orbit` says how to ask for the orbit in its syntax
  /// ("--from-orbit", "from_orbit=True").
  SimulateStart Build(bool from_orbit, const std::string& ask_orbit,
                      const FlagNames& names = {}) const;
};

}  // namespace capsubot
