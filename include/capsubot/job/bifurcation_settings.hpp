#pragma once
// The settings of a bifurcation diagram (BifurcationJobOptions, docs/model.md section 13) as
// `capsubot bifurcation` offers them: the range of the parameter stepped and how a shard of a
// study goes on after a kill. The parameter, the directions, the start, the second parameter
// and the shard are read as text by the front end (SetBifurcationDirection,
// SetBifurcationOver).

#include "capsubot/attract/bifurcation.hpp"
#include "capsubot/job/setting_table.hpp"
#include "capsubot/sweep/bifurcation_csv.hpp"

namespace capsubot {

/// from, to, steps: the values of the parameter stepped.
const SettingTable<BifurcationOptions>& BifurcationRangeSettings();

/// resume, checkpoint_seconds: a shard's files checkpointed and continued after a kill (they
/// name the shard, impacts and summary settings).
const SettingTable<BifurcationShardFiles>& BifurcationResumeSettings();

}  // namespace capsubot
