#pragma once
// Bounded 1-D maximisation inside a bracket of a function that may be undefined in places and
// may end at a cliff (the edge of a feasible set): golden-section refinement.

#include <cmath>
#include <limits>

#include "capsubot/numerics/not_computed.hpp"

namespace capsubot::detail {

inline constexpr int kGoldenMaxSteps = 100;  ///< refinement steps of GoldenRefine

/// Where a maximum was found.
struct ScanMax {
  double x = kNaN;                                      ///< argument (NaN: f never defined)
  double f = -std::numeric_limits<double>::infinity();  ///< value there
  int evaluations = 0;                                  ///< calls of f
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

}  // namespace capsubot::detail
