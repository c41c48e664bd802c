#pragma once
// Grids of parameter values for sweeps. An axis is written `name=lo:hi:n` (n equally spaced
// values from lo to hi inclusive; n = 1 means lo alone), `name=lo:hi:n:log` (n geometrically
// spaced values, lo, hi > 0) or `name=v1,v2,...` (an explicit list, in that order). A grid
// is any number of axes over different parameters; its points run row-major: the first axis
// varies slowest, the last fastest.
//
// A grid can vary every model parameter (model_parameter.hpp): its name and its domain come
// from the one table of parameters. An alpha axis gives the mass ratio of a robot whose
// impact phases phi0 are then solved for (docs/model.md section 8); an A axis sets the sine
// coefficient b_1 of the force (A of the harmonic family).

#include <cstdint>
#include <string>
#include <vector>

#include "capsubot/model/model_parameter.hpp"

namespace capsubot {

/// Largest number of points of a grid (the product of its axes' sizes), checked by
/// Grid::Validate before any work: 10^9 rows of about 110 bytes are a 110 GB file.
inline constexpr std::int64_t kMaxGridPoints = 1000000000;

/// How the values of an axis are spaced.
enum class GridSpacing {
  kLinear,  ///< lo:hi:n, equal steps
  kLog,     ///< lo:hi:n:log, equal ratios (lo, hi > 0)
  kList,    ///< v1,v2,...: the listed values
};

/// The values of one axis, whatever parameter it varies.
struct GridValues {
  GridSpacing spacing = GridSpacing::kLinear;  ///< how the values are spaced
  double lo = 0.0;                             ///< first value (linear and log spacing)
  double hi = 0.0;                             ///< last value (ignored when n = 1)
  std::int64_t n = 1;                          ///< number of values (linear, log), n >= 1
  std::vector<double> values;                  ///< the values of a list (kList), at least one

  /// Number of values.
  std::int64_t size() const;
  /// The i-th value, i in [0, size()): exactly lo for i = 0 and exactly hi for i = n-1.
  double Value(std::int64_t i) const;
  /// Smallest and largest value.
  double Min() const;
  double Max() const;
  /// The values as written after `name=` (`lo:hi:n`, `lo:hi:n:log`, `v1,v2`) with shortest
  /// round-trip numbers (infinity as `inf`).
  std::string ValuesText() const;
  /// Throws std::invalid_argument "grid <spec> is invalid: ..." naming the broken rule:
  /// 1 <= n <= kMaxGridPoints, finite values (or inf in a list, when the domain admits it) that
  /// do not overflow the spacing, lo, hi > 0 for a log axis, values inside `domain`.
  void Check(const std::string& spec, const ParameterDomain& domain) const;
};

/// One axis of a sweep's grid.
struct GridAxis : GridValues {
  ModelParameter parameter = ModelParameter::kPhi0;  ///< what varies
  int harmonic = 0;                                  ///< k of a_k or b_k (1..kMaxHarmonics), else 0

  /// The parameter's name ("phi0", "a2").
  std::string name() const { return ModelParameterName(parameter, harmonic); }
  /// Throws std::invalid_argument "grid <axis> is invalid: ..." naming the broken rule
  /// (GridValues::Check with the parameter's domain: A >= 0, T0 > 0, 0 <= e <= 1, ...; inf
  /// only for rho_max).
  void Validate() const;
  /// The axis as written (`name=lo:hi:n`, `name=lo:hi:n:log`, `name=v1,v2`) with
  /// shortest round-trip numbers.
  std::string ToString() const { return name() + "=" + ValuesText(); }
};

/// The name of a grid spec `name=...`; throws std::invalid_argument "grid <spec> is invalid:
/// expected name=lo:hi:n, ..." when it has no '='.
std::string GridSpecName(const std::string& spec);

/// The values of a grid spec `name=lo:hi:n`, `name=lo:hi:n:log` or `name=v1,v2,...` for a
/// parameter of `domain` (the caller knows the name): the syntax and rules of ParseGridAxis.
/// Throws std::invalid_argument "grid <spec> is invalid: ...".
GridValues ParseGridValues(const std::string& spec, const ParameterDomain& domain);

/// The value of axis `axis` at point index `point` of the row-major product of `axes` (the
/// first slowest).
template <class Axis>
double RowMajorValue(const std::vector<Axis>& axes, std::int64_t point, std::size_t axis) {
  std::int64_t stride = 1;
  for (std::size_t i = axis + 1; i < axes.size(); ++i) stride *= axes[i].size();
  return axes[axis].Value(point / stride % axes[axis].size());
}

/// Throws std::invalid_argument "grid <specs> is invalid: more than kMaxGridPoints points"
/// when the product of the axes' sizes exceeds kMaxGridPoints.
void CheckGridPoints(const std::vector<std::int64_t>& sizes, const std::string& specs);

/// Parses one axis. Throws std::invalid_argument "grid <spec> is invalid: ..." for an unknown
/// name, a malformed spec or a bad value. Numbers are decimal; lo and hi may also be pi, -pi.
GridAxis ParseGridAxis(const std::string& spec);

/// Any number of axes over different parameters; the point index runs row-major.
struct Grid {
  std::vector<GridAxis> axes;  ///< first = slowest

  /// Validates each axis and the combination: at least one axis, no parameter twice, not
  /// alpha together with phi0 (alpha determines phi0), not A together with b1 (A is b1),
  /// at most kMaxGridPoints points. Messages begin with "grid".
  void Validate() const;
  /// Number of points: the product of the axes' sizes.
  std::int64_t size() const;
  /// True when an axis varies `parameter` (with `harmonic` k for kCos and kSin; 0 means any k).
  bool Has(ModelParameter parameter, int harmonic = 0) const;
  /// The value of axis `axis` at point index `point` (row-major).
  double Value(std::int64_t point, std::size_t axis) const;
};

}  // namespace capsubot
