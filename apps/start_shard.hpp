#pragma once
// How `basins` and `attractors` run their map of starts: the whole map or `--shard K/N` (with
// `--resume`, `--checkpoint-seconds`), and on the ranks of an MPI job when started by mpirun
// (ranks.hpp). The run itself is the library's (capsubot/job/attractors_job.hpp).

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "attract_options.hpp"
#include "ranks.hpp"

namespace capsubot::app {

struct StartShardCliOptions {
  std::string shard;  ///< "K/N"; empty or 0/1: the whole map
  bool resume = false;
  double checkpoint_seconds = 0.5;
};

/// Adds --shard, --resume and --checkpoint-seconds to `cmd` (of command `name`).
void AddStartShardOptions(CLI::App& cmd, StartShardCliOptions& options, const char* name);

/// The run of the map of `starts` starts of command `cmd`: one shard (--shard K/N, N >= 2)
/// written to `output`, or the whole map (written to `output` when given), with the run's
/// provenance as the file's comment lines. Refuses --resume or --checkpoint-seconds without a
/// shard, more shards than starts, and the `refused` options (flag, given) with a shard: they
/// need the whole map (std::invalid_argument naming the option).
StartMapRun MapRun(const StartShardCliOptions& options, const CLI::App& cmd, std::int64_t starts,
                   const std::string& output,
                   const std::vector<std::pair<const char*, bool>>& refused);

/// A worker of an MPI job computes the blocks of `work` that rank 0 sends, until it says stop;
/// returns the exit status (0).
int ServeMap(Ranks& ranks, const StartMapWork& work);

}  // namespace capsubot::app
