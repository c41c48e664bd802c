#include "capsubot/sweep.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <thread>
#include <utility>

#include "sweep/sweep_file.hpp"
#include "sweep/sweep_rows.hpp"

namespace capsubot {
namespace {

constexpr int kMaxThreads = 1024;
constexpr int kSolveBlockPoints = 2048;  // ~3 ms of Solve calls: cheap to hand over
constexpr int kRobotBlockPoints = 32;
constexpr int kPhaseBlockPoints = 2;

constexpr unsigned Bit(SweepParameter p) { return 1U << static_cast<unsigned>(p); }
constexpr unsigned kForceParameters = Bit(SweepParameter::kA) | Bit(SweepParameter::kc) |
                                      Bit(SweepParameter::kcos) | Bit(SweepParameter::ksin);
constexpr unsigned kModelParameters =
    Bit(SweepParameter::kT0) | Bit(SweepParameter::ke) | Bit(SweepParameter::kmargin) |
    Bit(SweepParameter::kmargin_stroke) | Bit(SweepParameter::kstick_margin);

// What each mode computes: its name, the problem it solves, the parameters a grid may vary
// with it (the others are chosen by the optimiser or unused), points per block.
struct ModeRule {
  SweepOptimize mode;
  const char* name;
  const char* problem;
  unsigned gridded;
  int block_points;
};

constexpr ModeRule kModes[] = {
    {SweepOptimize::kNone, "none", "the orbit of the given force",
     kForceParameters | kModelParameters | Bit(SweepParameter::kphi0) | Bit(SweepParameter::kalpha),
     kSolveBlockPoints},
    {SweepOptimize::kPhase, "phi0", "problem P1, the best impact phase phi0",
     kForceParameters | kModelParameters | Bit(SweepParameter::krho_max), kPhaseBlockPoints},
    {SweepOptimize::kForcing, "forcing", "problem P2, the best A, c and phi0",
     kModelParameters | Bit(SweepParameter::kbound) | Bit(SweepParameter::krho_max), 1},
    {SweepOptimize::kFourier, "fourier", "problem P3, the best K-harmonic force",
     kModelParameters | Bit(SweepParameter::kbound) | Bit(SweepParameter::krho_max), 1},
    {SweepOptimize::kReach, "reach", "the fastest motion from rest, seeded by P2",
     kModelParameters | Bit(SweepParameter::kbound) | Bit(SweepParameter::krho_max), 1},
};

const ModeRule& RuleOf(SweepOptimize mode) {
  for (const ModeRule& r : kModes) {
    if (r.mode == mode) return r;
  }
  return kModes[0];  // unreachable: every enumerator has a row
}

int ThreadCount(const SweepOptions& o) {
  if (o.threads > 0) return o.threads;
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

// The names of the parameters in `set`, for messages.
std::string ParameterList(unsigned set) {
  std::string names;
  for (unsigned p = 0; p < 32; ++p) {
    if ((set & (1U << p)) == 0) continue;
    const auto parameter = static_cast<SweepParameter>(p);
    const bool indexed = parameter == SweepParameter::kcos || parameter == SweepParameter::ksin;
    names += (names.empty() ? "" : ", ") + SweepParameterName(parameter) + (indexed ? "k" : "");
  }
  return names;
}

// Smallest and largest value of a parameter over the sweep: its axis, or `fixed`.
std::pair<double, double> Extent(const Grid& grid, SweepParameter parameter, double fixed) {
  for (const GridAxis& axis : grid.axes) {
    if (axis.parameter == parameter) return {axis.Min(), axis.Max()};
  }
  return {fixed, fixed};
}

// The bound of P2 and P3 against T0 at the worst point of the grid (largest bound, smallest
// T0): no point can then fail part-way.
void CheckBoundAgainstT0(const SweepOptions& o, const SearchOptions& search) {
  SearchOptions worst = search;
  Params params = o.params;
  params.T0 = Extent(o.grid, SweepParameter::kT0, o.params.T0).first;
  worst.force_bound = Extent(o.grid, SweepParameter::kbound, search.force_bound).second;
  worst.BoundFor(params);
}

// The message of a write error after which the partial file and its checkpoint are kept.
std::string KeptMessage(const IoError& e, const std::string& output) {
  return fmt::format("{}; the rows done are kept in {} with its checkpoint {} for a resume",
                     e.what(), detail::SweepFile::PartialPath(output),
                     detail::SweepFile::CheckpointPath(output));
}

}  // namespace

std::int64_t ShardPointCount(const SweepOptions& o) {
  const std::int64_t total = o.grid.size();
  return o.shards <= 1 ? total : (total - o.shard + o.shards - 1) / o.shards;
}

std::int64_t ShardPoint(const SweepOptions& o, std::int64_t i) {
  return o.shard + i * std::max(1, o.shards);
}

const char* SweepOptimizeName(SweepOptimize mode) { return RuleOf(mode).name; }

std::vector<SweepOptimize> SweepOptimizeModes() {
  std::vector<SweepOptimize> modes;
  for (const ModeRule& r : kModes) {
    if (r.mode != SweepOptimize::kNone) modes.push_back(r.mode);
  }
  return modes;
}

ReachOptions SweepReachOptions() {
  ReachOptions r;
  r.max_seconds = std::numeric_limits<double>::infinity();
  return r;
}

SweepOptimize ParseSweepOptimize(const std::string& name) {
  std::string names;
  for (SweepOptimize mode : SweepOptimizeModes()) {
    if (name == SweepOptimizeName(mode)) return mode;
    names += (names.empty() ? "" : ", ") + std::string(SweepOptimizeName(mode));
  }
  throw std::invalid_argument(
      fmt::format("optimize = {} is invalid: expected one of {}", name, names));
}

void SweepOptions::Validate() const {
  grid.Validate();
  params.Validate();
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
  if (shards > 1 && grid.size() < shards) {
    throw std::invalid_argument(fmt::format(
        "shard = {}/{} is invalid: the grid has only {} points: expected at most as many shards "
        "as points",
        shard, shards, grid.size()));
  }
  if (block_points < 0) {
    throw std::invalid_argument(
        fmt::format("block_points = {} is invalid: expected >= 1 (0: automatic)", block_points));
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
  const ModeRule& mode = RuleOf(optimize);
  for (const GridAxis& axis : grid.axes) {
    if ((mode.gridded & Bit(axis.parameter)) == 0) {
      throw std::invalid_argument(
          fmt::format("grid {} is invalid with optimize = {} ({}): expected a grid over {}",
                      axis.ToString(), mode.name, mode.problem, ParameterList(mode.gridded)));
    }
  }
  if (grid.Has(SweepParameter::kA) && !forcing.harmonic()) {
    throw std::invalid_argument(
        "grid A is invalid with a Fourier force: expected the harmonic force "
        "A sin(phi + phi0) + c, whose amplitude A the grid varies (or a grid over b1)");
  }
  // A rho_max grid needs no stability switch: rho_max is the requirement (infinity: none).
  switch (optimize) {
    case SweepOptimize::kNone:
      break;
    case SweepOptimize::kPhase:
      phase.Validate();
      break;
    case SweepOptimize::kForcing:
      design.Validate();
      CheckBoundAgainstT0(*this, design);
      break;
    case SweepOptimize::kFourier:
      fourier.Validate();
      CheckBoundAgainstT0(*this, fourier.harmonic);
      break;
    case SweepOptimize::kReach:
      design.Validate();
      reach.Validate();
      if (!std::isinf(reach.max_seconds)) {
        throw std::invalid_argument(fmt::format(
            "reach.max_seconds = {} is invalid with optimize = reach: expected infinity (no "
            "wall-clock limit: the evaluation budgets bound each point, so the rows do not "
            "depend on the machine's speed)",
            reach.max_seconds));
      }
      if (stability) {
        throw std::invalid_argument(
            "stability = true is invalid with optimize = reach: expected no stability columns "
            "(the motion reached from rest is not one orbit)");
      }
      CheckBoundAgainstT0(*this, design);
      break;
  }
}

std::vector<std::string> SweepColumns(const SweepOptions& o) {
  std::vector<std::string> columns;
  for (const GridAxis& axis : o.grid.axes) {
    // In robot mode the computed alpha has its own column: the grid's is the robot's.
    const bool robot = axis.parameter == SweepParameter::kalpha;
    columns.emplace_back(robot ? "robot_alpha" : axis.name());
  }
  if (o.grid.Has(SweepParameter::kalpha)) {
    columns.emplace_back("orbits");
    columns.emplace_back("orbit");
    columns.emplace_back("phi0");
  }
  switch (o.optimize) {
    case SweepOptimize::kNone:
      break;
    case SweepOptimize::kPhase:
      columns.emplace_back("phi0");
      break;
    case SweepOptimize::kForcing:
      for (const char* name : {"A", "c", "phi0"}) columns.emplace_back(name);
      break;
    case SweepOptimize::kFourier:
      columns.emplace_back("c");
      for (const char* prefix : {"a", "b"}) {
        for (int k = 1; k <= o.fourier.harmonics; ++k) {
          columns.push_back(fmt::format("{}{}", prefix, k));
        }
      }
      break;
    case SweepOptimize::kReach:  // its own columns, the status last
      for (const auto& cell : detail::ReachCells(ReachResult{})) columns.emplace_back(cell.first);
      columns.emplace_back("status");
      return columns;
  }
  for (const char* name :
       {"phi1", "alpha", "u", "v_plus", "I", "v_mean", "x_min", "x_max", "valid", "violations"}) {
    columns.emplace_back(name);
  }
  if (o.stability) {
    for (const char* name : {"spectral_radius", "lambda_re", "lambda_im", "stable", "loss"}) {
      columns.emplace_back(name);
    }
  }
  if (o.optimize != SweepOptimize::kNone) columns.emplace_back("status");
  return columns;
}

BlockComputeFactory SweepBlocks(const SweepOptions& options) {
  return [&options]() -> BlockCompute {
    auto writer = std::make_shared<detail::SweepRowWriter>(options);
    return [&options, writer](std::int64_t begin, std::int64_t end, std::string& out) {
      detail::RowBuffer rows(out);  // the rows go straight into `out`
      std::int64_t count = 0;
      for (std::int64_t i = begin; i < end; ++i) {
        count += writer->AppendPoint(ShardPoint(options, i), rows);
      }
      return count;
    };
  };
}

std::int64_t SweepBlockPoints(const SweepOptions& options, std::int64_t points, int threads) {
  if (options.block_points > 0) return options.block_points;
  const std::int64_t most = options.grid.Has(SweepParameter::kalpha)
                                ? kRobotBlockPoints
                                : RuleOf(options.optimize).block_points;
  return BalancedBlock(points, threads, most);
}

SweepSummary RunSweep(const SweepOptions& options, const SweepProgressCallback& progress,
                      const BlockBackend& backend) {
  using Clock = std::chrono::steady_clock;
  options.Validate();
  const auto start = Clock::now();
  // This run's points: every grid point, or those of one shard (ShardPoint).
  const std::int64_t total = ShardPointCount(options);
  const int threads = ThreadCount(options);

  detail::SweepFile file(options.output, detail::SweepDescription(options),
                         detail::SweepHeaderLines(options), options.resume,
                         options.checkpoint_seconds);
  SweepSummary summary;
  summary.threads = threads;
  summary.points_resumed = file.points_done();
  BlockPlan plan;
  plan.first = file.points_done();
  plan.end = total;
  plan.threads = threads;
  plan.block = SweepBlockPoints(options, total - plan.first, backend.Threads(threads));

  // Where the first error came from: a point (deterministic: a resume would fail the same
  // way), the file (a write error: a resume can continue once it is mended) or `progress`.
  enum class Origin { kPoint, kFile, kProgress } origin = Origin::kPoint;
  const BlockSink sink = [&](std::int64_t begin, std::int64_t end, const std::string& bytes,
                             std::int64_t rows) {
    try {
      file.Append(bytes.data(), bytes.size(), end - begin);
    } catch (const IoError&) {
      origin = Origin::kFile;
      throw;
    }
    summary.rows += rows;
    if (progress) {
      origin = Origin::kProgress;
      SweepProgress p;
      p.points_done = end;
      p.points_total = total;
      p.points_resumed = plan.first;
      p.seconds = std::chrono::duration<double>(Clock::now() - start).count();
      progress(p);
      origin = Origin::kPoint;
    }
  };
  try {
    backend.Run(plan, SweepBlocks(options), sink);
  } catch (const IoError& e) {
    if (origin != Origin::kFile || file.direct()) throw;
    throw SweepResumableError(KeptMessage(e, options.output));
  } catch (...) {
    if (origin == Origin::kPoint) file.Discard();  // no resume could get past that point
    throw;
  }
  try {
    file.Commit();
  } catch (const IoError& e) {
    if (file.direct()) throw;
    throw SweepResumableError(KeptMessage(e, options.output));
  }
  summary.points = total;
  summary.seconds = std::chrono::duration<double>(Clock::now() - start).count();
  return summary;
}

}  // namespace capsubot
