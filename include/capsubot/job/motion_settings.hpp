#pragma once
// The settings of a long-run motion (MotionOptions) as the commands on attractors, basins,
// periodic motions, bifurcation diagrams and continuation offer them.

#include "capsubot/attract/attractors.hpp"
#include "capsubot/job/setting_table.hpp"

namespace capsubot {

/// transient, record, max_period, state_tolerance, converged_tolerance, chatter_velocity,
/// max_events_per_period: their meaning and rules.
const SettingTable<MotionOptions>& MotionSettings();

}  // namespace capsubot
