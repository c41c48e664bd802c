#pragma once
// Parameter sweeps to CSV: the orbit (docs/model.md section 4) and its validity (section 5),
// optionally its stability (section 8), or the optimum of problem P1, P2 or P3 (section 7),
// at every point of a grid of any number of axes (grid.hpp).
//
// The sweep runs on several threads; the CSV is byte-identical for any thread count. Rows
// are computed in blocks and written in order with a bounded number of blocks in flight, so
// memory does not grow with the grid. The file is built as `<output>.partial` next to a
// checkpoint `<output>.checkpoint` and renamed to `<output>` at the end: a killed sweep never
// leaves a truncated CSV under the final name, and `resume` continues it from its checkpoint
// without recomputing finished points (the result is byte-identical to an uninterrupted run).
// A checkpoint holds a checksum of itself and of the rows it vouches for, and the sweep's
// full description: a corrupted checkpoint or partial file, or one of another sweep, is an
// error, never a silently wrong file.
//
// File layout: the comment lines (`# ` + each of SweepOptions::comments), one header line,
// then rows in grid order (the last axis varying fastest):
//   plain:      <grid parameters>, phi1, alpha, u, v_plus, I, v_mean, x_min, x_max, valid,
//               violations [, spectral_radius, lambda_re, lambda_im, stable, loss]
//   optimize:   <grid parameters>, <optimised variables>, phi1, ..., violations
//               [, stability columns], status. The variables are phi0 (P1), A, c, phi0 (P2),
//               c, a1..aK, b1..bK (P3, force seen from the impact); status is the optimiser's
//               (with no_valid_orbit the row is its point nearest to validity).
//   reach:      <grid parameters>, A, c, phi0, alpha, mean_velocity, seed_won,
//               robust_to_settings, max_relative_deviation, evaluations, seed_A, seed_c,
//               seed_phi0, seed_alpha, seed_I, seed_v_mean, seed_mean_velocity_from_rest,
//               seed_reached, status: the fastest motion from rest (OptimizeReach) and the
//               robust gait it was seeded with (ReachResult, the names of its JSON object).
//   alpha grid (robot mode): <grid parameters>, orbits, orbit, phi0, phi1, ..., violations
//               [, stability columns]: one row per one-impact orbit of the robot (orbit =
//               1..orbits, in increasing phi0); a point with no orbit gets one row with
//               orbits = 0 and every other cell empty. The alpha axis is named robot_alpha.
// Numbers are shortest round-trip (WriteNumber); a quantity that does not exist is an empty
// cell; valid and stable are 0/1; violations are condition names joined by ';'; loss is
// fold, flip or torus for an unstable orbit (StabilityLoss), empty otherwise.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "capsubot/io/io.hpp"
#include "capsubot/model/forcing.hpp"
#include "capsubot/model/params.hpp"
#include "capsubot/optimize/optimize_forcing.hpp"
#include "capsubot/optimize/optimize_fourier.hpp"
#include "capsubot/optimize/optimize_phase.hpp"
#include "capsubot/parallel/blocks.hpp"
#include "capsubot/reach/optimize_reach.hpp"
#include "capsubot/sweep/grid.hpp"
#include "capsubot/sweep/grid_file.hpp"

namespace capsubot {

/// What a sweep computes at each point.
enum class SweepOptimize {
  kNone,     ///< the orbit of the given force (Solve)
  kPhase,    ///< P1: the best impact phase phi0 for the force shape (OptimizePhase)
  kForcing,  ///< P2: the best A, c, phi0 (OptimizeForcing)
  kFourier,  ///< P3: the best K-harmonic force (OptimizeFourier)
  kReach,    ///< the fastest motion from rest (OptimizeReach), seeded by P2 with `design`
};

/// The mode's name: "none", "phi0", "forcing", "fourier", "reach".
const char* SweepOptimizeName(SweepOptimize mode);
/// Every mode that optimises, in a fixed order (for parsers and messages).
std::vector<SweepOptimize> SweepOptimizeModes();
/// The mode called `name` (SweepOptimizeName); throws std::invalid_argument
/// "optimize = <name> is invalid: expected one of phi0, forcing, fourier, reach".
SweepOptimize ParseSweepOptimize(const std::string& name);

/// ReachOptions with no wall-clock limit (max_seconds infinite), as a sweep needs them.
ReachOptions SweepReachOptions();

/// The file options (comments, output, shard, resume, threads, checkpoints) are GridFileOptions.
struct SweepOptions : GridFileOptions {
  /// The grid; its parameters replace the values of `forcing`, `params` and the optimiser's
  /// options at every point.
  Grid grid;
  /// The force at every point, except the gridded parameters; an A grid needs the harmonic
  /// family; a grid over a_k or b_k beyond its K adds harmonics (the others 0). Its phi0 is
  /// ignored with an optimisation or an alpha grid; the whole force with P2, P3 and reach.
  Forcing forcing = Forcing::Harmonic(0.5, 0.5, 0.0);
  /// T0 and e at every point, except the gridded ones.
  Params params;
  /// The margins of the orbits without optimisation (kNone), except the gridded ones; an
  /// optimisation's are those of its options' gait (SweepMargins).
  Margins margins;
  /// Add the stability columns (docs/model.md section 8).
  bool stability = false;
  /// What to compute at each point.
  SweepOptimize optimize = SweepOptimize::kNone;
  /// Options of P1 (OptimizePhase); `phase.rho_max` bounds the spectral radius (1: stable).
  PhaseOptions phase;
  /// Options of P2 (OptimizeForcing), also the seed of the reach search (its force bound
  /// bounds the search too); a grid over bound or rho_max sets its fields.
  ForcingDesignOptions design;
  /// Options of P3 (OptimizeFourier); a grid over bound or rho_max sets those of its `harmonic`.
  FourierOptions fourier;
  /// Options of the reach search (OptimizeReach). Its force bound is design.force_bound and its
  /// seed is OptimizeForcing(params, design) at the point (its seed_design is
  /// not used); max_seconds must be infinite (SweepReachOptions): the evaluation budgets
  /// bound each point, so that the rows do not depend on the machine's speed. Each point runs
  /// on one thread.
  ReachOptions reach = SweepReachOptions();
  /// Grid points per block of rows (the unit of work and of checkpointing); 0: automatic.
  int block_points = 0;

