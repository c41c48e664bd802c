#pragma once
// The rows of one sweep point, formatted into a caller's buffer (no allocation once the
// buffer has grown), and the text that identifies a sweep in its checkpoint.

#include <fmt/format.h>

#include <cstdint>
#include <string>
#include <vector>

#include "capsubot/sweep.hpp"
#include "capsubot/validity.hpp"

namespace capsubot::detail {

using RowBuffer = fmt::memory_buffer;

/// Appends `value` with 17 significant digits, byte-identical to capsubot::FormatNumber
/// (nothing for NaN: an empty cell).
void AppendNumber(RowBuffer& out, double value);

/// Appends the header line (column names joined by ',', then '\n').
std::string SweepHeaderLine(const SweepOptions& options);

/// One line that determines the sweep's bytes (format version, columns, grid, force,
/// parameters, modes), stored in the checkpoint: a resume must match it exactly.
std::string SweepDescription(const SweepOptions& options);

/// Formats the rows of grid points. One per worker thread (holds scratch space).
class SweepRowWriter {
 public:
  explicit SweepRowWriter(const SweepOptions& options);
  /// Appends the rows of grid point `point` (row-major index) to `out`; returns how many.
  int AppendPoint(std::int64_t point, RowBuffer& out);

 private:
  void SetPoint(std::int64_t point);
  void AppendSolution(const Solution& s, RowBuffer& out) const;

  const SweepOptions& options_;
  bool rebuild_force_ = false;  // an A or c axis: the force is rebuilt at each point
  std::vector<double> a_, b_;   // its Fourier coefficients (A lives in b_[0])
  double c_ = 0.0, phi0_ = 0.0;
  Forcing forcing_;
  Params params_;
  double alpha_ = 0.0;
};

}  // namespace capsubot::detail
