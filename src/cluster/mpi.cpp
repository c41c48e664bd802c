// The ranks of an MPI job (ranks.hpp): rank 0 hands blocks of units to the workers, one at a
// time each (a worker gets its next block when it returns one: costly blocks do not stall the
// run), computes blocks with its own threads as well, and gives the blocks to the sink in
// order; the workers compute each block with their threads and send its bytes back. Only the
// main thread of a process calls MPI (MPI_THREAD_FUNNELED).
//
// Messages (all between rank 0 and one worker): kWork {begin, end} (two int64), kResult
// {count (int64), bytes}, kError {message}, kStop {} (after the one distributed run of a
// command, or when rank 0 fails before it). A rank that dies ends the job: mpirun
// kills the others and exits non-zero; a sweep's partial file then stays for --resume and
// no final file is written.

#include <fmt/format.h>
#include <mpi.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstring>
#include <exception>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "capsubot/cluster/ranks.hpp"

namespace capsubot {
namespace {

enum Tag : int { kWork = 1, kResult = 2, kError = 3, kStop = 4 };
constexpr int kWindowPerThread = 4;  // blocks computed ahead of the sink, per computing thread
// Rank 0's wait for its next block between two looks at the workers' messages.
constexpr auto kPoll = std::chrono::microseconds(200);

void Check(int status, const char* call) {
  if (status != MPI_SUCCESS) throw std::runtime_error(fmt::format("MPI: {} failed", call));
}

int Count(std::size_t bytes) {
  if (bytes > static_cast<std::size_t>(std::numeric_limits<int>::max())) {
    throw std::runtime_error(
        fmt::format("MPI: a block of {} bytes is invalid: expected < 2 GiB per block", bytes));
  }
  return static_cast<int>(bytes);
}

// Receives the message `status` announced into `bytes`.
void Receive(const MPI_Status& status, std::string& bytes) {
  int count = 0;
  Check(MPI_Get_count(&status, MPI_BYTE, &count), "MPI_Get_count");
  bytes.resize(static_cast<std::size_t>(count));
  Check(MPI_Recv(bytes.data(), count, MPI_BYTE, status.MPI_SOURCE, status.MPI_TAG, MPI_COMM_WORLD,
                 MPI_STATUS_IGNORE),
        "MPI_Recv");
}

class Master : public BlockBackend {
 public:
  explicit Master(int size) : size_(size) {}

  int Threads(int local) const override { return local * size_; }

  void Run(const BlockPlan& plan, const BlockComputeFactory& make,
           const BlockSink& sink) const override {
    plan.Validate();
    BlockQueue queue(plan, static_cast<std::int64_t>(kWindowPerThread) * plan.threads * size_);
    std::vector<std::int64_t> held(static_cast<std::size_t>(size_), -1);  // block of each worker
    ComputeThreads workers(queue, make, plan.threads);
    try {
      std::string bytes;
      while (!queue.done() && !queue.stopped()) {
        bool busy = false;
        for (int w = 1; w < size_; ++w) {
          if (held[static_cast<std::size_t>(w)] >= 0) continue;
          const std::int64_t k = queue.TryClaim();
          if (k < 0) break;
          const std::int64_t range[2] = {plan.Begin(k), plan.End(k)};
          Check(MPI_Send(range, 2, MPI_INT64_T, w, kWork, MPI_COMM_WORLD), "MPI_Send");
          held[static_cast<std::size_t>(w)] = k;
        }
        for (;;) {
          int arrived = 0;
          MPI_Status status;
          Check(MPI_Iprobe(MPI_ANY_SOURCE, MPI_ANY_TAG, MPI_COMM_WORLD, &arrived, &status),
                "MPI_Iprobe");
          if (arrived == 0) break;
          busy = true;
          TakeResult(status, bytes, held, queue);
        }
        queue.DeliverNext(sink, busy ? std::chrono::microseconds(0) : kPoll);
      }
    } catch (...) {
      queue.Stop(std::current_exception());
    }
    workers.Join();
    // Blocks still out (after an error): take their answers, so that every worker waits for
    // its next order again.
    std::string bytes;
    for (int w = 1; w < size_; ++w) {
      if (held[static_cast<std::size_t>(w)] < 0) continue;
      MPI_Status status;
      Check(MPI_Probe(w, MPI_ANY_TAG, MPI_COMM_WORLD, &status), "MPI_Probe");
      Receive(status, bytes);
    }
    StopWorkers();  // one distributed run per command: the workers need not wait for the rest
    queue.RethrowError();
  }

