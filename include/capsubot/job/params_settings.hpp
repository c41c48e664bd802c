#pragma once
// The robot's parameters T0, e (Params), its mass ratio alpha and the margins a gait must keep
// (Margins) as the commands offer them.

#include "capsubot/job/setting_table.hpp"
#include "capsubot/model/gait_requirements.hpp"
#include "capsubot/model/params.hpp"
#include "capsubot/model/robot_model.hpp"

namespace capsubot {

/// T0, e: their meaning and rules.
const SettingTable<Params>& ParamsSettings();

/// The robot's mass ratio alpha (its force and Params have their own tables).
const SettingTable<RobotModel>& MassRatioSettings();

/// The clearance d, the clearance relative to the stroke d_s and the stick margin s.
const SettingTable<Margins>& MarginsSettings();

}  // namespace capsubot
