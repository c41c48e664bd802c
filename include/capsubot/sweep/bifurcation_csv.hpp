#pragma once
// The CSV files of a bifurcation diagram (`capsubot bifurcation`): the impacts (-o) and the
// summary (--summary), their header lines and rows; and the files of one shard of a study
// (`--shard K/N`): its parts, each after its part line (bifurcation_shards.hpp), written part
// after part to `<file>.partial` with a checkpoint `<file>.checkpoint` each (as a sweep does:
// sweep.hpp), so that a killed shard continues with `resume`. `capsubot merge` joins the
// shards (bifurcation_shards.hpp).

#include <cstdint>
#include <string>

#include "capsubot/attract/bifurcation.hpp"

namespace capsubot {

/// The header line of the impacts CSV, with its line break: param, direction, period_index,
/// wall, phase, velocity, after a first column named after the second parameter if any.
std::string BifurcationImpactsHeader(const BifurcationOptions& options);
/// The header line of the summary CSV, with its line break: param, direction, period,
/// impacts_right, impacts_left, mean_velocity, largest_multiplier, largest_multiplier_im,
/// spectral_radius, status, after a first column named after the second parameter if any.
std::string BifurcationSummaryHeader(const BifurcationOptions& options);

/// Appends the rows of every impact of `d` (in order) to `out`; `over`: with the value of the
/// second parameter first.
void AppendImpactRows(std::string& out, const BifurcationDiagram& d, bool over);
/// Appends the rows of every summary point of `d` (in order) to `out`, as AppendImpactRows.
void AppendSummaryRows(std::string& out, const BifurcationDiagram& d, bool over);

/// Where a shard of a bifurcation study is written and how.
struct BifurcationShardFiles {
  std::string impacts;  ///< the impacts CSV (required; "-": standard output, no resume)
  std::string summary;  ///< the summary CSV; empty: none
  /// The lines before the shard line (each "# ...\n"): the run's name, those of the whole
  /// study's files, which the join writes.
  std::string comments;
  /// Continue from `<file>.checkpoint` of each file if it exists and was written by this same
  /// shard (same comment lines, shard line, header and parts); without one, a file starts anew.
  bool resume = false;
  /// Minimum time between two checkpoints of a file (fsync of the partial file, then of the
  /// checkpoint), in seconds; 0 checkpoints after every part.
  double checkpoint_seconds = 0.5;

  /// Throws std::invalid_argument naming the first bad field, its value and the rule.
  void Validate() const;
};

/// What a shard run did.
struct BifurcationShardSummary {
  int parts = 0;                  ///< parts of the shard
  int resumed = 0;                ///< of them taken over from the checkpoints (not computed again)
  std::int64_t impacts = 0;       ///< impact rows of the impacts file (resumed ones included)
  std::int64_t summary_rows = 0;  ///< rows of the summary file (resumed ones included)
};

/// Computes shard options.shard of the study (StreamBifurcation, its parts computed by
/// `backend`: this process's threads by default) and writes its files: the
/// comment lines, the line "# shard K/N of T continuations", the header, then part after part
/// its part line and rows. Each file goes to `<file>.partial` with its checkpoint (at most
/// one every checkpoint_seconds, after a complete part) and both are renamed to their names
/// once every part is written. Killed, the same call with `resume` continues after the parts
/// both checkpoints hold (computing only the others) and gives the same bytes. Throws
/// std::invalid_argument for bad inputs or a checkpoint of another run or shard, IoError for a
/// file that cannot be used or a damaged checkpoint or partial file; the inputs and both
/// checkpoints are checked before any file is touched.
BifurcationShardSummary WriteBifurcationShard(const RobotModel& robot,
                                              const BifurcationOptions& options,
                                              const BifurcationShardFiles& files,
                                              const StartsProgress& progress = {},
                                              const BlockBackend& backend = LocalBlocks());

}  // namespace capsubot
