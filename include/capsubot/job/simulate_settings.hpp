#pragma once
// The settings of `capsubot simulate` as the front ends offer them: the run of the simulator
// (SimOptions: its start position y0, how long, its chattering cut-off and work bound) and the
// job's grid of the sampled trajectory (SimulateJobOptions).

#include "capsubot/job/setting_table.hpp"
#include "capsubot/job/simulate_job.hpp"

namespace capsubot {

/// y0, periods, transient, chatter_velocity, max_events_per_period: their meaning and rules
/// (the start alpha, x0, u0, v0 is the job's SimulateFromState).
const SettingTable<SimOptions>& SimulateRunSettings();

/// samples_per_period: the grid of the trajectory (when the job samples one: its field
/// trajectory).
const SettingTable<SimulateJobOptions>& SimulateJobSettings();

}  // namespace capsubot
