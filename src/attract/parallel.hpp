#pragma once
// The computing threads of a run of blocks (capsubot/parallel/blocks.hpp) over independent items: each
// item's result depends only on the item, so the output does not depend on the number of
// threads.

#include <algorithm>
#include <cstdint>
#include <thread>

namespace capsubot::detail {

/// Threads to use for `items` items: `threads` (0: all cores), at most one per item.
inline int WorkerCount(int threads, std::int64_t items) {
  const int wanted =
      threads > 0 ? threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  return static_cast<int>(std::max<std::int64_t>(1, std::min<std::int64_t>(wanted, items)));
}

}  // namespace capsubot::detail
