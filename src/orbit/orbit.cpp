#include "capsubot/orbit/orbit.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <utility>

#include "capsubot/model/detail/enum_names.hpp"
#include "orbit/velocity_pieces.hpp"

namespace capsubot {
namespace {

// Phase reduced into [0, tau]; exact multiples of tau other than 0 map to tau (pre-impact).
double Wrap(double phi) {
  if (phi >= 0.0 && phi <= kTau) return phi;
  double p = std::fmod(phi, kTau);
  if (p < 0.0) p += kTau;
  return p == 0.0 ? kTau : p;
}

// phi1: the first root in (0, tau) of g = Pi(tau) - T0 phi - Pi(phi) (docs/model.md section 4),
// with its cosine and sine and Phi(phi1). g' = -T0 - F, so g is monotone between the crossings
// of F = -T0: walk those pieces and bracket the first sign change (g(0) = Pi(tau) > 0 and
// g(tau) = -T0 tau < 0), then Halley's iteration inside the bracket (PhaseRoot).
detail::PhaseZero StopPhase(const Forcing& f, double T0, double Pi_tau) {
  const auto g = [&](const Angle& at, double Pi) { return Pi_tau - T0 * at.phi - Pi; };
  const auto jet = [&](const Angle& at, const ForceJet& v) {
    return detail::PhaseJet{g(at, v.Pi), -T0 - v.F, -v.dF, -v.ddF};
  };
  const AngleList cuts = f.CrossingAngles(-T0, 0.0, kTau);
  Angle lo = Angle::Of(0.0);
  double g_lo = Pi_tau;  // Pi(0) = 0
  for (int i = 0; i <= cuts.n; ++i) {
    const Angle hi = i < cuts.n ? cuts.angle[i] : Angle::Of(kTau);
    if (hi.phi > lo.phi) {
      const double g_hi = i < cuts.n ? g(hi, f.Values(hi).Pi) : -T0 * kTau;  // Pi(tau) = Pi_tau
      if (g_hi <= 0.0) return detail::PhaseRoot(f, jet, lo, hi, g_lo, g_hi);
      lo = hi;
      g_lo = g_hi;
    }
  }
  return {Angle::Of(kTau), f.Values(kTau)};  // unreachable: g(tau) < 0
}

}  // namespace

const char* StatusName(OrbitStatus status) {
  static constexpr const char* kNames[] = {"not_run", "ok", "non_positive_mean_force",
                                           "no_mass_ratio", "non_finite"};
  static_assert(std::size(kNames) == static_cast<std::size_t>(OrbitStatus::kNonFinite) + 1);
  return detail::EnumName(kNames, status);
}

Orbit ComputeOrbit(const Forcing& forcing, const Params& params) {
  params.Validate();
  Orbit o;
  o.forcing = forcing;
  o.T0 = params.T0;
  o.e = params.e;
  const double T0 = o.T0, e = o.e, tau = kTau;
  o.Pi_tau = forcing.mean() * tau;
  o.Phi_tau = forcing.Phi(tau);
  if (!std::isfinite(o.Pi_tau) || !std::isfinite(o.Phi_tau)) {
    o.status = OrbitStatus::kNonFinite;
    return o;
  }
  if (!(o.Pi_tau > 0.0)) {
    o.status = OrbitStatus::kNonPositiveMeanForce;
    return o;
  }
  const detail::PhaseZero stop = StopPhase(forcing, T0, o.Pi_tau);
  o.phi1 = stop.at.phi;
  o.cos_phi1 = stop.at.cos;
  o.sin_phi1 = stop.at.sin;
  o.Phi1 = stop.values.Phi;
  const double phi1 = o.phi1, Phi1 = o.Phi1;
  // psi(alpha) = e tau Pi(tau)/(1+e) - (1-alpha) Phi(tau)
  //              - alpha (T0 phi1^2/2 + (tau - phi1) Pi(tau) + Phi(phi1))
  const double head = e * tau * o.Pi_tau / (1.0 + e);
  o.psi0 = head - o.Phi_tau;
  o.psi1 = head - T0 * phi1 * phi1 / 2.0 - (tau - phi1) * o.Pi_tau - Phi1;
  if (!std::isfinite(o.psi0) || !std::isfinite(o.psi1)) {
    o.status = OrbitStatus::kNonFinite;
    return o;
  }
  if (!(o.psi0 * o.psi1 < 0.0)) {
    o.status = OrbitStatus::kNoMassRatio;
    return o;
  }
  const double alpha = o.psi0 / (o.psi0 - o.psi1);
  const double u = o.Pi_tau / (alpha * (1.0 - alpha) * (1.0 + e));
  const double v_plus = o.Pi_tau / (1.0 - alpha);
  const double I = (o.Pi_tau * phi1 - T0 * phi1 * phi1 / 2.0 - Phi1) / (1.0 - alpha);
  const double x1 = 1.0 - e * u * phi1 + T0 * phi1 * phi1 / (2.0 * (1.0 - alpha)) +
                    Phi1 / (alpha * (1.0 - alpha));
  // alpha rounded to 0 or 1 (a tiny psi0 or psi1 next to the other) divides by zero above.
  if (!(alpha > 0.0 && alpha < 1.0 && std::isfinite(u) && std::isfinite(v_plus) &&
        std::isfinite(I) && std::isfinite(x1))) {
    o.status = OrbitStatus::kNonFinite;
    return o;
  }
  o.alpha = alpha;
  o.u = u;
  o.v_plus = v_plus;
  o.I = I;
  o.v_mean = I / tau;
  o.x1 = x1;
  o.status = OrbitStatus::kOk;
  return o;
}

double Orbit::x(double phi) const {
  phi = Wrap(phi);
  return detail::RelativePosition(*this, phi, forcing.Phi(phi), Phi1);
}

double Orbit::dx(double phi) const {
  phi = Wrap(phi);
  return detail::RelativeVelocity(*this, phi, forcing.Pi(phi));
}

double Orbit::ddx(double phi) const {
  phi = Wrap(phi);
  return detail::RelativeAcceleration(*this, phi, forcing.F(phi));
}

double Orbit::v(double phi) const {
  phi = Wrap(phi);
  if (phi >= phi1) return 0.0;
  return (Pi_tau - T0 * phi - forcing.Pi(phi)) / (1.0 - alpha);
}

}  // namespace capsubot
