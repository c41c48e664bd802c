#pragma once
// Bounded 1-D maximisation of a function that may be undefined in places and may end at a
// cliff (the edge of a feasible set): a uniform scan, then golden-section refinement.

#include <cmath>
#include <limits>

namespace capsubot::detail {

inline constexpr int kGoldenMaxSteps = 100;  ///< refinement steps of GoldenRefine

/// Where a maximum was found.
struct ScanMax {
  double x = std::numeric_limits<double>::quiet_NaN();  ///< argument (NaN: f never defined)
  double f = -std::numeric_limits<double>::infinity();  ///< value there
  int index = -1;       ///< index of the best scan sample (-1: none defined)
  int evaluations = 0;  ///< calls of f
};

/// Refines the maximum of f inside the bracket [a, c] around best.x (a <= best.x <= c, f there
/// = best.f, the largest value known in the bracket) by golden-section steps: the best point so
/// far stays in the middle, the trial point goes into the larger side, and a side shrinks
/// whenever its trial is not better. This converges to a local maximum or to the edge of a
/// cliff inside the bracket; it stops when the bracket is narrower than tol or after
/// kGoldenMaxSteps steps. f returns NaN where it is undefined (treated as -infinity). Returns
/// best updated to the best point evaluated; its evaluations count the calls of f.
template <class Fn>
ScanMax GoldenRefine(const Fn& f, double a, double c, double tol, ScanMax best) {
  double b = best.x;
  constexpr double kGolden = 0.38196601125010515;  // (3 - sqrt 5)/2
  for (int step = 0; step < kGoldenMaxSteps && c - a > tol; ++step) {
    const bool right = c - b >= b - a;
    const double x = right ? b + kGolden * (c - b) : b - kGolden * (b - a);
    ++best.evaluations;
    const double fx = f(x);
    const double v = std::isnan(fx) ? -std::numeric_limits<double>::infinity() : fx;
    if (v > best.f) {  // x becomes the middle; the old middle bounds the side it left
      (right ? a : c) = b;
      b = x;
      best.x = x;
      best.f = v;
    } else {
      (right ? c : a) = x;
    }
  }
  return best;
}

/// Maximum of f over [lo, hi]. f returns NaN where it is undefined (treated as -infinity).
/// First n >= 2 uniform samples lo, ..., hi; then the triplet (left neighbour, best sample,
/// right neighbour), clamped to [lo, hi], is refined by GoldenRefine. Returns the best point
/// evaluated: at most n + kGoldenMaxSteps calls.
template <class Fn>
ScanMax ScanGoldenMaximize(const Fn& f, double lo, double hi, int n, double tol) {
  ScanMax best;
  const auto sample = [&](int i) { return i == n - 1 ? hi : lo + (hi - lo) * i / (n - 1); };
  for (int i = 0; i < n; ++i) {
    const double x = sample(i), fx = f(x);
    ++best.evaluations;
    const double v = std::isnan(fx) ? -std::numeric_limits<double>::infinity() : fx;
    if (v > best.f) {
      best.x = x;
      best.f = v;
      best.index = i;
    }
  }
  if (best.index < 0) return best;
  return GoldenRefine(f, sample(best.index > 0 ? best.index - 1 : 0),
                      sample(best.index < n - 1 ? best.index + 1 : n - 1), tol, best);
}

}  // namespace capsubot::detail
