#pragma once
// The search of the optimize job's gaits (SearchRequest, docs/optimize.md) as `capsubot
// optimize` offers it: the gait asked for (its force bound and stability requirement; its
// margins are the model's settings) and how P1-P3 search it (the Fourier force's harmonics, the
// algorithms, their budgets and time limit). The number of starts, whose default is each
// problem's own, is read by the front end.

#include "capsubot/job/setting_table.hpp"
#include "capsubot/model/gait_requirements.hpp"
#include "capsubot/optimize/optimize_request.hpp"

namespace capsubot {

/// bound, rho_max: the force bound (default: T0) and the largest spectral radius of the gait;
/// their meanings alone, which each job opens with the modes that use them (WithModes).
const SettingTable<GaitRequirements>& GaitBoundMeanings();

/// max_time, harmonics, global_algorithm, local_algorithm, global_evaluations, hops: their
/// meanings alone, as GaitBoundMeanings.
const SettingTable<SearchRequest>& SearchMeanings();

/// The meanings as optimize offers them: opened by the problems that use each (OptimizeModes).
const SettingTable<GaitRequirements>& GaitBoundSettings();
const SettingTable<SearchRequest>& SearchSettings();

}  // namespace capsubot
