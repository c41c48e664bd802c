// --shard K/N of `basins` and `attractors`: one shard of the map of starts, resumable.

#include "capsubot/cli/start_shard.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <string>
#include <tuple>

#include "capsubot/cli/progress.hpp"
#include "capsubot/cli/provenance.hpp"
#include "capsubot/cli/shard_option.hpp"

namespace capsubot::cli {

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

void AddMapStartOptions(CLI::App& cmd, MapCommandOptions& options, const char* starts_help) {
  AddRobotOptions(cmd, options.robot);
  cmd.add_option("--starts", options.starts, starts_help)->capture_default_str();
}

void AddMapRunOptions(CLI::App& cmd, MapCommandOptions& options, const char* name,
                      const char* json_help) {
  AddStartShardOptions(cmd, options.shard, name);
  AddThreadsOption(cmd, options.threads);
  cmd.add_flag("--json", options.json, json_help);
  AddProgressOptions(cmd);
}

Command MapCommand(CLI::App* cmd, const std::function<int()>& run) {
  // The job names the shard and its checkpoints by their fields, too.
  static const FlagNames kFlags = [] {
    FlagNames names = MotionFlagNames();
    names.insert(names.end(),
                 {{"shard", "--shard"}, {"checkpoint_seconds", "--checkpoint-seconds"}});
    return names;
  }();
  return {cmd, [run] { return RunNamingFlags(kFlags, run); }, [] { return true; }};
}

StartMapRun MapRun(const StartShardCliOptions& options, const CLI::App& cmd,
                   const std::string& output,
                   const std::vector<std::pair<const char*, bool>>& refused) {
  const bool sharded = SplitsRun(options.shard);
  RequireShardForResume(cmd, sharded, "map");
  // The comment lines of the whole map's file; a shard carries them for the join.
  const std::string comments = OutputProvenance(cmd).CommentLine();
  if (!sharded) return WholeStartMap{output, comments};
  StartMapShard run;
  StartShardOptions& file = run.file;
  std::tie(file.shard, file.shards) = ParseShard(options.shard);
  for (const auto& [flag, set] : refused) {
    if (set) {
      throw std::invalid_argument(fmt::format(
          "{} is invalid with --shard: expected it only on a whole map (draw the merged CSV: "
          "docs/cluster.md)",
          flag));
    }
  }
  file.output = output;
  file.comments = comments;
  file.resume = options.resume;
  file.checkpoint_seconds = options.checkpoint_seconds;
  return run;
}

int RunMapOnRanks(AttractorsJobOptions& map, const std::function<StartMapWork()>& work,
                  const std::function<std::string()>& run) {
  Ranks ranks;  // under mpirun: rank 0 runs the job, the others compute blocks of its starts
  if (ranks.worker()) {
    const StartMapWork blocks = work();
    return ranks.Serve(blocks.Blocks(), blocks.attractor.threads);
  }
  map.backend = &ranks.backend();
  map.progress = CountProgress("starts");
  fmt::print("{}", run());
  return 0;
}

}  // namespace capsubot::cli
