#include "capsubot/orbit.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>
#include <utility>

#include "model/enum_names.hpp"
#include "numerics/safe_newton.hpp"
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

// phi1: the first root in (0, tau) of g = Pi(tau) - T0 phi - Pi(phi) (docs/model.md section 4).
// g' = -T0 - F, so g is monotone between the crossings of F = -T0: walk those pieces and
// bracket the first sign change (g(0) = Pi(tau) > 0 and g(tau) = -T0 tau < 0), then Newton's
// iteration inside the bracket with g and g' from one evaluation of the force per step.
double StopPhase(const Forcing& f, double T0, double Pi_tau) {
  const auto g = [&](double phi) { return Pi_tau - T0 * phi - f.Pi(phi); };
  const auto g_dg = [&](double phi) {
    const ForceValues v = f.Values(phi);  // v.Pi is f.Pi(phi) bit for bit
    return std::pair<double, double>(Pi_tau - T0 * phi - v.Pi, -T0 - v.F);
  };
  const PhaseList cuts = f.Crossings(-T0, 0.0, kTau);
  double lo = 0.0, g_lo = Pi_tau;  // Pi(0) = 0
  for (int i = 0; i <= cuts.n; ++i) {
    const double hi = i < cuts.n ? cuts.phi[i] : kTau;
    if (hi > lo) {
      const double g_hi = g(hi);
      if (g_hi <= 0.0)
        return detail::SafeNewtonBracket(g_dg, lo, hi, g_lo, g_hi,
                                         detail::NewtonStart::kFalsePosition);
      lo = hi;
      g_lo = g_hi;
    }
  }
  return kTau;  // unreachable: g(tau) < 0
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
  o.phi1 = StopPhase(forcing, T0, o.Pi_tau);
  const double phi1 = o.phi1, Phi1 = forcing.Phi(phi1);
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
  const Forcing& f = forcing;
  if (phi <= phi1) {
    return 1.0 - e * u * phi + T0 * phi * phi / (2.0 * (1.0 - alpha)) +
           f.Phi(phi) / (alpha * (1.0 - alpha));
  }
  return x1 + (phi - phi1) * (v_plus - e * u) + (f.Phi(phi) - f.Phi(phi1)) / alpha;
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
