#pragma once
// Bracketed root finding by safeguarded Newton steps, allocation-free on the hot path.

#include <algorithm>
#include <cmath>
#include <tuple>
#include <utility>

namespace capsubot::detail {

inline constexpr double kRootAbsTol = 1e-14;  ///< absolute tolerance in phase
inline constexpr int kRootMaxIter = 200;

/// Root in [lo, hi] of a function whose values at the bracket's ends are known, flo = f(lo)
/// and fhi = f(hi) of opposite signs (or one of them zero), started from x in the bracket
/// with fx, dfx = f(x), f'(x) known: fdf(x) returns {f(x), f'(x)} from one evaluation (when
/// both share their costly part, e.g. one sincos). Newton steps kept inside a shrinking
/// bracket, bisection whenever a step would leave it or converge too slowly (Numerical
/// Recipes' rtsafe). Quadratic near the root: the hot path's root finder. Started from an end
/// where f f'' > 0 (f convex or concave on the bracket), the Newton steps never overshoot.
template <class FDfn>
double SafeNewtonFrom(const FDfn& fdf, double lo, double hi, double flo, double fhi, double x,
                      double fx, double dfx) {
  if (flo == 0.0) return lo;
  if (fhi == 0.0) return hi;
  if (fx == 0.0) return x;
  if (flo > 0.0) std::swap(lo, hi);  // now f(lo) < 0 < f(hi), lo may exceed hi
  double dx_old = std::abs(hi - lo), dx = dx_old;
  for (int it = 0; it < kRootMaxIter; ++it) {
    const bool newton_leaves = ((x - hi) * dfx - fx) * ((x - lo) * dfx - fx) > 0.0;
    if (newton_leaves || std::abs(2.0 * fx) > std::abs(dx_old * dfx)) {
      dx_old = dx;
      dx = 0.5 * (hi - lo);
      x = lo + dx;
    } else {
      dx_old = dx;
      dx = fx / dfx;
      x -= dx;
    }
    if (std::abs(dx) < kRootAbsTol) return x;
    std::tie(fx, dfx) = fdf(x);
    if (fx == 0.0) return x;
    (fx < 0.0 ? lo : hi) = x;
  }
  return x;
}

/// How SafeNewtonBracket picks its first iterate.
enum class NewtonStart {
  kMidpoint,       ///< the middle of the bracket
  kFalsePosition,  ///< where the chord through the bracket's ends crosses zero
};

/// SafeNewtonFrom with only the values at the bracket's ends known, flo = f(lo), fhi = f(hi):
/// started from the bracket's midpoint or from the chord's zero.
template <class FDfn>
double SafeNewtonBracket(const FDfn& fdf, double lo, double hi, double flo, double fhi,
                         NewtonStart start = NewtonStart::kMidpoint) {
  if (flo == 0.0) return lo;
  if (fhi == 0.0) return hi;
  double x = 0.5 * (lo + hi);
  if (start == NewtonStart::kFalsePosition) {
    const double chord = lo - flo * (hi - lo) / (fhi - flo);
    if (chord > std::min(lo, hi) && chord < std::max(lo, hi)) x = chord;
  }
  const auto [fx, dfx] = fdf(x);
  return SafeNewtonFrom(fdf, lo, hi, flo, fhi, x, fx, dfx);
}

/// Root of f in [lo, hi] with f(lo), f(hi) of opposite signs, given f and f' together:
/// fdf(x) returns {f(x), f'(x)} from one evaluation (when both share their costly part, e.g.
/// one sincos); f alone is evaluated at the bracket's ends.
template <class Fn, class FDfn>
double SafeNewtonFused(const Fn& f, const FDfn& fdf, double lo, double hi) {
  return SafeNewtonBracket(fdf, lo, hi, f(lo), f(hi));
}

/// SafeNewtonFused with f and f' given as two functions.
template <class Fn, class Dfn>
double SafeNewton(const Fn& f, const Dfn& df, double lo, double hi) {
  return SafeNewtonFused(
      f, [&](double x) { return std::pair<double, double>(f(x), df(x)); }, lo, hi);
}

}  // namespace capsubot::detail
