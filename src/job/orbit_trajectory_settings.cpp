#include "capsubot/job/orbit_trajectory_settings.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "capsubot/model/limits.hpp"

namespace capsubot {

void OrbitTrajectoryOptions::Validate() const {
  if (samples < 2 || samples > kMaxTrajectoryRows) {
    throw std::invalid_argument(fmt::format("samples = {} is invalid: expected 2 <= samples <= {}",
                                            samples, kMaxTrajectoryRows));
  }
}

const SettingTable<OrbitTrajectoryOptions>& OrbitTrajectorySettings() {
  static const SettingTable<OrbitTrajectoryOptions> table = {
      {"samples", &OrbitTrajectoryOptions::samples, "number of rows of {trajectory}", 2,
       kMaxTrajectoryRows}};
  return table;
}

}  // namespace capsubot
