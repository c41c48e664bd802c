#pragma once
// Real zeros of a trigonometric polynomial on an interval (private helper of forcing.cpp).

#include "capsubot/forcing.hpp"

namespace capsubot::detail {

/// Zeros in [lo, hi] (hi - lo <= tau) of  c0 + sum_{k=1..K} (a[k-1] cos k phi + b[k-1] sin k phi),
/// sorted, tangential zeros included once. K = 1 is solved in closed form; larger K through
/// the eigenvalues of the companion matrix of the polynomial in z = exp(i phi), each zero on
/// the unit circle then polished by Newton steps on the real function.
PhaseList TrigRoots(double c0, const double* a, const double* b, int K, double lo, double hi);

}  // namespace capsubot::detail
