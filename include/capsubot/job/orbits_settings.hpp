#pragma once
// The settings of `capsubot orbits` (OrbitsJobOptions) as the front ends offer them.

#include "capsubot/job/orbits_job.hpp"
#include "capsubot/job/setting_table.hpp"

namespace capsubot {

/// max_evaluations: its meaning and rule (the force, T0, e and alpha are the robot's:
/// MassRatioSettings, params_settings.hpp).
const SettingTable<OrbitsJobOptions>& OrbitsSettings();

}  // namespace capsubot
