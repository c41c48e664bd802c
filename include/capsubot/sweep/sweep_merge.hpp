#pragma once
// Joining the shards of a sweep (SweepOptions::shard, shards): N files computed apart, e.g. by
// the tasks of a cluster job array, into the file of the whole grid, byte for byte.

#include <cstdint>
#include <string>
#include <vector>

namespace capsubot {

/// What MergeSweepShards did.
struct MergeSummary {
  int shards = 0;           ///< shard files joined
  std::int64_t points = 0;  ///< grid points in the output
  std::int64_t rows = 0;    ///< data rows in the output
};

/// Joins the files of the N shards of one sweep, given in any order, into `output` (written
/// atomically, as AtomicFile): the comment lines (without the shard line), the header, and
/// the rows in grid order (point p from shard p % N) - the bytes the sweep of the whole grid
/// writes. Checks first that every file is a shard ("# shard K/N of T points"), that all
/// belong to the same sweep (same comment and header lines, same N and T), that none is
/// missing or given twice, that `output` is none of them (also through a symlink or a hard
/// link), and, while joining, that none is truncated, holds extra rows or a line longer than
/// kMaxLineBytes; the numbers of the shard line are range-checked, never wrapped. Throws
/// std::invalid_argument naming the file(s) and the broken rule, IoError for a file that cannot be
/// read or written; `output` is then untouched.
MergeSummary MergeSweepShards(const std::vector<std::string>& shards, const std::string& output);

}  // namespace capsubot
