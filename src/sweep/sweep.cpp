#include "capsubot/sweep/sweep.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <stdexcept>
#include <utility>

#include "sweep/grid_run.hpp"
#include "sweep/sweep_rows.hpp"

namespace capsubot {
namespace {

constexpr int kSolveBlockPoints = 2048;  // ~3 ms of Solve calls: cheap to hand over
constexpr int kRobotBlockPoints = 32;
constexpr int kPhaseBlockPoints = 2;

constexpr unsigned Bit(ModelParameter p) { return 1U << static_cast<unsigned>(p); }
constexpr unsigned kForceParameters = Bit(ModelParameter::kA) | Bit(ModelParameter::kMean) |
                                      Bit(ModelParameter::kCos) | Bit(ModelParameter::kSin);
constexpr unsigned kModelParameters =
    Bit(ModelParameter::kT0) | Bit(ModelParameter::kRestitution) | Bit(ModelParameter::kMargin) |
    Bit(ModelParameter::kMarginStroke) | Bit(ModelParameter::kStickMargin);

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
     kForceParameters | kModelParameters | Bit(ModelParameter::kPhi0) | Bit(ModelParameter::kAlpha),
     kSolveBlockPoints},
    {SweepOptimize::kPhase, "phi0", "problem P1, the best impact phase phi0",
     kForceParameters | kModelParameters | Bit(ModelParameter::kRhoMax), kPhaseBlockPoints},
    {SweepOptimize::kForcing, "forcing", "problem P2, the best A, c and phi0",
     kModelParameters | Bit(ModelParameter::kBound) | Bit(ModelParameter::kRhoMax), 1},
    {SweepOptimize::kFourier, "fourier", "problem P3, the best K-harmonic force",
     kModelParameters | Bit(ModelParameter::kBound) | Bit(ModelParameter::kRhoMax), 1},
    {SweepOptimize::kReach, "reach", "the fastest motion from rest, seeded by P2",
     kModelParameters | Bit(ModelParameter::kBound) | Bit(ModelParameter::kRhoMax), 1},
};

const ModeRule& RuleOf(SweepOptimize mode) {
  for (const ModeRule& r : kModes) {
    if (r.mode == mode) return r;
  }
  return kModes[0];  // unreachable: every enumerator has a row
}

// The names of the parameters in `set`, for messages.
std::string ParameterList(unsigned set) {
  std::string names;
  for (unsigned p = 0; p < 32; ++p) {
    if ((set & (1U << p)) == 0) continue;
    const auto parameter = static_cast<ModelParameter>(p);
    names += (names.empty() ? "" : ", ") + ModelParameterName(parameter) +
             (IsFourierCoefficient(parameter) ? "k" : "");
  }
  return names;
}

// Smallest and largest value of a parameter over the sweep: its axis, or `fixed`.
std::pair<double, double> Extent(const Grid& grid, ModelParameter parameter, double fixed) {
  for (const GridAxis& axis : grid.axes) {
    if (axis.parameter == parameter) return {axis.Min(), axis.Max()};
  }
  return {fixed, fixed};
}

// The bound of P2 and P3 against T0 at the worst point of the grid (largest bound, smallest
// T0): no point can then fail part-way.
void CheckBoundAgainstT0(const SweepOptions& o, const GaitRequirements& gait) {
  GaitRequirements worst = gait;
  Params params = o.params;
  params.T0 = Extent(o.grid, ModelParameter::kT0, o.params.T0).first;
  worst.force_bound = Extent(o.grid, ModelParameter::kBound, gait.force_bound).second;
  worst.BoundFor(params);
}

}  // namespace

std::int64_t ShardPointCount(const SweepOptions& o) {
  return detail::ShardCount(o.grid.size(), o.shard, o.shards);
}

std::int64_t ShardPoint(const SweepOptions& o, std::int64_t i) {
  return o.shard + i * std::max(1, o.shards);
}

const Margins& SweepMargins(const SweepOptions& o) {
  switch (o.optimize) {
    case SweepOptimize::kNone:
      return o.margins;
    case SweepOptimize::kPhase:
      return o.phase.gait.margins;
    case SweepOptimize::kFourier:
      return o.fourier.harmonic.gait.margins;
    case SweepOptimize::kForcing:
    case SweepOptimize::kReach:
      break;
  }
  return o.design.gait.margins;
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
  SweepMargins(*this).Validate();
  ValidateFile(grid.size());
  if (block_points < 0) {
    throw std::invalid_argument(
        fmt::format("block_points = {} is invalid: expected >= 1 (0: automatic)", block_points));
  }
  const ModeRule& mode = RuleOf(optimize);
  for (const GridAxis& axis : grid.axes) {
    if ((mode.gridded & Bit(axis.parameter)) == 0) {
      throw std::invalid_argument(
          fmt::format("grid {} is invalid with optimize = {} ({}): expected a grid over {}",
                      axis.ToString(), mode.name, mode.problem, ParameterList(mode.gridded)));
    }
  }
  if (grid.Has(ModelParameter::kA) && !forcing.harmonic()) {
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
      CheckBoundAgainstT0(*this, design.gait);
      break;
    case SweepOptimize::kFourier:
      fourier.Validate();
      CheckBoundAgainstT0(*this, fourier.harmonic.gait);
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
      CheckBoundAgainstT0(*this, design.gait);
      break;
  }
}

std::vector<std::string> SweepColumns(const SweepOptions& o) {
  std::vector<std::string> columns;
  for (const GridAxis& axis : o.grid.axes) {
    // In robot mode the computed alpha has its own column: the grid's is the robot's.
    const bool robot = axis.parameter == ModelParameter::kAlpha;
    columns.emplace_back(robot ? "robot_alpha" : axis.name());
  }
  if (o.grid.Has(ModelParameter::kAlpha)) {
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
  const std::int64_t most = options.grid.Has(ModelParameter::kAlpha)
                                ? kRobotBlockPoints
                                : RuleOf(options.optimize).block_points;
  return BalancedBlock(points, threads, most);
}

SweepSummary RunSweep(const SweepOptions& options, const SweepProgressCallback& progress,
                      const BlockBackend& backend) {
  options.Validate();
  detail::GridRun run;
  run.output = options.output;
  run.description = detail::SweepDescription(options);
  run.header = detail::SweepHeaderLines(options);
  run.resume = options.resume;
  run.checkpoint_seconds = options.checkpoint_seconds;
  run.points = ShardPointCount(options);  // every grid point, or those of one shard
  run.threads = WorkerThreads(options.threads);
  run.block_points = [&options](std::int64_t points, int threads) {
    return SweepBlockPoints(options, points, threads);
  };
  return detail::RunGridRows(run, SweepBlocks(options), progress, backend);
}

}  // namespace capsubot
