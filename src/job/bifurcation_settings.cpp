#include "capsubot/job/bifurcation_settings.hpp"

namespace capsubot {

const SettingTable<BifurcationOptions>& BifurcationRangeSettings() {
  using B = BifurcationOptions;
  static const SettingTable<BifurcationOptions> table = {
      {"from", &B::from, "first value of the parameter"},
      {"to", &B::to, "last value of the parameter"},
      {"steps", &B::steps, "values of the parameter, both ends included"}};
  return table;
}

const SettingTable<BifurcationShardFiles>& BifurcationResumeSettings() {
  using F = BifurcationShardFiles;
  static const SettingTable<BifurcationShardFiles> table = {
      {"resume", &F::resume,
       "with {shard}: continue a killed shard from the checkpoints FILE.checkpoint of "
       "{impacts} and {summary} (same options required; their checksums are verified)"},
      {"checkpoint_seconds", &F::checkpoint_seconds,
       "with {shard}: minimum time [s] between two checkpoints of each shard file (written as "
       "FILE.partial, renamed at the end); 0: after every part"}};
  return table;
}

}  // namespace capsubot
