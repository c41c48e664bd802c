#pragma once
// The pieces of the one-impact orbit on which the relative velocity x' is monotone, and its
// zeros (private helper of orbit.cpp, validity.cpp and orbit_energy.cpp).
//
// x' is continuous on [0, tau] and x'' has the sign of F + alpha*T0 on the slide [0, phi1] and
// of F on the rest [phi1, tau] (docs/model.md sections 3 and 4). Cut at the crossings of those
// levels, each piece has a monotone x' and so at most one zero of x'.

#include <utility>

#include "capsubot/orbit.hpp"
#include "numerics/safe_newton.hpp"

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

/// x' at phi in [0, tau] given Pi(phi) (docs/model.md section 4): the one formula behind
/// Orbit::dx and the root searches below.
inline double RelativeVelocity(const Orbit& o, double phi, double Pi) {
  if (phi <= o.phi1) {
    return -o.e * o.u + o.T0 * phi / (1.0 - o.alpha) + Pi / (o.alpha * (1.0 - o.alpha));
  }
  return o.v_plus - o.e * o.u + Pi / o.alpha;
}

/// x'' at phi in [0, tau] given F(phi) (docs/model.md section 3; one-sided at phi1: the rest's
/// value there): the one formula behind Orbit::ddx and the root searches below.
inline double RelativeAcceleration(const Orbit& o, double phi, double F) {
  if (phi < o.phi1) return (F + o.alpha * o.T0) / (o.alpha * (1.0 - o.alpha));
  return F / o.alpha;
}

/// The zero of x' in a monotone piece [lo, hi] whose ends have x' of opposite signs, dlo and
/// dhi (known to the caller): a bracketed Newton iteration, x' and x'' from one evaluation of
/// the force (one sincos) per step; the same numbers as Orbit::dx and Orbit::ddx.
inline double VelocityZero(const Orbit& o, double lo, double hi, double dlo, double dhi) {
  const auto dx_ddx = [&o](double p) {
    const ForceValues f = o.forcing.Values(p);
    return std::pair<double, double>(RelativeVelocity(o, p, f.Pi), RelativeAcceleration(o, p, f.F));
  };
  return SafeNewtonBracket(dx_ddx, lo, hi, dlo, dhi, NewtonStart::kFalsePosition);
}

}  // namespace capsubot::detail
