#pragma once
// The one-impact periodic orbit of the paper (docs/model.md section 4).
//
// Per period tau = 2*pi: the inner body hits the right wall at phi = 0 with relative velocity
// u > 0, the capsule slides forward and stops at phi1, then rests until the next impact.

#include "capsubot/model/forcing.hpp"
#include "capsubot/model/params.hpp"
#include "capsubot/numerics/not_computed.hpp"

namespace capsubot {

enum class OrbitStatus {
  kNotRun,                ///< not computed
  kOk,                    ///< phi1 and alpha exist (the orbit may still be invalid: validity.hpp)
  kNonPositiveMeanForce,  ///< Pi(tau) <= 0: no directed one-impact orbit, no phi1
  kNoMassRatio,           ///< psi(0)*psi(1) >= 0: no alpha in (0, 1) closes the orbit
  /// A quantity of the orbit is not a finite number in double precision (or alpha rounds to
  /// 0 or 1): the force or T0 is beyond the range this computation can represent. Rescale
  /// as in docs/model.md section 6.
  kNonFinite,
};

/// Stable identifier of a status ("ok", "non_positive_mean_force", "non_finite", ...).
const char* StatusName(OrbitStatus status);

struct Orbit {
  Forcing forcing;   ///< F(phi), phi = 0 at the impact
  double T0 = kNaN;  ///< friction bound
  double e = kNaN;   ///< restitution
  OrbitStatus status = OrbitStatus::kNotRun;

  double Pi_tau = kNaN;    ///< Pi(tau) = mean force * tau
  double Phi_tau = kNaN;   ///< Phi(tau)
  double phi1 = kNaN;      ///< stop phase: first root of g = Pi(tau) - T0 phi - Pi(phi) in (0, tau)
  double cos_phi1 = kNaN;  ///< cos phi1 (the force at phi1 needs only its cosine and sine)
  double sin_phi1 = kNaN;  ///< sin phi1
  double Phi1 = kNaN;      ///< Phi(phi1)
  double psi0 = kNaN;      ///< psi(0) of the position periodicity condition
  double psi1 = kNaN;      ///< psi(1)
  double alpha = kNaN;     ///< mass ratio m2/(m1+m2) = psi0/(psi0 - psi1)
  double u = kNaN;         ///< relative velocity just before the impact
  double v_plus = kNaN;    ///< capsule velocity just after the impact
  double x1 = kNaN;        ///< x(phi1), where the capsule stops
  double I = kNaN;         ///< displacement per period, integral_0^phi1 v (units of L)
  double v_mean = kNaN;    ///< mean capsule velocity I/tau (units of omega*L)

  bool ok() const { return status == OrbitStatus::kOk; }
  /// State along the period (needs ok()); phi is taken modulo tau into [0, tau], phi = 0
  /// meaning just after the impact and phi = tau just before the next one.
  double x(double phi) const;    ///< relative position of the inner body, walls at 0 and 1
  double dx(double phi) const;   ///< x' = dx/dphi, relative velocity
  double ddx(double phi) const;  ///< x'' (one-sided: the value on the piece phi belongs to)
  double v(double phi) const;    ///< capsule velocity
};

/// Builds the orbit for this force and T0, e.
/// Throws std::invalid_argument for invalid params; never for a force without orbit.
Orbit ComputeOrbit(const Forcing& forcing, const Params& params);

}  // namespace capsubot
