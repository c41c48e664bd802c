#pragma once
// The CSV of a map of starts (`capsubot basins`, `capsubot attractors -o`): one row per start,
// x0, psi (or u0), attractor, period, impacts_right, impacts_left, mean_velocity, status; and
// its shards (`--shard K/N`): the rows of the starts s with s % N = K, their attractor cells
// empty (a label depends on the whole map), written to `<output>.partial` with a checkpoint so
// that a killed shard continues with `resume` (as a sweep does: sweep.hpp). `capsubot merge`
// joins the shards (basin_shards.hpp).

#include <cstdint>
#include <string>
#include <vector>

#include "capsubot/attract/attractors.hpp"

namespace capsubot {

/// The header line of the map, with its line break: second column u0 (`u0`) or psi.
const char* StartMapHeader(bool u0);

/// Appends the row of one start to `out`: `attractor` is its label ("" in a shard file).
void AppendStartMapRow(std::string& out, const PhaseState& start, const Motion& motion, bool u0,
                       const std::string& attractor);

/// Writes the map of `starts` (in their order) with their motions and labels from `a` (of
/// ClassifyStarts or GroupMotions of these starts; label k + 1 for a.attractors[k]) to `output`,
/// atomically (AtomicFile, "-": standard output): `comments` (the run's name, each line
/// "# ...\n"; empty: none), the header, one row per start. Throws std::invalid_argument when
/// the sizes differ, IoError when the file cannot be written.
void WriteStartMap(const std::string& output, const std::vector<PhaseState>& starts,
                   const Attractors& a, bool u0, const std::string& comments = "");

/// Which starts a shard holds and where it is written.
struct StartShardOptions {
  int shard = 0;       ///< K: the starts s with s % shards = shard; 0 <= shard < shards
  int shards = 1;      ///< N; 1 <= shards <= the starts
  std::string output;  ///< the CSV ("-": standard output, written in place, no resume)
  /// The lines before the shard line (each "# ...\n"): the run's name, those of the whole
  /// map's file (WriteStartMap), which the join writes.
  std::string comments;
  bool u0 = false;  ///< second column u0 (else psi)
  /// Continue from `<output>.checkpoint` if it exists and was written by this same shard
  /// (same comment lines, shard line and header).
  bool resume = false;
  /// Minimum time between two checkpoints (fsync of the partial file, then of the
  /// checkpoint), in seconds; 0 checkpoints after every block of starts.
  double checkpoint_seconds = 0.5;

  /// Throws std::invalid_argument naming the first bad field, its value and the rule
  /// (`starts`: the size of the map).
  void Validate(std::size_t starts) const;
};

/// The starts of shard K of N: starts[s] for s % N = K, in order.
std::vector<PhaseState> ShardStarts(const std::vector<PhaseState>& starts, int shard, int shards);

/// What a shard run did.
struct StartShardSummary {
  std::int64_t starts = 0;   ///< starts of the shard (rows of its file)
  std::int64_t resumed = 0;  ///< of them taken over from a checkpoint (not recomputed)
};

/// Computes the long-run motion of the starts of shard options.shard of `starts` (the whole
/// map, in its order) and writes its file: options.comments, the line "# shard K/N of T
/// starts", the header and one row per start with an empty attractor cell. The rows go to
/// `<output>.partial`, checkpointed, renamed to `output` at the end; killed, the same call with
/// `resume` continues after the last checkpoint. `progress` is told the shard's starts done.
/// Throws std::invalid_argument for bad inputs or a checkpoint of another run or shard (before
/// any file is touched), IoError for a file that cannot be used or a damaged checkpoint.
StartShardSummary WriteStartShard(const RobotModel& robot, const std::vector<PhaseState>& starts,
                                  const AttractorOptions& attractor,
                                  const StartShardOptions& options,
                                  const StartsProgress& progress = {},
                                  const BlockBackend& backend = LocalBlocks());

}  // namespace capsubot
