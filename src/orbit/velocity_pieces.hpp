#pragma once
// The pieces of the one-impact orbit on which the relative velocity x' is monotone, and its
// zeros (private helper of orbit.cpp, validity.cpp and orbit_energy.cpp).
//
// x' is continuous on [0, tau] and x'' has the sign of F + alpha*T0 on the slide [0, phi1] and
// of F on the rest [phi1, tau] (docs/model.md sections 3 and 4). Cut at the crossings of those
// levels, each piece has a monotone x' and so at most one zero of x'.

#include <utility>

#include "capsubot/orbit.hpp"
#include "orbit/phase_root.hpp"

namespace capsubot::detail {

/// x at phi in [0, tau] given Phi(phi) and Phi1 = Phi(phi1) (docs/model.md section 4; Phi1 is
/// used only on the rest, phi > phi1): the one formula behind Orbit::x and the extrema of x.
inline double RelativePosition(const Orbit& o, double phi, double Phi, double Phi1) {
  if (phi <= o.phi1) {
    return 1.0 - o.e * o.u * phi + o.T0 * phi * phi / (2.0 * (1.0 - o.alpha)) +
           Phi / (o.alpha * (1.0 - o.alpha));
  }
  return o.x1 + (phi - o.phi1) * (o.v_plus - o.e * o.u) + (Phi - Phi1) / o.alpha;
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

/// Calls visit(lo, hi, dlo, dhi) for each piece [lo, hi] of [0, tau] on which x' is monotone,
/// in increasing order, with x' at its ends, dlo and dhi; the pieces tile [0, tau] and phi1
/// (given with its cosine and sine) is always a piece boundary. Needs o.ok().
template <class Visit>
void ForEachMonotonePiece(const Orbit& o, const Angle& phi1, Visit&& visit) {
  Angle a = Angle::Of(0.0);                    // where Pi = 0
  double d_a = RelativeVelocity(o, 0.0, 0.0);  // x' at a
  const auto piece = [&](const Angle& b) {
    const double d_b = RelativeVelocity(o, b.phi, o.forcing.Values(b).Pi);
    visit(a, b, d_a, d_b);
    a = b;
    d_a = d_b;
  };
  const auto walk = [&](double level, const Angle& end) {
    const AngleList cuts = o.forcing.CrossingAngles(level, a.phi, end.phi);
    for (int i = 0; i < cuts.n; ++i) {
      if (cuts.angle[i].phi > a.phi && cuts.angle[i].phi < end.phi) piece(cuts.angle[i]);
    }
    piece(end);
  };
  walk(-o.alpha * o.T0, phi1);
  walk(0.0, Angle::Of(kTau));
}

/// The zero of x' in a monotone piece [lo, hi] whose ends have x' of opposite signs, dlo and
/// dhi (known to the caller), with its cosine and sine: PhaseRoot with x' and x'' from one
/// evaluation of the force per step; the same formulas as Orbit::dx and Orbit::ddx.
inline Angle VelocityZero(const Orbit& o, const Angle& lo, const Angle& hi, double dlo,
                          double dhi) {
  const auto dx_ddx = [&o](const Angle& at, const ForceValues& f) {
    return std::pair<double, double>(RelativeVelocity(o, at.phi, f.Pi),
                                     RelativeAcceleration(o, at.phi, f.F));
  };
  return PhaseRoot(o.forcing, dx_ddx, lo, hi, dlo, dhi);
}

}  // namespace capsubot::detail
