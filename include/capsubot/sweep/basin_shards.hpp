#pragma once
// Joining the shards of a basin map (`capsubot basins --shard K/N`, and the map of the starts
// from rest of `capsubot attractors --shard K/N`, start_map.hpp): each shard file holds the
// rows of the starts s with s % N = K, their attractor cells empty (a label depends on the
// whole map); the join regroups every start's motion as ClassifyStarts does and writes the
// map's CSV byte for byte (docs/cluster.md).

#include <string>
#include <vector>

#include "capsubot/attract/attractors.hpp"
#include "capsubot/sweep/sweep_merge.hpp"

namespace capsubot {

/// Joins the files of the N shards of one basin map, given in any order, into `output`
/// (written atomically): the comment lines (without the shard line), the header and the rows
/// in start order (start s from shard s % N), with the attractor of each start (1 = reached
/// from most starts) from GroupMotions of all the motions read. The shard checks are
/// MergeSweepShards' (line "# shard K/N of T starts", same run, none missing or twice, none
/// truncated or longer); a row that is not a basin row with an empty attractor cell is refused.
/// Throws std::invalid_argument naming the file and the rule, IoError for a file that cannot be
/// read or written; `output` is then untouched.
MergeSummary MergeBasinShards(const std::vector<std::string>& shards, const std::string& output,
                              double velocity_tolerance = AttractorOptions{}.velocity_tolerance);

/// MergeBasinShards when the first file is a basin shard (its shard line counts "starts"),
/// MergeBifurcationShards when it counts "continuations", else MergeSweepShards.
MergeSummary MergeShards(const std::vector<std::string>& shards, const std::string& output);

}  // namespace capsubot
