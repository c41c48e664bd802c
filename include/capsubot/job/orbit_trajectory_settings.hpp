#pragma once
// The grid of the trajectory of a one-impact orbit over one period, which `capsubot solve
// --trajectory` writes beside its result (text::WriteOrbitTrajectoryCsv), and its settings as
// the front ends offer them.

#include <cstdint>

#include "capsubot/job/setting_table.hpp"

namespace capsubot {

struct OrbitTrajectoryOptions {
  /// Rows at phi = tau i / (samples - 1), i = 0 .. samples - 1 (phi = 0 just after the impact,
  /// tau just before the next one); 2 <= samples <= kMaxTrajectoryRows.
  std::int64_t samples = 1001;

  /// Throws std::invalid_argument naming samples, its value and the rule.
  void Validate() const;
};

/// samples: its meaning and range. Its help names the front end's option of the file written
/// ({trajectory}).
const SettingTable<OrbitTrajectoryOptions>& OrbitTrajectorySettings();

}  // namespace capsubot
