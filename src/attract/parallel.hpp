#pragma once
// A bounded parallel loop over independent items: each item's result depends only on the item,
// so the output does not depend on the number of threads.

#include <algorithm>
#include <atomic>
#include <cstdint>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace capsubot::detail {

/// Threads to use for `items` items: `threads` (0: all cores), at most one per item.
inline int WorkerCount(int threads, std::int64_t items) {
  const int wanted =
      threads > 0 ? threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  return static_cast<int>(std::max<std::int64_t>(1, std::min<std::int64_t>(wanted, items)));
}

/// Calls work(item, worker) for item = 0..items-1 on `workers` threads (worker in
/// [0, workers): index of per-thread scratch space), then done(count) under a lock after each
/// item (count increasing). The first exception of any worker is rethrown after all stopped.
template <class Work, class Done>
void ParallelFor(std::int64_t items, int workers, Work&& work, Done&& done) {
  std::atomic<std::int64_t> next{0};
  std::atomic<bool> abort{false};
  std::mutex mutex;
  std::int64_t finished = 0;
  std::exception_ptr error;
  const auto run = [&](int worker) {
    try {
      for (;;) {
        const std::int64_t i = next.fetch_add(1);
        if (i >= items || abort.load()) return;
        work(i, worker);
        std::lock_guard<std::mutex> lock(mutex);
        done(++finished);
      }
    } catch (...) {
      std::lock_guard<std::mutex> lock(mutex);
      if (!error) error = std::current_exception();
      abort = true;
    }
  };
  std::vector<std::thread> pool;
  pool.reserve(static_cast<std::size_t>(std::max(0, workers - 1)));
  for (int w = 1; w < workers; ++w) pool.emplace_back(run, w);
  run(0);
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);
}

}  // namespace capsubot::detail