  /// Throws std::invalid_argument naming the bad field (grid, optimize, threads, ...), its
  /// value and the rule. Checks the gridded values against the other parameters too (a
  /// bound grid against T0), so that no point fails part-way.
  void Validate() const;
};

/// The margins of the orbits of the sweep's mode: `margins` without optimisation, else those of
/// the optimiser's gait (phase.gait, design.gait for P2 and the reach search's seed,
/// fourier.harmonic.gait).
const Margins& SweepMargins(const SweepOptions& options);

/// How far a sweep is, reported after each block written.
struct SweepProgress {
  std::int64_t points_done = 0;     ///< grid points written so far (including resumed ones)
  std::int64_t points_total = 0;    ///< grid points in the sweep
  std::int64_t points_resumed = 0;  ///< points taken from the checkpoint (not recomputed)
  double seconds = 0.0;             ///< wall time since this run started
};

/// Called from the thread that writes the file, after each block; must be cheap. An exception
/// it throws stops the sweep like a kill: the partial file and checkpoint stay for a resume.
using SweepProgressCallback = std::function<void(const SweepProgress&)>;

/// What a finished sweep did.
struct SweepSummary {
  std::int64_t points = 0;          ///< grid points in the file
  std::int64_t rows = 0;            ///< data rows written by this run (not counting resumed ones)
  std::int64_t points_resumed = 0;  ///< points taken over from a checkpoint
  int threads = 0;                  ///< worker threads used
  double seconds = 0.0;             ///< wall time of this run
};

/// A sweep stopped by a failure a resume can mend (a write error: disk full, ...): the partial
/// file and checkpoint are kept, and the message says so.
class SweepResumableError : public WriteError {
 public:
  using WriteError::WriteError;
};

/// Number of grid points this run computes: the grid's, or its shard's.
std::int64_t ShardPointCount(const SweepOptions& options);
/// The grid point (row-major index) of this run's i-th point, i < ShardPointCount(options).
std::int64_t ShardPoint(const SweepOptions& options, std::int64_t i);

/// The computers of the sweep's blocks (blocks.hpp): unit i is this run's i-th point
/// (ShardPoint), its bytes its CSV rows, the count the rows. `options` must outlive them.
/// A distributed backend's workers compute with these what RunSweep's writer asks for.
BlockComputeFactory SweepBlocks(const SweepOptions& options);
/// Points per block for `points` points on `threads` threads (over all processes):
/// options.block_points, or automatic (cheap points in larger blocks).
std::int64_t SweepBlockPoints(const SweepOptions& options, std::int64_t points, int threads);

/// The CSV header's column names for these options.
std::vector<std::string> SweepColumns(const SweepOptions& options);

/// Runs the sweep and writes options.output (see the file comment). Throws
/// std::invalid_argument for bad options or a checkpoint of another sweep (both before any
/// file is touched), IoError for a file that cannot be used or a corrupted checkpoint,
/// SweepResumableError for a write error part-way. On any exception `<output>` is untouched;
/// the partial file and checkpoint are kept only when a resume can continue (a write error,
/// an exception of `progress`) and removed otherwise (a point that cannot be computed).
/// The blocks of rows are computed by `backend` (this process's threads by default).
SweepSummary RunSweep(const SweepOptions& options, const SweepProgressCallback& progress = {},
                      const BlockBackend& backend = LocalBlocks());

}  // namespace capsubot
