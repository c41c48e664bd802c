#pragma once
// The sweep job's settings (SweepSettings) as `capsubot sweep` offers them: the mode and its
// own numbers, the search of the modes that optimise (its SearchRequest and the gait's bound
// and rho_max) and the CSV file. The grid, the force, the model's parameters, the starts of a
// search, stable_only, the shard and the reach search's starts and budgets are read as text or
// by options of their own in the front end.

#include "capsubot/job/setting_table.hpp"
#include "capsubot/job/sweep_settings.hpp"
#include "capsubot/model/gait_requirements.hpp"
#include "capsubot/optimize/optimize_request.hpp"
#include "capsubot/sweep/grid_file.hpp"

namespace capsubot {

/// stability, optimize, scan_points, alpha: the columns of stability, the mode, P1's scan and
/// the reach search's fixed mass ratio.
const SettingTable<SweepSettings>& SweepModeSettings();

/// bound, rho_max: the gait the modes that optimise look for (SweepSettings::search.gait), the
/// meanings of GaitBoundMeanings opened by the modes that use them.
const SettingTable<GaitRequirements>& SweepGaitSettings();

/// harmonics, global_algorithm, local_algorithm, global_evaluations, hops: the search of P2, P3
/// and of the reach search's seed (SweepSettings::search), the meanings of SearchMeanings opened
/// by the modes that use them (not max_time: a sweep runs no clock).
const SettingTable<SearchRequest>& SweepSearchSettings();

/// output, resume, checkpoint_seconds: the CSV file (SweepSettings::file).
const SettingTable<GridFileOptions>& SweepFileSettings();

}  // namespace capsubot
