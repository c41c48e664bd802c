// The run of a map of starts (attractors, basins): whole or one shard, on a block backend.

#include "start_map_run.hpp"

#include <fmt/format.h>

#include "capsubot/io/io.hpp"

namespace capsubot {

BlockComputeFactory StartMapWork::Blocks() const { return MotionBlocks(robot, starts, attractor); }

namespace detail {

AttractorsJobResult RunStartMap(const AttractorsJobOptions& options,
                                const std::vector<PhaseState>& starts, bool u0,
                                const char* command) {
  AttractorsJobResult result;
  result.options = options;
  result.options.progress = {};
  result.options.on_stage = {};
  result.options.attractor.interrupt = {};
  result.options.backend = nullptr;
  const BlockBackend& backend = options.backend != nullptr ? *options.backend : LocalBlocks();
  if (const auto* shard = std::get_if<StartMapShard>(&options.run)) {
    StartShardOptions file = shard->file;
    file.u0 = u0;
    std::get<StartMapShard>(result.options.run).file.u0 = u0;
    TellStage(options.on_stage, fmt::format("{}: shard {}/{} of {} starts", command, file.shard,
                                            file.shards, starts.size()));
    result.shard =
        WriteStartShard(options.robot, starts, options.attractor, file, options.progress, backend);
    TellStage(options.on_stage, "");
    return result;
  }
  const WholeStartMap& whole = std::get<WholeStartMap>(options.run);
  if (!whole.output.empty()) CheckWritable(whole.output, "output");  // before the long run
  TellStage(options.on_stage, fmt::format("{}: {} starts", command, starts.size()));
  result.attractors =
      ClassifyStarts(options.robot, starts, options.attractor, options.progress, backend);
  if (!whole.output.empty()) {
    WriteStartMap(whole.output, starts, result.attractors, u0, whole.comments);
  }
  TellStage(options.on_stage, "");
  return result;
}

StartMapWork StartMapWorkOf(const AttractorsJobOptions& options,
                            const std::vector<PhaseState>& starts) {
  StartMapWork work;
  work.robot = options.robot;
  work.attractor = options.attractor;
  if (const auto* shard = std::get_if<StartMapShard>(&options.run)) {
    work.starts = ShardStarts(starts, shard->file.shard, shard->file.shards);
  } else {
    work.starts = starts;
  }
  return work;
}

}  // namespace detail
}  // namespace capsubot
