#pragma once
// Parameter sweeps to CSV: the orbit (docs/model.md section 4) and its validity (section 5), and
// optionally its stability (section 8) or the best impact phase (problem P1, section 7), at
// every point of a 1-D or 2-D grid (grid.hpp).
//
// The sweep runs on several threads; the CSV is byte-identical for any thread count. Rows
// are computed in blocks and written in order with a bounded number of blocks in flight, so
// memory does not grow with the grid. The file is built as `<output>.partial` next to a
// checkpoint `<output>.checkpoint` and renamed to `<output>` at the end: a killed sweep never
// leaves a truncated CSV under the final name, and `resume` continues it from its checkpoint
// without recomputing finished points (the result is byte-identical to an uninterrupted run).
//
// Row layout (one header line, then rows in grid order, the last axis varying fastest):
//   plain:        <grid parameters>, phi1, alpha, u, v_plus, I, v_mean, x_min, x_max, valid,
//                 violations [, spectral_radius, stable]
//   optimize_phi0: <grid parameters>, phi0, phi1, ..., violations [, spectral_radius, stable],
//                 status        (phi0 is the optimal impact phase; status the optimiser's:
//                 with no_valid_orbit the row is its point nearest to validity)
//   alpha grid (robot mode): <grid parameters>, orbits, orbit, phi0, phi1, ..., violations
//                 [, spectral_radius, stable]: one row per one-impact orbit of the robot
//                 (orbit = 1..orbits, in increasing phi0); a point with no orbit gets one
//                 row with orbits = 0 and every other cell empty. The header then holds
//                 alpha twice: the robot's (grid) value first, then the orbit's computed one.
// Numbers have 17 significant digits (they round-trip); a quantity that does not exist is an
// empty cell; valid and stable are 0/1; violations are condition names joined by ';'.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "capsubot/forcing.hpp"
#include "capsubot/grid.hpp"
#include "capsubot/optimize_phase.hpp"
#include "capsubot/params.hpp"

namespace capsubot {

struct SweepOptions {
  /// The grid (1 or 2 axes); its parameters replace the values of `forcing` and `params`.
  Grid grid;
  /// The force at every point, except the gridded parameters; an A grid needs the harmonic
  /// family. Its phi0 is ignored with `optimize_phi0` or an alpha grid.
  Forcing forcing = Forcing::Harmonic(0.5, 0.5, 0.0);
  /// T0, e, margin at every point, except the gridded ones.
  Params params;
  /// Add the columns spectral_radius and stable (docs/model.md section 8).
  bool stability = false;
  /// Maximise I over phi0 at every point (problem P1): adds the columns phi0 and status.
  bool optimize_phi0 = false;
  /// Options of that optimisation (OptimizePhase); `phase.stable` maximises over stable orbits.
  PhaseOptions phase;
  /// The CSV file to write (required); "-" (standard output) or a path that is not a regular
  /// file (/dev/stdout, a pipe) is written in place, without checkpoint or resume.
  std::string output;
  /// Continue from `<output>.checkpoint` if it exists and belongs to this same sweep.
  bool resume = false;
  /// Worker threads; 0 means std::thread::hardware_concurrency().
  int threads = 0;
  /// Grid points per block of rows (the unit of work and of checkpointing); 0: automatic.
  int block_points = 0;
  /// Minimum time between two checkpoints (fsync of the partial file, then of the
  /// checkpoint), in seconds; 0 checkpoints after every block.
  double checkpoint_seconds = 0.5;

  /// Throws std::invalid_argument naming the bad field, its value and the rule.
  void Validate() const;
};

/// How far a sweep is, reported after each block written.
struct SweepProgress {
  std::int64_t points_done = 0;     ///< grid points written so far (including resumed ones)
  std::int64_t points_total = 0;    ///< grid points in the sweep
  std::int64_t points_resumed = 0;  ///< points taken from the checkpoint (not recomputed)
  double seconds = 0.0;             ///< wall time since this run started
};

/// Called from the thread that writes the file, after each block; must be cheap.
using SweepProgressCallback = std::function<void(const SweepProgress&)>;

/// What a finished sweep did.
struct SweepSummary {
  std::int64_t points = 0;          ///< grid points in the file
  std::int64_t rows = 0;            ///< data rows written by this run (not counting resumed ones)
  std::int64_t points_resumed = 0;  ///< points taken over from a checkpoint
  int threads = 0;                  ///< worker threads used
  double seconds = 0.0;             ///< wall time of this run
};

/// The CSV header's column names for these options.
std::vector<std::string> SweepColumns(const SweepOptions& options);

/// Runs the sweep and writes options.output (see the file comment). Throws
/// std::invalid_argument for bad options or a checkpoint of another sweep, IoError when a
/// file cannot be written; on any exception `<output>` is untouched and the partial file
/// and checkpoint stay for `resume`.
SweepSummary RunSweep(const SweepOptions& options, const SweepProgressCallback& progress = {});

}  // namespace capsubot
