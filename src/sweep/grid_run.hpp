#pragma once
// The run of a grid to a CSV file, whatever each point computes: this run's points (the whole
// grid or one shard, interleaved), the file built as `<output>.partial` with its checkpoint
// (SweepFile) and renamed at the end, the rows computed in blocks (blocks.hpp) and appended in
// grid order. RunSweep and RunDesignGrid are this with their own rows.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "capsubot/parallel/blocks.hpp"
#include "capsubot/sweep/sweep.hpp"

namespace capsubot::detail {

/// What a grid run writes and how.
struct GridRun {
  std::string output;       ///< the CSV file (SweepFile: "-" or a non-regular file in place)
  std::string description;  ///< everything that determines the bytes (checks a resume)
  std::string header;       ///< the lines before the rows, each with its line break
  bool resume = false;      ///< continue from the checkpoint of the same run
  double checkpoint_seconds = 0.5;
  std::int64_t points = 0;  ///< points of this run (ShardCount)
  int threads = 1;          ///< computing threads of this process
  /// Points per block for `points` points on `threads` threads (over all processes).
  std::function<std::int64_t(std::int64_t points, int threads)> block_points;
};

/// Points of shard `shard` of `shards` of a grid of `total` points (p % shards == shard).
std::int64_t ShardCount(std::int64_t total, int shard, int shards);

/// The lines before the rows: `# ` + each comment, the shard line with several shards, then
/// the column names joined by ','.
std::string GridHeader(const std::vector<std::string>& comments, int shard, int shards,
                       std::int64_t total, const std::vector<std::string>& columns);

/// Runs the grid (the contract of RunSweep): unit i of `blocks` is this run's i-th point.
SweepSummary RunGridRows(const GridRun& run, const BlockComputeFactory& blocks,
                         const SweepProgressCallback& progress, const BlockBackend& backend);

}  // namespace capsubot::detail
