#pragma once
// Work split into blocks of consecutive units (the grid points of a sweep, the starts of a
// basin map), computed apart and handed to one sink in block order. A unit's bytes depend
// only on the unit, so the sink receives the same bytes however the blocks were computed:
// by the threads of this process (LocalBlocks) or by other processes as well (a backend of
// the command-line program runs them on the ranks of an MPI job; the library knows nothing
// of MPI). A bounded window of blocks computed ahead of the sink bounds the memory.

#include <chrono>
#include <condition_variable>
#include <cstdint>
#include <exception>
#include <functional>
#include <limits>
#include <mutex>
#include <string>
#include <thread>
#include <vector>

namespace capsubot {

/// Appends the bytes of units [begin, end) to `out` and returns a count the caller gives a
/// meaning (the rows written). One per computing thread: it may hold scratch space.
using BlockCompute =
    std::function<std::int64_t(std::int64_t begin, std::int64_t end, std::string& out)>;
/// Makes the computer of one thread.
using BlockComputeFactory = std::function<BlockCompute()>;
/// Receives block [begin, end): its bytes and count, in block order, on the calling thread.
using BlockSink = std::function<void(std::int64_t begin, std::int64_t end, const std::string& bytes,
                                     std::int64_t count)>;

/// Units [first, end) in blocks of `block` units (the last one may be shorter).
struct BlockPlan {
  std::int64_t first = 0;  ///< first unit to compute
  std::int64_t end = 0;    ///< one past the last unit
  std::int64_t block = 1;  ///< units per block; >= 1
  int threads = 1;         ///< computing threads of this process; >= 1

  std::int64_t Blocks() const { return end > first ? (end - first + block - 1) / block : 0; }
  std::int64_t Begin(std::int64_t k) const { return first + k * block; }
  std::int64_t End(std::int64_t k) const;
  /// Throws std::invalid_argument naming the bad field.
  void Validate() const;
};

/// Computing threads of this process for `threads` asked: `threads`, or one per core of the
/// machine for 0; at most one per unit when `units` is given, and at least one.
int WorkerThreads(int threads, std::int64_t units = std::numeric_limits<std::int64_t>::max());

/// Block size for `units` units on `threads` computing threads: at most `most` units, and
/// small enough that every thread gets about 8 blocks (balance); at least 1.
std::int64_t BalancedBlock(std::int64_t units, int threads, std::int64_t most);

/// Distributes the blocks of a plan over its computers.
class BlockBackend {
 public:
  virtual ~BlockBackend() = default;
  /// Computing threads over all the processes it uses, `local` of them in this one.
  virtual int Threads(int local) const = 0;
  /// Computes every block of `plan` with computers made by `make` and calls `sink` with each
  /// block in order, on the calling thread. The first exception of a computer or of `sink`
  /// stops the run and is rethrown once every thread stopped.
  virtual void Run(const BlockPlan& plan, const BlockComputeFactory& make,
                   const BlockSink& sink) const = 0;
};

/// The backend of this process alone: plan.threads threads.
const BlockBackend& LocalBlocks();

/// The shared state of a run: which block is claimed next, the computed blocks waiting for
/// the sink (at most `window` ahead of it), the first error. For backends: LocalBlocks is
/// plan.threads ComputeBlocks loops and one DeliverNext loop.
class BlockQueue {
 public:
  BlockQueue(const BlockPlan& plan, std::int64_t window);

  const BlockPlan& plan() const { return plan_; }
  /// The next block to compute; waits while the window is full. -1: none left, or stopped.
  std::int64_t Claim();
  /// As Claim without waiting: -1 none left or stopped, -2 the window is full now.
  std::int64_t TryClaim();
  /// Block k computed (claimed before): swaps `bytes` into its place (`bytes` gets a buffer
  /// to reuse).
  void Deliver(std::int64_t k, std::string& bytes, std::int64_t count);
  /// Waits at most `timeout` for the next block in order; passes it to `sink` and returns
  /// true, or returns false. Throws what `sink` throws.
  bool DeliverNext(const BlockSink& sink, std::chrono::microseconds timeout);
  /// Every block passed to the sink.
  bool done() const;
  /// Stops the run with error `e` (the first one is kept); wakes every waiting thread.
  void Stop(std::exception_ptr e);
  bool stopped() const;
  /// Rethrows the first error, if any.
  void RethrowError() const;

 private:
  struct Slot {
    std::string bytes;
    std::int64_t count = 0;
    bool ready = false;
  };
  Slot& SlotOf(std::int64_t k);

  BlockPlan plan_;
  std::int64_t blocks_ = 0;
  std::vector<Slot> slots_;
  mutable std::mutex mutex_;
  std::condition_variable claim_cv_, ready_cv_;
  std::int64_t next_claim_ = 0, next_write_ = 0;
  bool stopped_ = false;
  std::exception_ptr error_;
};

/// A computing thread's loop: claims blocks of `queue`, computes them with `compute` and
/// delivers them until none is left; an exception stops the queue.
void ComputeBlocks(BlockQueue& queue, const BlockComputeFactory& make);

/// The computing threads of this process in a run (the one pool of every backend): `threads`
/// ComputeBlocks loops over `queue`, started at construction, joined by Join or at
/// destruction (`queue` and `make` must outlive them). When the system refuses a thread, the
/// ones started do the blocks (throws std::system_error only when it refuses the first).
class ComputeThreads {
 public:
  ComputeThreads(BlockQueue& queue, const BlockComputeFactory& make, std::int64_t threads);
  ~ComputeThreads() { Join(); }
  ComputeThreads(const ComputeThreads&) = delete;
  ComputeThreads& operator=(const ComputeThreads&) = delete;

  /// Waits for every thread to end (the queue done or stopped).
  void Join();

 private:
  std::vector<std::thread> pool_;
};

}  // namespace capsubot