  /// Tells every worker to stop (once).
  void StopWorkers() const {
    if (stopped_) return;
    stopped_ = true;
    for (int w = 1; w < size_; ++w) MPI_Send(nullptr, 0, MPI_BYTE, w, kStop, MPI_COMM_WORLD);
  }

 private:
  // A worker's answer: its block's bytes for the queue, or its error.
  static void TakeResult(const MPI_Status& status, std::string& bytes,
                         std::vector<std::int64_t>& held, BlockQueue& queue) {
    Receive(status, bytes);
    const auto w = static_cast<std::size_t>(status.MPI_SOURCE);
    const std::int64_t k = held[w];
    held[w] = -1;
    if (status.MPI_TAG == kError || k < 0 || bytes.size() < sizeof(std::int64_t)) {
      throw std::runtime_error(
          fmt::format("rank {}: {}", status.MPI_SOURCE,
                      status.MPI_TAG == kError ? bytes : "unexpected message"));
    }
    std::int64_t count = 0;
    std::memcpy(&count, bytes.data(), sizeof count);
    bytes.erase(0, sizeof count);
    queue.Deliver(k, bytes, count);
  }

  int size_;
  mutable bool stopped_ = false;
};

}  // namespace

struct Ranks::Job {
  int rank = 0;
  int size = 1;
  bool mpi = false;  // MPI_Init called here
  std::unique_ptr<Master> master;
};

Ranks::Ranks() : job_(std::make_unique<Job>()) {
  if (LaunchedProcesses() <= 1) return;  // alone: no MPI at all
  int provided = 0;
  Check(MPI_Init_thread(nullptr, nullptr, MPI_THREAD_FUNNELED, &provided), "MPI_Init_thread");
  job_->mpi = true;
  if (provided < MPI_THREAD_FUNNELED) {
    throw std::runtime_error("MPI: MPI_THREAD_FUNNELED is not supported by this MPI library");
  }
  MPI_Comm_set_errhandler(MPI_COMM_WORLD, MPI_ERRORS_RETURN);
  MPI_Comm_rank(MPI_COMM_WORLD, &job_->rank);
  MPI_Comm_size(MPI_COMM_WORLD, &job_->size);
  if (job_->size > 1 && job_->rank == 0) job_->master = std::make_unique<Master>(job_->size);
}

Ranks::~Ranks() {
  if (!job_->mpi) return;
  if (job_->master) job_->master->StopWorkers();
  MPI_Finalize();
}

bool Ranks::worker() const { return job_->rank > 0; }

const BlockBackend& Ranks::backend() const {
  if (job_->master) return *job_->master;
  return LocalBlocks();
}

int Ranks::Serve(const BlockComputeFactory& make, int threads) {
  std::string bytes;
  for (;;) {
    MPI_Status status;
    Check(MPI_Probe(0, MPI_ANY_TAG, MPI_COMM_WORLD, &status), "MPI_Probe");
    Receive(status, bytes);
    if (status.MPI_TAG == kStop) return 0;
    std::int64_t range[2] = {0, 0};
    if (status.MPI_TAG != kWork || bytes.size() != sizeof range) {
      throw std::runtime_error("MPI: rank 0 sent an unexpected message");
    }
    std::memcpy(range, bytes.data(), sizeof range);
    std::string out(sizeof(std::int64_t), '\0');
    std::int64_t count = 0;
    int tag = kResult;
    try {
      BlockPlan plan;
      plan.first = range[0];
      plan.end = range[1];
      plan.threads = WorkerThreads(threads);
      plan.block = BalancedBlock(plan.end - plan.first, threads, plan.end - plan.first);
      LocalBlocks().Run(plan, make,
                        [&](std::int64_t, std::int64_t, const std::string& b, std::int64_t c) {
                          out += b;
                          count += c;
                        });
      std::memcpy(out.data(), &count, sizeof count);
    } catch (const std::exception& e) {
      out = e.what();
      tag = kError;
    }
    Check(MPI_Send(out.data(), Count(out.size()), MPI_BYTE, 0, tag, MPI_COMM_WORLD), "MPI_Send");
  }
}

}  // namespace capsubot
