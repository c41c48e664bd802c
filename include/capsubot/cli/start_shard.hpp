#pragma once
// How `basins` and `attractors` run their map of starts: the whole map or `--shard K/N` (with
// `--resume`, `--checkpoint-seconds`), and on the ranks of an MPI job when started by mpirun
// (capsubot/cluster/ranks.hpp). The run itself is the library's (capsubot/job/attractors_job.hpp).

#include <cstdint>
#include <functional>
#include <string>
#include <utility>
#include <vector>

#include "capsubot/attract/start_grid.hpp"
#include "capsubot/cli/attract_options.hpp"
#include "capsubot/cli/command.hpp"
#include "capsubot/cluster/ranks.hpp"

namespace capsubot::cli {

struct StartShardCliOptions {
  std::string shard;  ///< "K/N"; empty or 0/1: the whole map
  bool resume = false;
  double checkpoint_seconds = 0.5;
};

/// Adds --shard, --resume and --checkpoint-seconds to `cmd` (of command `name`).
void AddStartShardOptions(CLI::App& cmd, StartShardCliOptions& options, const char* name);

/// What `attractors` and `basins` read alike: the robot, the grid of starts, the CSV of the
/// map, the shard, the threads, --json.
struct MapCommandOptions {
  RobotOptions robot;
  std::string starts = StartGrid{}.Text();
  std::string output;  ///< the CSV of the map (-o); empty: none
  StartShardCliOptions shard;
  int threads = 0;
  bool json = false;
};

/// Adds the robot's options (AddRobotOptions) and --starts (`starts_help`, its default shown)
/// to `cmd`.
void AddMapStartOptions(CLI::App& cmd, MapCommandOptions& options, const char* starts_help);

/// Adds the shard's options (AddStartShardOptions, of command `name`), --threads, --json
/// (`json_help`) and the progress options to `cmd`.
void AddMapRunOptions(CLI::App& cmd, MapCommandOptions& options, const char* name,
                      const char* json_help);

/// The map command `cmd` that `run` runs: its messages in the flags of the long-run options
/// (MotionFlagNames), its work distributed over the ranks of an MPI job.
Command MapCommand(CLI::App* cmd, const std::function<int()>& run);

/// The run of the map of command `cmd`: one shard (--shard K/N, N >= 2) written to `output`,
/// or the whole map (written to `output` when given), with the run's provenance as the file's
/// comment lines. Refuses --resume or --checkpoint-seconds without a shard and the `refused`
/// options (flag, given) with a shard: they need the whole map (std::invalid_argument naming
/// the option). The job checks the shard against its starts and the checkpoints' interval.
StartMapRun MapRun(const StartShardCliOptions& options, const CLI::App& cmd,
                   const std::string& output,
                   const std::vector<std::pair<const char*, bool>>& refused);

/// Runs the map job whose options are `map` (those of `attractors`, or the map of `basins`):
/// under mpirun rank 0 runs it and the other ranks compute the blocks of `work()` that it sends
/// until it says stop (capsubot/cluster/ranks.hpp); else this process runs it. `run` runs the job
/// with the ranks' backend and the progress over the starts set in `map`, and returns what the
/// command prints. Returns the exit status (0).
int RunMapOnRanks(AttractorsJobOptions& map, const std::function<StartMapWork()>& work,
                  const std::function<std::string()>& run);

}  // namespace capsubot::cli
