#pragma once
// The effort of the reach search (ReachEffort, docs/model.md section 13) as the front ends offer
// it: the evaluation budgets of its stages, its time limit, and the budgets of each drive beyond
// the sine. Its grid of starts is read as text by the front end (reach_starts, NXxNPSI).

#include "capsubot/job/setting_table.hpp"
#include "capsubot/reach/reach_effort.hpp"

namespace capsubot {

/// reach_evaluations, reach_local_evaluations, reach_seconds: the search's global stage, its
/// local polish and its wall-clock limit; drive_evaluations, drive_polishes,
/// drive_local_evaluations, drive_refine_evaluations, drive_screens: the search of each Fourier
/// drive K >= 2 and pulse drive. The fields are the names ReachEffort::Validate gives them.
const SettingTable<ReachEffort>& ReachEffortSettings();

}  // namespace capsubot
