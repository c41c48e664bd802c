#pragma once
// The rows of one sweep point, formatted into a caller's buffer (no allocation once the
// buffer has grown), and the text that identifies a sweep in its checkpoint.

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "capsubot/orbit/validity.hpp"
#include "capsubot/sweep/sweep.hpp"

namespace capsubot::detail {

/// Text appended to a string at the cost of writes to a raw buffer (a std::string's own
/// append is a library call for every cell): the string is grown in large zero-filled steps
/// past the text, and cut to the text when the RowBuffer goes. The rows of a block are
/// written so straight into the bytes the block hands over.
class RowBuffer {
 public:
  /// Appends after the current end of `bytes`.
  explicit RowBuffer(std::string& bytes) : bytes_(bytes), size_(bytes.size()) {}
  ~RowBuffer() { bytes_.resize(size_); }  ///< cuts `bytes` to the text appended
  RowBuffer(const RowBuffer&) = delete;
  RowBuffer& operator=(const RowBuffer&) = delete;

  const char* data() const { return bytes_.data(); }
  std::size_t size() const { return size_; }  ///< the text's length
  void clear() { size_ = 0; }

  /// Room for `n` characters at the end of the text; Advance(end) then takes them.
  char* Room(std::size_t n) {
    if (bytes_.size() - size_ < n) Grow(n);
    return &bytes_[size_];
  }
  void Advance(const char* end) { size_ = static_cast<std::size_t>(end - bytes_.data()); }
  void push_back(char c) {
    *Room(1) = c;
    ++size_;
  }
  void append(std::string_view text) {
    std::memcpy(Room(text.size()), text.data(), text.size());
    size_ += text.size();
  }

 private:
  static constexpr std::size_t kMinGrowth = 4096;
  void Grow(std::size_t n) {
    bytes_.resize(std::max({bytes_.capacity(), 2 * bytes_.size(), size_ + n + kMinGrowth}));
  }

  std::string& bytes_;
  std::size_t size_;
};

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

/// The values a sweep point sets: the robot (force, model parameters, mass ratio) and the
/// optimisers' options.
struct SweepPoint {
  SweepOptimize mode;  ///< what the point computes
  /// The robot; with a_k or b_k axes its force has every harmonic an axis names (the others 0).
  RobotModel robot;
  PhaseOptions phase;
  ForcingDesignOptions design;
  FourierOptions fourier;
  ReachOptions reach;
  Margins margins;  ///< the orbits' margins without optimisation (SweepOptions::margins)

  /// The sweep's fixed values (the grid not applied yet).
  explicit SweepPoint(const SweepOptions& options);
  /// Sets the value of one gridded parameter: a robot parameter by SetParameter (an A axis
  /// sets b_1, the force being a series when a_k or b_k axes extend it), a margin among the
  /// mode's (`margins` without optimisation, else those of the mode's GaitRequirements), the
  /// force bound or rho_max in the mode's GaitRequirements. Axes over phi0
  /// go first: a coefficient set after the phase rebuilds the force with the phase reduced, as
  /// one series (Forcing::Fourier).
  void Set(const GridAxis& axis, double value);
  /// The gait the mode asks for (the reach search's bound is that of its seed, `design`).
  GaitRequirements& Gait();
  /// The margins of the mode's orbits (SweepMargins).
  Margins& ModeMargins();
};

/// Formats the rows of grid points. One per worker thread (holds scratch space).
class SweepRowWriter {
 public:
  explicit SweepRowWriter(const SweepOptions& options);
  /// Appends the rows of grid point `point` (row-major index) to `out`; returns how many.
  int AppendPoint(std::int64_t point, RowBuffer& out);

 private:
  // Sets point_ to grid point `point` and values_ to its grid values.
  void SetPoint(std::int64_t point);
  void AppendGridValues(RowBuffer& out) const;
  void AppendSolution(const Solution& s, RowBuffer& out) const;
  void AppendVariables(const Forcing& f, bool exists, RowBuffer& out) const;
  int AppendRobotPoint(std::int64_t point, RowBuffer& out);
  void AppendReach(RowBuffer& out) const;

  const SweepOptions& options_;
  SweepPoint point_;
  std::vector<std::size_t> order_;  // the axes in the order they are set: phi0 first
  std::vector<double> values_;      // the grid values of the point, one per axis
  std::string no_orbit_cells_;      // robot mode: the cells after the axes of a point without orbit
};

}  // namespace capsubot::detail
