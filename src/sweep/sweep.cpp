#include "capsubot/sweep.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <condition_variable>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "sweep/sweep_file.hpp"
#include "sweep/sweep_rows.hpp"

namespace capsubot {
namespace {

constexpr int kMaxThreads = 1024;
constexpr int kBlocksInFlightPerThread = 4;  // bounds memory: blocks computed ahead of the writer
constexpr int kSolveBlockPoints = 2048;      // ~3 ms of Solve calls: cheap to hand over
constexpr int kRobotBlockPoints = 32;
constexpr int kOptimizeBlockPoints = 2;

// Points per block: big enough to amortise the hand-over, small enough to balance threads.
std::int64_t BlockPoints(const SweepOptions& o, std::int64_t todo, int threads) {
  if (o.block_points > 0) return o.block_points;
  const std::int64_t base = o.optimize_phi0                      ? kOptimizeBlockPoints
                            : o.grid.Has(SweepParameter::kalpha) ? kRobotBlockPoints
                                                                 : kSolveBlockPoints;
  const std::int64_t balanced = todo / (8 * static_cast<std::int64_t>(threads));
  return std::max<std::int64_t>(1, std::min(base, balanced));
}

int ThreadCount(const SweepOptions& o) {
  if (o.threads > 0) return o.threads;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

}  // namespace

void SweepOptions::Validate() const {
  grid.Validate();
  params.Validate();
  if (output.empty()) {
    throw std::invalid_argument("--output is missing: expected the path of the CSV file to write");
  }
  if (threads < 0 || threads > kMaxThreads) {
    throw std::invalid_argument(
        fmt::format("--threads = {} is invalid: expected 1 <= threads <= {} (0: all cores)",
                    threads, kMaxThreads));
  }
  if (block_points < 0) {
    throw std::invalid_argument(
        fmt::format("block_points = {} is invalid: expected >= 1 (0: automatic)", block_points));
  }
  if (!(checkpoint_seconds >= 0.0)) {
    throw std::invalid_argument(
        fmt::format("checkpoint_seconds = {} is invalid: expected >= 0", checkpoint_seconds));
  }
  if (grid.Has(SweepParameter::kA) && !forcing.harmonic()) {
    throw std::invalid_argument(
        "--grid A is invalid with a Fourier force (--sin/--cos): expected the harmonic force "
        "A sin(phi + phi0) + c, whose amplitude A the grid varies");
  }
  if (optimize_phi0) {
    if (grid.Has(SweepParameter::kphi0)) {
      throw std::invalid_argument(
          "--optimize phi0 with --grid phi0 is invalid: expected phi0 either optimised or "
          "gridded, not both");
    }
    if (grid.Has(SweepParameter::kalpha)) {
      throw std::invalid_argument(
          "--optimize phi0 with --grid alpha is invalid: a robot's alpha fixes its orbits "
          "(phi0 is solved for): expected one of them");
    }
    phase.Validate();
  }
}

std::vector<std::string> SweepColumns(const SweepOptions& o) {
  std::vector<std::string> columns;
  for (const GridAxis& axis : o.grid.axes) {
    // In robot mode the computed alpha has its own column: the grid's is the robot's.
    const bool robot = axis.parameter == SweepParameter::kalpha;
    columns.emplace_back(robot ? "robot_alpha" : SweepParameterName(axis.parameter));
  }
  if (o.grid.Has(SweepParameter::kalpha)) {
    columns.emplace_back("orbits");
    columns.emplace_back("orbit");
  }
  if (o.grid.Has(SweepParameter::kalpha) || o.optimize_phi0) columns.emplace_back("phi0");
  for (const char* name :
       {"phi1", "alpha", "u", "v_plus", "I", "v_mean", "x_min", "x_max", "valid", "violations"}) {
    columns.emplace_back(name);
  }
  if (o.stability) {
    columns.emplace_back("spectral_radius");
    columns.emplace_back("stable");
  }
  if (o.optimize_phi0) columns.emplace_back("status");
  return columns;
}

SweepSummary RunSweep(const SweepOptions& options, const SweepProgressCallback& progress) {
  using Clock = std::chrono::steady_clock;
  options.Validate();
  const auto start = Clock::now();
  const std::int64_t total = options.grid.size();
  const int threads = ThreadCount(options);

  detail::SweepFile file(options.output, detail::SweepDescription(options),
                         detail::SweepHeaderLine(options), options.resume,
                         options.checkpoint_seconds);
  SweepSummary summary;
  summary.threads = threads;
  summary.points_resumed = file.points_done();
  const std::int64_t first = file.points_done();
  const std::int64_t todo = total - first;
  const std::int64_t block = BlockPoints(options, todo, threads);
  const std::int64_t blocks = (todo + block - 1) / block;
  const auto block_begin = [&](std::int64_t k) { return first + k * block; };
  const auto block_end = [&](std::int64_t k) { return std::min(total, first + (k + 1) * block); };

  // Slot k % window holds block k, computed by a worker, written in order by this thread.
  struct Slot {
    detail::RowBuffer rows;
    std::int64_t count = 0;
    bool ready = false;
  };
  const std::int64_t window = static_cast<std::int64_t>(kBlocksInFlightPerThread) * threads;
  std::vector<Slot> slots(
      static_cast<std::size_t>(std::min(window, std::max<std::int64_t>(blocks, 1))));
  const auto slot_of = [&](std::int64_t k) -> Slot& {
    return slots[static_cast<std::size_t>(k % static_cast<std::int64_t>(slots.size()))];
  };
  std::mutex mutex;
  std::condition_variable work_cv, ready_cv;
  std::int64_t next_claim = 0, next_write = 0;
  bool abort = false;
  std::exception_ptr error;
  const auto fail = [&](std::exception_ptr e) {
    std::lock_guard<std::mutex> lock(mutex);
    if (!error) error = e;
    abort = true;
    work_cv.notify_all();
    ready_cv.notify_all();
  };

  const auto worker = [&] {
    try {
      detail::SweepRowWriter writer(options);
      const auto in_flight = static_cast<std::int64_t>(slots.size());
      for (;;) {
        std::int64_t k = 0;
        {
          std::unique_lock<std::mutex> lock(mutex);
          work_cv.wait(lock, [&] {
            return abort || next_claim >= blocks || next_claim < next_write + in_flight;
          });
          if (abort || next_claim >= blocks) return;
          k = next_claim++;
        }
        Slot& slot = slot_of(k);
        slot.rows.clear();
        std::int64_t rows = 0;
        for (std::int64_t p = block_begin(k); p < block_end(k); ++p) {
          rows += writer.AppendPoint(p, slot.rows);
        }
        {
          std::lock_guard<std::mutex> lock(mutex);
          slot.count = rows;
          slot.ready = true;
        }
        ready_cv.notify_all();
      }
    } catch (...) {
      fail(std::current_exception());
    }
  };

  std::vector<std::thread> pool;
  const int workers =
      static_cast<int>(std::min<std::int64_t>(threads, std::max<std::int64_t>(blocks, 1)));
  pool.reserve(static_cast<std::size_t>(workers));
  for (int i = 0; i < workers; ++i) pool.emplace_back(worker);

  try {
    for (std::int64_t k = 0; k < blocks; ++k) {
      Slot& slot = slot_of(k);
      {
        std::unique_lock<std::mutex> lock(mutex);
        ready_cv.wait(lock, [&] { return abort || slot.ready; });
        if (abort) break;
      }
      file.Append(slot.rows.data(), slot.rows.size(), block_end(k) - block_begin(k));
      summary.rows += slot.count;
      {
        std::lock_guard<std::mutex> lock(mutex);
        slot.ready = false;
        next_write = k + 1;
      }
      work_cv.notify_all();
      if (progress) {
        SweepProgress p;
        p.points_done = block_end(k);
        p.points_total = total;
        p.points_resumed = first;
        p.seconds = std::chrono::duration<double>(Clock::now() - start).count();
        progress(p);
      }
    }
  } catch (...) {
    fail(std::current_exception());
  }
  for (std::thread& t : pool) t.join();
  if (error) std::rethrow_exception(error);

  file.Commit();
  summary.points = total;
  summary.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return summary;
}

}  // namespace capsubot
