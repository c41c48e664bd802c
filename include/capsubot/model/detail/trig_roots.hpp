#pragma once
// Real zeros of a trigonometric polynomial on an interval (private helper of forcing.cpp).

#include "capsubot/model/forcing.hpp"

namespace capsubot::detail {

/// Zeros in [lo, hi] (hi - lo <= tau) of  c0 + sum_{k=1..K} (a[k-1] cos k phi + b[k-1] sin k phi),
/// sorted; a zero of even multiplicity (a touch) is reported once. K = 1 is solved in closed
/// form. Larger K: the interval is cut into charts phi = m + 2 atan(t), on which the series
/// times (1 + t^2)^K is a polynomial of degree 2K in t; its roots are isolated by subdividing
/// its Bernstein form (a piece whose coefficients, beyond their rounding bound, all have one
/// sign holds no root; one sign variation with ends of opposite signs holds exactly one; a
/// piece within rounding noise of zero is one touch), then polished by a bracketed Newton
/// iteration in t and one Newton step on the series in phi. No zero that changes the sign
/// beyond the rounding noise is missed; no allocation.
PhaseList TrigRoots(double c0, const double* a, const double* b, int K, double lo, double hi);

/// Zeros in [lo, hi] (hi - lo <= tau) of c0 + a cos phi + b sin phi = c0 + R sin(phi + delta),
/// R = hypot(a, b) > 0 or 0, delta = atan2(a, b) up to a multiple of tau, sorted, with the
/// cosine and sine of each zero in closed form (no sincos): TrigRoots' closed form for one
/// harmonic, for callers that keep R and delta across the levels c0 they cross.
AngleList HarmonicRootAngles(double c0, double a, double b, double R, double delta, double lo,
                             double hi);

/// The phases of HarmonicRootAngles.
PhaseList HarmonicRoots(double c0, double a, double b, double R, double delta, double lo,
                        double hi);

}  // namespace capsubot::detail
