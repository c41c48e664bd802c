#pragma once
// The settings of Newton shooting (ShootingOptions) as `capsubot periodic` offers them.

#include "capsubot/attract/periodic.hpp"
#include "capsubot/job/setting_table.hpp"

namespace capsubot {

/// max_period, step, chatter_velocity: their meaning (the start's transient is the job's).
const SettingTable<ShootingOptions>& ShootingSettings();

}  // namespace capsubot
