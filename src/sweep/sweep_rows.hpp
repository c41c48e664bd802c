#pragma once
// The rows of one sweep point, formatted into a caller's buffer (no allocation once the
// buffer has grown), and the text that identifies a sweep in its checkpoint.

#include <fmt/format.h>

#include <cstdint>
#include <string>
#include <utility>
#include <vector>

#include "capsubot/sweep.hpp"
#include "capsubot/validity.hpp"

namespace capsubot::detail {

using RowBuffer = fmt::memory_buffer;

/// Appends `value` as capsubot::WriteNumber writes it (nothing for NaN: an empty cell).
void AppendNumber(RowBuffer& out, double value);

/// The line that marks a shard's file: "# shard K/N of T points\n".
std::string ShardLine(int shard, int shards, std::int64_t points);

/// The comment lines (with the shard line of a shard) and the header line, as the file begins.
std::string SweepHeaderLines(const SweepOptions& options);

/// One line that determines the sweep's bytes (format version, comments, columns, grid,
/// force, parameters, mode and its options, numbers in hexadecimal), stored in the
/// checkpoint: a resume must match it exactly.
std::string SweepDescription(const SweepOptions& options);

/// The numeric cells of a reach row, name and value, in column order (the status follows);
/// the names are those of the reach JSON object (seed.v_mean is seed_v_mean), 0/1 for flags,
/// NaN (an empty cell) for what was not found.
std::vector<std::pair<const char*, double>> ReachCells(const ReachResult& r);

/// The values a sweep point sets: the force's coefficients, the model parameters, the robot's
/// mass ratio and the optimisers' options.
struct SweepPoint {
  std::vector<double> a, b;  ///< Fourier coefficients of the force (A lives in b[0])
  double c = 0.0, phi0 = 0.0;
  Params params;
  double alpha = 0.0;
  PhaseOptions phase;
  ForcingDesignOptions design;
  FourierOptions fourier;
  ReachOptions reach;

  /// The sweep's fixed values (the grid not applied yet).
  explicit SweepPoint(const SweepOptions& options);
  /// Sets the value of one gridded parameter (the one place that maps a SweepParameter to
  /// what it changes).
  void Set(const GridAxis& axis, double value);
};

/// Formats the rows of grid points. One per worker thread (holds scratch space).
class SweepRowWriter {
 public:
  explicit SweepRowWriter(const SweepOptions& options);
  /// Appends the rows of grid point `point` (row-major index) to `out`; returns how many.
  int AppendPoint(std::int64_t point, RowBuffer& out);

 private:
  void SetPoint(std::int64_t point);
  void AppendSolution(const Solution& s, RowBuffer& out) const;
  void AppendVariables(const Forcing& f, bool exists, RowBuffer& out) const;
  int AppendRobotPoint(std::int64_t point, RowBuffer& out);
  void AppendReach(RowBuffer& out) const;

  const SweepOptions& options_;
  bool rebuild_force_ = false;  // a force coefficient is gridded: rebuilt at each point
  SweepPoint point_;
  Forcing forcing_;
  std::string no_orbit_cells_;  // robot mode: the cells after the axes of a point without orbit
};

}  // namespace capsubot::detail
