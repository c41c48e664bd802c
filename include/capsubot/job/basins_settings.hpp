#pragma once
// The settings of the x0-u0 plane of starts of a basin map (VelocityPlane, basins_job.hpp) as
// `capsubot basins` offers them.

#include "capsubot/job/basins_job.hpp"
#include "capsubot/job/setting_table.hpp"

namespace capsubot {

/// psi, u_min, u_max: the forcing phase and the range of u0 of the starts in the x0-u0 plane.
const SettingTable<VelocityPlane>& VelocityPlaneSettings();

}  // namespace capsubot
