// Blocks of units computed by threads (or other processes) and handed to one sink in order.

#include "capsubot/parallel/blocks.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <stdexcept>
#include <system_error>
#include <thread>
#include <utility>

namespace capsubot {
namespace {

constexpr int kBlocksPerThread = 8;  // blocks per computing thread: balances the tail
constexpr int kWindowPerThread = 4;  // blocks computed ahead of the sink, per thread
constexpr auto kSinkWait = std::chrono::seconds(1);  // the sink thread's wait (it is woken)

class LocalBackend : public BlockBackend {
 public:
  int Threads(int local) const override { return local; }

  void Run(const BlockPlan& plan, const BlockComputeFactory& make,
           const BlockSink& sink) const override {
    plan.Validate();
    const std::int64_t blocks = plan.Blocks();
    BlockQueue queue(plan, static_cast<std::int64_t>(kWindowPerThread) * plan.threads);
    ComputeThreads workers(queue, make, std::min<std::int64_t>(plan.threads, blocks));
    try {
      while (!queue.done() && !queue.stopped()) queue.DeliverNext(sink, kSinkWait);
    } catch (...) {
      queue.Stop(std::current_exception());
    }
    workers.Join();
    queue.RethrowError();
  }
};

}  // namespace

std::int64_t BlockPlan::End(std::int64_t k) const { return std::min(end, first + (k + 1) * block); }

void BlockPlan::Validate() const {
  if (first < 0 || end < first) {
    throw std::invalid_argument(
        fmt::format("units = [{}, {}) are invalid: expected 0 <= first <= end", first, end));
  }
  if (block < 1) {
    throw std::invalid_argument(fmt::format("block = {} is invalid: expected >= 1 unit", block));
  }
  if (threads < 1) {
    throw std::invalid_argument(fmt::format("threads = {} is invalid: expected >= 1", threads));
  }
}

int WorkerThreads(int threads, std::int64_t units) {
  const int wanted =
      threads > 0 ? threads : std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
  return static_cast<int>(std::max<std::int64_t>(1, std::min<std::int64_t>(wanted, units)));
}

std::int64_t BalancedBlock(std::int64_t units, int threads, std::int64_t most) {
  const std::int64_t balanced =
      units / (static_cast<std::int64_t>(kBlocksPerThread) * std::max(1, threads));
  return std::max<std::int64_t>(1, std::min(most, balanced));
}

const BlockBackend& LocalBlocks() {
  static const LocalBackend backend;
  return backend;
}

BlockQueue::BlockQueue(const BlockPlan& plan, std::int64_t window)
    : plan_(plan), blocks_(plan.Blocks()) {
  slots_.resize(static_cast<std::size_t>(
      std::max<std::int64_t>(1, std::min(std::max<std::int64_t>(window, 1), blocks_))));
}

BlockQueue::Slot& BlockQueue::SlotOf(std::int64_t k) {
  return slots_[static_cast<std::size_t>(k % static_cast<std::int64_t>(slots_.size()))];
}

std::int64_t BlockQueue::Claim() {
  std::unique_lock<std::mutex> lock(mutex_);
  const auto window = static_cast<std::int64_t>(slots_.size());
  claim_cv_.wait(lock, [&] {
    return stopped_ || next_claim_ >= blocks_ || next_claim_ < next_write_ + window;
  });
  if (stopped_ || next_claim_ >= blocks_) return -1;
  return next_claim_++;
}

std::int64_t BlockQueue::TryClaim() {
  std::lock_guard<std::mutex> lock(mutex_);
  if (stopped_ || next_claim_ >= blocks_) return -1;
  if (next_claim_ >= next_write_ + static_cast<std::int64_t>(slots_.size())) return -2;
  return next_claim_++;
}

void BlockQueue::Deliver(std::int64_t k, std::string& bytes, std::int64_t count) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    Slot& slot = SlotOf(k);
    slot.bytes.swap(bytes);
    slot.count = count;
    slot.ready = true;
  }
  ready_cv_.notify_all();
}

bool BlockQueue::DeliverNext(const BlockSink& sink, std::chrono::microseconds timeout) {
  std::int64_t k = 0;
  {
    std::unique_lock<std::mutex> lock(mutex_);
    if (next_write_ >= blocks_) return false;
    k = next_write_;
    const bool ready =
        ready_cv_.wait_for(lock, timeout, [&] { return stopped_ || SlotOf(k).ready; });
    if (!ready || stopped_) return false;
  }
  // Only this thread writes slot k while it is ready: no computer claims it before next_write_
  // moves past it.
  Slot& slot = SlotOf(k);
  sink(plan_.Begin(k), plan_.End(k), slot.bytes, slot.count);
  {
    std::lock_guard<std::mutex> lock(mutex_);
    slot.ready = false;
    next_write_ = k + 1;
  }
  claim_cv_.notify_all();
  return true;
}

bool BlockQueue::done() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return next_write_ >= blocks_;
}

void BlockQueue::Stop(std::exception_ptr e) {
  {
    std::lock_guard<std::mutex> lock(mutex_);
    if (!error_) error_ = std::move(e);
    stopped_ = true;
  }
  claim_cv_.notify_all();
  ready_cv_.notify_all();
}

bool BlockQueue::stopped() const {
  std::lock_guard<std::mutex> lock(mutex_);
  return stopped_;
}

void BlockQueue::RethrowError() const {
  std::lock_guard<std::mutex> lock(mutex_);
  if (error_) std::rethrow_exception(error_);
}

void ComputeBlocks(BlockQueue& queue, const BlockComputeFactory& make) {
  try {
    const BlockCompute compute = make();
    std::string bytes;
    for (;;) {
      const std::int64_t k = queue.Claim();
      if (k < 0) return;
      bytes.clear();
      const std::int64_t count = compute(queue.plan().Begin(k), queue.plan().End(k), bytes);
      queue.Deliver(k, bytes, count);
    }
  } catch (...) {
    queue.Stop(std::current_exception());
  }
}

ComputeThreads::ComputeThreads(BlockQueue& queue, const BlockComputeFactory& make,
                               std::int64_t threads) {
  pool_.reserve(static_cast<std::size_t>(std::max<std::int64_t>(threads, 0)));
  for (std::int64_t i = 0; i < threads; ++i) {
    try {
      pool_.emplace_back([&queue, &make] { ComputeBlocks(queue, make); });
    } catch (const std::system_error&) {
      if (pool_.empty()) throw;  // no thread at all: nothing would compute the blocks
      return;                    // the threads started compute every block
    }
  }
}

void ComputeThreads::Join() {
  for (std::thread& t : pool_) {
    if (t.joinable()) t.join();
  }
}

}  // namespace capsubot
