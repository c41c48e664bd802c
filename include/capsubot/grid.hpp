#pragma once
// Grids of parameter values for sweeps. An axis is written `name=lo:hi:n` (n equally spaced
// values from lo to hi inclusive; n = 1 means lo alone), `name=lo:hi:n:log` (n geometrically
// spaced values, lo, hi > 0) or `name=v1,v2,...` (an explicit list, in that order). A grid
// is any number of axes over different parameters; its points run row-major: the first axis
// varies slowest, the last fastest.
//
// Every parameter a grid can vary is one row of a table (its name, its domain and the rule a
// message states): SweepParameterName, ParseGridAxis and the checks all read it.

#include <cstdint>
#include <string>
#include <vector>

namespace capsubot {

/// A parameter a grid can vary (docs/model.md sections 2, 6, 7 and 8 for the symbols).
enum class SweepParameter {
  kA,        ///< amplitude A of F = A sin(phi + phi0) + c (the sine coefficient b_1)
  kc,        ///< mean force c
  kphi0,     ///< motor phase at the impact phi0 [rad]
  kT0,       ///< friction bound T0
  ke,        ///< restitution e
  kmargin,   ///< clearance d
  kalpha,    ///< mass ratio of a given robot: phi0 is then solved for (docs/model.md section 8)
  kcos,      ///< cosine coefficient a_k of the Fourier force (GridAxis::harmonic = k)
  ksin,      ///< sine coefficient b_k of the Fourier force (GridAxis::harmonic = k)
  kbound,    ///< force bound of problems P2 and P3: A + c (max |F|) <= bound
  krho_max,  ///< largest admissible spectral radius of a stability requirement
  kmargin_stroke,  ///< clearance relative to the stroke d_s (docs/model.md section 12)
  kstick_margin,   ///< stick margin s (docs/model.md section 12)
};

/// Largest number of points of a grid (the product of its axes' sizes), checked by
/// Grid::Validate before any work: 10^9 rows of about 110 bytes are a 110 GB file.
inline constexpr std::int64_t kMaxGridPoints = 1000000000;

/// The parameter's name as written in a grid and in CSV headers ("A", "phi0", "a2", ...);
/// `harmonic` is k for kcos and ksin ("a" and "b" alone when it is 0).
std::string SweepParameterName(SweepParameter parameter, int harmonic = 0);

/// Every name a grid accepts, for messages: "A, c, phi0, T0, e, margin, alpha, a1..a16, ...".
std::string SweepParameterNames();

/// How the values of an axis are spaced.
enum class GridSpacing {
  kLinear,  ///< lo:hi:n, equal steps
  kLog,     ///< lo:hi:n:log, equal ratios (lo, hi > 0)
  kList,    ///< v1,v2,...: the listed values
};

/// Where a parameter's values may lie: [min, max], open ends excluded, and the rule a message
/// states ("" when every finite value is admissible); `infinite`: +infinity is a value too
/// (written `inf` in a list: a bound that is no bound, as rho_max = inf).
struct GridDomain {
  double min = 0.0;
  bool min_open = false;
  double max = 0.0;
  bool max_open = false;
  const char* rule = "";
  bool infinite = false;
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
  void Check(const std::string& spec, const GridDomain& domain) const;
};

/// One axis of a sweep's grid.
struct GridAxis : GridValues {
  SweepParameter parameter = SweepParameter::kphi0;  ///< what varies
  int harmonic = 0;                                  ///< k of a_k or b_k (1..kMaxHarmonics), else 0

  /// The parameter's name ("phi0", "a2").
  std::string name() const { return SweepParameterName(parameter, harmonic); }
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
GridValues ParseGridValues(const std::string& spec, const GridDomain& domain);

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
  /// True when an axis varies `parameter` (with `harmonic` k for kcos and ksin; 0 means any k).
  bool Has(SweepParameter parameter, int harmonic = 0) const;
  /// The value of axis `axis` at point index `point` (row-major).
  double Value(std::int64_t point, std::size_t axis) const;
};

}  // namespace capsubot
