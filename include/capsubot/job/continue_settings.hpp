#pragma once
// The settings of a continuation (ContinueJobOptions, docs/continuation.md) as `capsubot
// continue` offers them: the parameter and its range, the two-parameter curve's second
// parameter and the arclength steps (the shooting's are ShootingSettings). The choices of
// where the branch starts, where it is switched and which special point is followed are read as
// text by the front end (from_orbit, switch, follow).

#include "capsubot/continue/continuation.hpp"
#include "capsubot/job/continue_job.hpp"
#include "capsubot/job/setting_table.hpp"

namespace capsubot {

/// param: the parameter followed.
const SettingTable<ContinueJobOptions>& ContinueParamSettings();

/// from, to: the range of the parameter.
const SettingTable<ContinuationOptions>& ContinuationRangeSettings();

/// param2, from2, to2: the second parameter of the curve of a special point and its range.
const SettingTable<FollowOptions>& FollowSettings();

/// max_points, initial_step, min_step, max_step: the points and arclength steps of the branch.
const SettingTable<ContinuationOptions>& ContinuationStepSettings();

}  // namespace capsubot
