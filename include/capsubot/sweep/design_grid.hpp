#pragma once
// Designs over a grid of a robot's SI inputs (docs/design.md): at every point of a grid of any
// number of axes over the shell mass, the gap, the friction, the restitution, the motor force,
// the frequency, the inner mass and the robust margins, the gait the design finds
// (DesignGait), one CSV row a point. The axes are written as the sweep's (grid.hpp:
// `name=lo:hi:n`, `name=lo:hi:n:log`, `name=v1,v2,...`, row-major, the first slowest) with the
// names of the design's settings (m1, L, force-amplitude, rho-max, ...).
//
// The file is a sweep's (sweep.hpp): comment lines, a header line, the rows in grid order;
// threads, `<output>.partial` with its checkpoint and resume, shards (`# shard K/N of T
// points`, joined by MergeSweepShards) work the same way and give the same bytes.

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "capsubot/design/design.hpp"
#include "capsubot/parallel/blocks.hpp"
#include "capsubot/sweep/grid.hpp"
#include "capsubot/sweep/grid_file.hpp"
#include "capsubot/sweep/sweep.hpp"

namespace capsubot {

/// An SI input of the design a grid can vary.
enum class DesignParameter {
  kM1,              ///< shell mass m1 [kg]
  kL,               ///< gap L [m]
  kMu,              ///< friction coefficient mu
  kGravity,         ///< gravity g [m/s^2]
  kRestitution,     ///< restitution e
  kForceAmplitude,  ///< amplitude of the harmonic motor force [N]
  kForceBias,       ///< mean motor force [N]
  kFrequency,       ///< motor frequency [Hz], fixed at each point (no frequency search)
  kM2,              ///< inner mass m2 [kg], fixed at each point (no m2 search)
  kMargin,          ///< clearance d [units of L]
  kMarginStroke,    ///< clearance d_s [units of the stroke]
  kStickMargin,     ///< stick margin s
  kRhoMax,          ///< largest admissible multiplier modulus (inf: no stability requirement)
};

/// The parameter's name in a grid: the design's setting ("m1", "force-amplitude", "rho-max",
/// ...; "m2" for the inner mass).
const char* DesignParameterName(DesignParameter parameter);

/// One axis of a design grid.
struct DesignGridAxis : GridValues {
  DesignParameter parameter = DesignParameter::kM2;  ///< what varies

  std::string name() const { return DesignParameterName(parameter); }
  /// Its column in the CSV header: name(), but "m2_kg" for the inner mass and "frequency_hz" for
  /// the frequency (the names of a gait's Gait::m2_kg and Gait::frequency_hz, with their units:
  /// a file has one column for each).
  std::string column() const;
  /// `name=` + ValuesText().
  std::string ToString() const { return name() + "=" + ValuesText(); }
  /// Throws std::invalid_argument "grid <axis> is invalid: ..." (GridValues::Check with the
  /// parameter's domain: m1 > 0, 0 <= e <= 1, ..., rho-max > 0 or inf).
  void Validate() const;
};

/// Parses one axis; throws std::invalid_argument "grid <spec> is invalid: ..." for an unknown
/// name (the message lists the names), a malformed spec or a value outside the domain.
DesignGridAxis ParseDesignGridAxis(const std::string& spec);

/// The cells after the grid's of a point's row, joined by ',' (no line break).
using DesignGridRow = std::function<std::string(const Gait& gait)>;

/// The file options (comments, output, shard, resume, threads, checkpoints) are GridFileOptions.
struct DesignGridOptions : GridFileOptions {
  /// The robot at every point, except the gridded inputs (validated: DesignInput::Validate).
  DesignInput input;
  /// The axes, first slowest; each parameter at most once, at least one axis.
  std::vector<DesignGridAxis> axes;
  /// The names of the columns after the grid's (none an axis's column: DesignGridAxis::column),
  /// and their cells (required).
  std::vector<std::string> columns;
  DesignGridRow row;

  /// Throws std::invalid_argument naming the bad field (grid, output, threads, shard, ...),
  /// its value and the rule. Every point's input is valid once this passes.
  void Validate() const;
  /// Number of grid points.
  std::int64_t Points() const;
  /// The input at grid point `point` and its inner mass (NaN: searched over the range).
  DesignInput PointInput(std::int64_t point, double& m2) const;
};

/// The computers of the grid's blocks (blocks.hpp): unit i is this run's i-th point (grid
/// point options.shard + i * options.shards), its bytes its CSV row, the count 1 a point.
/// `options` must outlive them. A distributed backend's workers compute with these what
/// RunDesignGrid's writer asks for.
BlockComputeFactory DesignGridBlocks(const DesignGridOptions& options);

/// Runs the grid and writes options.output: `# ` comments, the shard line of a shard, the
/// header (the axes' columns, then options.columns), one row a point (the axes' values, then
/// options.row(DesignGait(PointInput))). Errors as RunSweep: std::invalid_argument for bad
/// options (before any file is touched), IoError, SweepResumableError. The blocks of rows are
/// computed by `backend` (this process's threads by default).
SweepSummary RunDesignGrid(const DesignGridOptions& options,
                           const SweepProgressCallback& progress = {},
                           const BlockBackend& backend = LocalBlocks());

}  // namespace capsubot
