#pragma once
// The pieces of the one-impact orbit on which the relative velocity x' is monotone, and its
// zeros (private helper of validity.cpp and orbit_energy.cpp).
//
// x' is continuous on [0, tau] and x'' has the sign of F + alpha*T0 on the slide [0, phi1] and
// of F on the rest [phi1, tau] (docs/model.md sections 3 and 4). Cut at the crossings of those
// levels, each piece has a monotone x' and so at most one zero of x'.

#include "capsubot/orbit.hpp"
#include "numerics/brent.hpp"

namespace capsubot::detail {

/// Calls visit(lo, hi) for each piece [lo, hi] of [0, tau] on which x' is monotone, in
/// increasing order; the pieces tile [0, tau] and phi1 is always a piece boundary. Needs o.ok().
template <class Visit>
void ForEachMonotonePiece(const Orbit& o, Visit&& visit) {
  auto walk = [&](double level, double lo, double hi) {
    const PhaseList cuts = o.forcing.Crossings(level, lo, hi);
    double a = lo;
    for (int i = 0; i < cuts.n; ++i) {
      if (cuts.phi[i] > a && cuts.phi[i] < hi) {
        visit(a, cuts.phi[i]);
        a = cuts.phi[i];
      }
    }
    visit(a, hi);
  };
  walk(-o.alpha * o.T0, 0.0, o.phi1);
  walk(0.0, o.phi1, kTau);
}

/// The zero of x' in a monotone piece [lo, hi] whose ends have x' of opposite signs: a
/// bracketed Newton iteration (x'' is known in closed form).
inline double VelocityZero(const Orbit& o, double lo, double hi) {
  return SafeNewton([&](double p) { return o.dx(p); }, [&](double p) { return o.ddx(p); }, lo, hi);
}

}  // namespace capsubot::detail
