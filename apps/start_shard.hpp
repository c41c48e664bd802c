#pragma once
// `--shard K/N` (with `--resume`, `--checkpoint-seconds`) of the commands that run a map of
// starts, `basins` and `attractors`: the shard's starts computed (on the ranks of an MPI job
// when started by mpirun) and written to a resumable shard file (capsubot/sweep/start_map.hpp).

#include <string>
#include <utility>
#include <vector>

#include "attract_options.hpp"

namespace capsubot::app {

struct StartShardCliOptions {
  std::string shard;  ///< "K/N"; empty or 0/1: the whole map
  bool resume = false;
  double checkpoint_seconds = 0.5;
};

/// Adds --shard, --resume and --checkpoint-seconds to `cmd` (of command `name`).
void AddStartShardOptions(CLI::App& cmd, StartShardCliOptions& options, const char* name);

/// Refuses --resume or a changed --checkpoint-seconds without --shard K/N, N >= 2
/// (std::invalid_argument).
void RequireShardForResume(const CLI::App& cmd, const StartShardCliOptions& options);

/// Runs shard options.shard of the map `starts` of command `cmd` (output `output`, second
/// column u0 when `u0`). `refused`: options (flag, given) that need the whole map. Returns the
/// exit code; throws std::invalid_argument for bad input (naming the option).
int RunStartShard(const StartShardCliOptions& options, const CLI::App& cmd,
                  const RobotOptions& robot, const Forcing& forcing,
                  const std::vector<PhaseState>& starts, const AttractorOptions& attractor, bool u0,
                  const std::string& output,
                  const std::vector<std::pair<const char*, bool>>& refused);

}  // namespace capsubot::app
