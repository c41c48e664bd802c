#pragma once
// The settings of Newton shooting (ShootingOptions) as the periodic motions and their
// continuation offer them.

#include "capsubot/attract/periodic.hpp"
#include "capsubot/job/setting_table.hpp"

namespace capsubot {

/// max_period, step, chatter_velocity: their meaning (the start's transient is the job's). A
/// continuation shoots at its start and along its branch with them.
const SettingTable<ShootingOptions>& ShootingSettings();

}  // namespace capsubot
