#include "capsubot/job/shooting_settings.hpp"

namespace capsubot {

const SettingTable<ShootingOptions>& ShootingSettings() {
  using S = ShootingOptions;
  static const SettingTable<ShootingOptions> table = {
      {"max_period", &S::max_period, "largest period searched from the start, in forcing periods"},
      {"step", &S::step, "step of the central finite differences of the Jacobians"},
      {"chatter_velocity", &S::chatter_velocity, "the simulator's chatter cut-off (omega L)"}};
  return table;
}

}  // namespace capsubot
