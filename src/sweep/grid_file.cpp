// The options of a grid command's CSV file, checked (capsubot/sweep/grid_file.hpp).

#include "capsubot/sweep/grid_file.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "capsubot/model/limits.hpp"

namespace capsubot {

void GridFileOptions::ValidateFile(std::int64_t points) const {
  if (output.empty()) {
    throw std::invalid_argument("output is missing: expected the path of the CSV file to write");
  }
  if (threads < 0 || threads > kMaxThreads) {
    throw std::invalid_argument(
        fmt::format("threads = {} is invalid: expected 1 <= threads <= {} (0: all cores)", threads,
                    kMaxThreads));
  }
  if (shards < 1 || shard < 0 || shard >= shards) {
    throw std::invalid_argument(fmt::format(
        "shard = {}/{} is invalid: expected K/N with N >= 1 shards and 0 <= K < N", shard, shards));
  }
  if (shards > 1 && points < shards) {
    throw std::invalid_argument(fmt::format(
        "shard = {}/{} is invalid: the grid has only {} points: expected at most as many shards "
        "as points",
        shard, shards, points));
  }
  if (!(checkpoint_seconds >= 0.0)) {
    throw std::invalid_argument(
        fmt::format("checkpoint_seconds = {} is invalid: expected >= 0", checkpoint_seconds));
  }
  for (const std::string& line : comments) {
    if (line.find_first_of("\r\n") != std::string::npos) {
      throw std::invalid_argument(
          "comments are invalid: a comment line contains a line break: expected one line each");
    }
  }
}

}  // namespace capsubot
