// --shard K/N of `basins` and `attractors`: one shard of the map of starts, resumable.

#include "start_shard.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <tuple>

#include "capsubot/sweep/start_map.hpp"
#include "provenance.hpp"
#include "ranks.hpp"

namespace capsubot::app {

void AddStartShardOptions(CLI::App& cmd, StartShardCliOptions& options, const char* name) {
  cmd.add_option("--shard", options.shard,
                 fmt::format("compute only shard K of N (0 <= K < N): the starts s with s % N = "
                             "K (in the order x0 major); the CSV gets a comment line naming the "
                             "run, a line '# shard K/N of T starts' and empty attractor cells; "
                             "`capsubot merge OUT SHARDS...` joins the N files into the CSV of "
                             "`capsubot {}` without --shard, which 0/1 writes (docs/cluster.md)",
                             name));
  cmd.add_flag("--resume", options.resume,
               "with --shard: continue a killed shard from <output>.checkpoint (same options "
               "required; the checkpoint's checksums are verified)");
  cmd.add_option("--checkpoint-seconds", options.checkpoint_seconds,
                 "with --shard: minimum time [s] between two checkpoints of the shard file; 0: "
                 "after every block of starts")
      ->capture_default_str();
}

void RequireShardForResume(const CLI::App& cmd, const StartShardCliOptions& options) {
  RequireShardForResume(cmd, SplitsRun(options.shard), "map");
}

int RunStartShard(const StartShardCliOptions& options, const CLI::App& cmd,
                  const RobotOptions& robot, const Forcing& forcing,
                  const std::vector<PhaseState>& starts, const AttractorOptions& attractor, bool u0,
                  const std::string& output,
                  const std::vector<std::pair<const char*, bool>>& refused) {
  StartShardOptions so;
  std::tie(so.shard, so.shards) = ParseShard(options.shard);
  if (static_cast<std::size_t>(so.shards) > starts.size()) {
    throw std::invalid_argument(
        fmt::format("--shard = {} is invalid: the map has only {} starts: expected at most as "
                    "many shards as starts",
                    options.shard, starts.size()));
  }
  RequireCheckpointSeconds(options.checkpoint_seconds);
  for (const auto& [flag, set] : refused) {
    if (set) {
      throw std::invalid_argument(fmt::format(
          "{} is invalid with --shard: expected it only on a whole map (draw the merged CSV: "
          "docs/cluster.md)",
          flag));
    }
  }
  Ranks ranks;  // under mpirun: rank 0 writes, the others compute blocks of the shard's starts
  if (ranks.worker()) {
    const std::vector<PhaseState> mine = ShardStarts(starts, so.shard, so.shards);
    return ranks.Serve(MotionBlocks(forcing, robot.params, robot.alpha, mine, attractor),
                       attractor.threads);
  }
  so.output = output;
  so.comments = OutputProvenance(cmd).CommentLine();  // that of the whole map's file
  so.u0 = u0;
  so.resume = options.resume;
  so.checkpoint_seconds = options.checkpoint_seconds;
  const StartShardSummary s = WriteStartShard(forcing, robot.params, robot.alpha, starts, attractor,
                                              so, CountProgress("starts"), ranks.backend());
  fmt::print("{}: shard {}/{}: {} of {} starts written to {}{}\n", cmd.get_name(), so.shard,
             so.shards, s.starts, starts.size(), output,
             s.resumed > 0 ? fmt::format(" ({} resumed from the checkpoint)", s.resumed) : "");
  return 0;
}

}  // namespace capsubot::app
