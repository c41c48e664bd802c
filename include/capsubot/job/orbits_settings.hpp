#pragma once
// The settings of `capsubot orbits` (OrbitsJobOptions) as the front ends offer them.

#include "capsubot/job/orbits_job.hpp"
#include "capsubot/job/setting_table.hpp"

namespace capsubot {

/// alpha, max_evaluations: their meaning and rules (the force and model are the robot's).
const SettingTable<OrbitsJobOptions>& OrbitsSettings();

}  // namespace capsubot
