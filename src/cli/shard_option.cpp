#include "capsubot/cli/shard_option.hpp"

#include <fmt/format.h>

#include <cctype>
#include <charconv>
#include <stdexcept>
#include <system_error>

namespace capsubot::cli {

std::pair<int, int> ParseShard(const std::string& text) {
  const std::size_t slash = text.find('/');
  // One count: digits only, no sign and no wrap-around.
  const auto count = [&text](std::size_t begin, std::size_t end, int& value) {
    const auto [stop, error] = std::from_chars(text.data() + begin, text.data() + end, value);
    return begin < end && std::isdigit(static_cast<unsigned char>(text[begin])) != 0 &&
           error == std::errc() && stop == text.data() + end;
  };
  int k = 0, n = 0;
  if (slash == std::string::npos || !count(0, slash, k) || !count(slash + 1, text.size(), n)) {
    throw std::invalid_argument(fmt::format(
        "--shard {} is invalid: expected K/N, e.g. 0/4 (shard K of N, 0 <= K < N)", text));
  }
  if (n < 1 || k >= n) {
    throw std::invalid_argument(fmt::format(
        "--shard = {} is invalid: expected K/N with N >= 1 shards and 0 <= K < N", text));
  }
  return {k, n};
}

bool SplitsRun(const std::string& text) {
  return !text.empty() && ParseShard(text) != std::pair<int, int>(0, 1);
}

void RequireShardForResume(const CLI::App& cmd, bool sharded, const char* what) {
  for (const char* flag : {"--resume", "--checkpoint-seconds"}) {
    if (cmd.count(flag) > 0 && !sharded) {
      throw std::invalid_argument(fmt::format(
          "{} is invalid without --shard K/N, N >= 2: expected it only for a shard of the {} (a "
          "whole {} is not checkpointed)",
          flag, what, what));
    }
  }
}

}  // namespace capsubot::cli
