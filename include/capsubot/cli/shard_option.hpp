#pragma once
// --shard K/N: one shard of a run split over N processes or machines, and the options that
// only a shard takes (--resume, --checkpoint-seconds).

#include <CLI/CLI.hpp>
#include <string>
#include <utility>

namespace capsubot::cli {

/// --shard "K/N" -> (K, N): decimal digits, K and N at most INT_MAX, 0 <= K < N; throws
/// std::invalid_argument naming the option, its value and the rule.
std::pair<int, int> ParseShard(const std::string& text);

/// Whether --shard `text` splits the run into N >= 2 shards: false when not given ("") and
/// for 0/1, the one shard of the whole run, which writes the files of the run without
/// --shard. Throws ParseShard's errors.
bool SplitsRun(const std::string& text);

/// Refuses --resume or a given --checkpoint-seconds of `cmd` when not `sharded` (N >= 2)
/// (std::invalid_argument): only a shard is checkpointed, not the whole `what` ("map").
void RequireShardForResume(const CLI::App& cmd, bool sharded, const char* what);

}  // namespace capsubot::cli
