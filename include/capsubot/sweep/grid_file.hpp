#pragma once
// How a grid command writes its CSV file: the provenance lines, the file, the shard of the grid
// it computes, resume, threads and checkpoints. The options of every grid command
// (SweepOptions, DesignGridOptions) derive from it.

#include <cstdint>
#include <string>
#include <vector>

namespace capsubot {

struct GridFileOptions {
  /// Lines written first, each as `# ` + line (provenance: what made the file); part of the
  /// file's bytes, so a resume must give the same. No line may contain a line break.
  std::vector<std::string> comments;
  /// The CSV file to write (required); "-" (standard output) or a path that is not a regular
  /// file (/dev/stdout, a pipe) is written in place, without checkpoint or resume.
  std::string output;
  /// Compute only shard `shard` of `shards` (0 <= shard < shards): the grid points p with
  /// p % shards == shard, in grid order (interleaved: neighbouring points, of similar cost,
  /// go to different shards). A shard's file has the same comment and header lines plus the
  /// line `# shard K/N of T points`; MergeSweepShards joins the N files into the file of the
  /// whole grid, byte for byte. 1 shard: the whole grid.
  int shard = 0;
  int shards = 1;
  /// Continue from `<output>.checkpoint` if it exists and belongs to this same run.
  bool resume = false;
  /// Worker threads; 0 means std::thread::hardware_concurrency().
  int threads = 0;
  /// Minimum time between two checkpoints (fsync of the partial file, then of the
  /// checkpoint), in seconds; 0 checkpoints after every block.
  double checkpoint_seconds = 0.5;

  /// Throws std::invalid_argument naming the bad field (output, threads, shard,
  /// checkpoint_seconds, comments), its value and the rule, for a grid of `points` points.
  void ValidateFile(std::int64_t points) const;
};

}  // namespace capsubot
