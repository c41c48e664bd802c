#pragma once
// The shard files of a bifurcation study (`capsubot bifurcation --shard K/N`) and their join.
// A shard computes some continuations (BifurcationOptions::shard); its files (-o impacts,
// --summary) hold, after the comment lines (the run's name, "# shard K/N of T continuations")
// and the header, the rows of its parts (bifurcation.hpp: per value of the second parameter,
// up sweep, down sweep, analytic orbits), each part after a line "# part P of Q: R rows".
// The join puts the parts of all shards in order: the file of the whole study, byte for byte.

#include <cstdint>
#include <string>
#include <vector>

#include "capsubot/sweep/sweep_merge.hpp"

namespace capsubot {

/// The line before the rows of part `part` of `parts` in a shard file, with its line break:
/// "# part 3 of 8: 120 rows\n".
std::string BifurcationPartLine(int part, int parts, std::int64_t rows);

/// Joins the files of the N shards of one bifurcation study (all impacts files or all
/// summary files), given in any order, into `output` (written atomically): the comment lines
/// (without the shard line), the header and the rows of parts 0 .. Q-1 in order, without
/// their part lines. The shard checks are
/// MergeSweepShards' (same run, none missing or twice); every part must be in exactly one
/// file with its R rows. Throws std::invalid_argument naming the file and the rule, IoError for
/// a file that cannot be read or written; `output` is then untouched.
MergeSummary MergeBifurcationShards(const std::vector<std::string>& shards,
                                    const std::string& output);

}  // namespace capsubot
