#pragma once
// Grids of parameter values for sweeps: `name=lo:hi:n`, n equally spaced values from lo to hi
// inclusive (n = 1 means lo alone). A sweep has one or two axes; with two, the first one
// varies slowest (row-major order).

#include <cstdint>
#include <string>
#include <vector>

namespace capsubot {

/// A parameter a grid can vary (docs/model.md sections 2 and 6 for the symbols).
enum class SweepParameter {
  kA,       ///< amplitude A of F = A sin(phi + phi0) + c
  kc,       ///< mean force c
  kphi0,    ///< motor phase at the impact phi0 [rad]
  kT0,      ///< friction bound T0
  ke,       ///< restitution e
  kmargin,  ///< clearance d
  kalpha,   ///< mass ratio of a given robot: phi0 is then solved for (docs/model.md section 8)
};

/// The parameter's name as written in `--grid` and in CSV headers ("A", "phi0", ...).
const char* SweepParameterName(SweepParameter parameter);

/// One axis of a grid: n values lo, lo + (hi-lo)/(n-1), ..., hi.
struct GridAxis {
  SweepParameter parameter = SweepParameter::kphi0;  ///< what varies
  double lo = 0.0;                                   ///< first value (unit of the parameter)
  double hi = 0.0;                                   ///< last value (ignored when n = 1)
  std::int64_t n = 1;                                ///< number of values, n >= 1

  /// The i-th value, i in [0, n): exactly lo for i = 0 and exactly hi for i = n-1 (n > 1).
  double Value(std::int64_t i) const;
  /// Throws std::invalid_argument naming the axis ("--grid phi0=...") and the broken rule:
  /// n >= 1, finite bounds, and bounds inside the parameter's domain (A >= 0, T0 > 0,
  /// 0 <= e <= 1, 0 <= margin < 0.5, 0 < alpha < 1).
  void Validate() const;
  /// The axis as `name=lo:hi:n` with round-trip numbers (for messages and checkpoints).
  std::string ToString() const;
};

/// Parses `name=lo:hi:n` (lo and hi are numbers or +-pi). Throws std::invalid_argument
/// "--grid <spec> is invalid: ..." for an unknown name, a malformed spec or a bad value.
GridAxis ParseGridAxis(const std::string& spec);

/// One or two axes; the point index runs row-major (the last axis varies fastest).
struct Grid {
  std::vector<GridAxis> axes;  ///< 1 or 2 axes, first = slowest

  /// Validates each axis and the combination: 1 or 2 axes, no parameter twice, not alpha
  /// together with phi0 (alpha determines phi0), at most 2^53 points.
  void Validate() const;
  /// Number of points: the product of the axes' n.
  std::int64_t size() const;
  /// True when one axis varies `parameter`.
  bool Has(SweepParameter parameter) const;
  /// The value of axis `axis` at point index `point` (row-major).
  double Value(std::int64_t point, std::size_t axis) const;
};

}  // namespace capsubot
