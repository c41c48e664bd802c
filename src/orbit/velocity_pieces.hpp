#pragma once
// The pieces of the one-impact orbit on which the relative velocity x' is monotone, and its
// zeros (private helper of orbit.cpp, validity.cpp and orbit_energy.cpp).
//
// x' is continuous on [0, tau] and x'' has the sign of F + alpha*T0 on the slide [0, phi1] and
// of F on the rest [phi1, tau] (docs/model.md sections 3 and 4). Cut at the crossings of those
// levels, each piece has a monotone x' and so at most one zero of x'.

#include "capsubot/model/detail/phase_root.hpp"
#include "capsubot/orbit/orbit.hpp"

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

/// x''' or x'''' at phi in [0, tau] given F' or F'' there: the derivatives of
/// RelativeAcceleration on its piece.
inline double RelativeHigherDerivative(const Orbit& o, double phi, double dF) {
  if (phi < o.phi1) return dF / (o.alpha * (1.0 - o.alpha));
  return dF / o.alpha;
}

/// phi1 with the cosine and sine ComputeOrbit found it with.
inline Angle StopAngle(const Orbit& o) { return {o.phi1, o.cos_phi1, o.sin_phi1}; }

/// Calls visit(lo, hi, dlo, dhi) for each piece [lo, hi] of [0, tau] on which x' is monotone,
/// in increasing order, with x' at its ends, dlo and dhi; the pieces tile [0, tau] and phi1 is
/// always a piece boundary. Needs o.ok().
template <class Visit>
void ForEachMonotonePiece(const Orbit& o, Visit&& visit) {
  Angle a = Angle::Of(0.0);                    // where Pi = 0
  double d_a = RelativeVelocity(o, 0.0, 0.0);  // x' at a
  const auto piece = [&](const Angle& b, double Pi_b) {
    const double d_b = RelativeVelocity(o, b.phi, Pi_b);
    visit(a, b, d_a, d_b);
    a = b;
    d_a = d_b;
  };
  // The pieces from a to `end`, cut where F crosses `level`; Pi at `end` is known.
  const auto walk = [&](double level, const Angle& end, double Pi_end) {
    const AngleList cuts = o.forcing.CrossingAngles(level, a.phi, end.phi);
    for (int i = 0; i < cuts.n; ++i) {
      const Angle& cut = cuts.angle[i];
      if (cut.phi > a.phi && cut.phi < end.phi) piece(cut, o.forcing.Values(cut).Pi);
    }
    piece(end, Pi_end);
  };
  walk(-o.alpha * o.T0, StopAngle(o), o.Pi_tau - o.T0 * o.phi1);  // g(phi1) = 0
  walk(0.0, Angle::Of(kTau), o.Pi_tau);
}

/// The zero of x' in a monotone piece [lo, hi] whose ends have x' of opposite signs, dlo and
/// dhi (known to the caller), with Phi there: PhaseRoot with x' and its derivatives from one
/// evaluation of the force per step; the same formulas as Orbit::dx and Orbit::ddx.
inline PhaseZero VelocityZero(const Orbit& o, const Angle& lo, const Angle& hi, double dlo,
                              double dhi) {
  const auto jet = [&o](const Angle& at, const ForceJet& f) {
    return PhaseJet{RelativeVelocity(o, at.phi, f.Pi), RelativeAcceleration(o, at.phi, f.F),
                    RelativeHigherDerivative(o, at.phi, f.dF),
                    RelativeHigherDerivative(o, at.phi, f.ddF)};
  };
  return PhaseRoot(o.forcing, jet, lo, hi, dlo, dhi);
}

}  // namespace capsubot::detail
