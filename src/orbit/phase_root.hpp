#pragma once
// Zeros in the phase of a function of the force's values (private helper of the orbit stage).

#include <algorithm>
#include <cmath>

#include "capsubot/forcing.hpp"
#include "numerics/safe_newton.hpp"

namespace capsubot::detail {

/// A function of the phase with its first three derivatives, at one phase.
struct PhaseJet {
  double f;
  double df;   ///< f'
  double ddf;  ///< f''
  double d3f;  ///< f'''
};

/// A zero found by PhaseRoot: its phase with cosine and sine, and Phi there.
struct PhaseZero {
  Angle at;
  double Phi;
};

/// Largest last step after which Phi at the zero comes from its Taylor series at the last
/// iterate (PhaseRoot): the first term omitted, step^4 F''/24, is below 1e-21 |F''|.
inline constexpr double kTaylorStep = 1e-5;
/// PhaseRoot stops when the error left after a step is estimated below this, a small fraction
/// of the spacing of doubles near 1: one more step would not move the zero by more than about
/// an ulp.
inline constexpr double kRootErrorTol = 1e-17;

/// The zero in [lo, hi] of a function of the phase whose values at the bracket's ends are
/// known, flo and fhi of opposite signs (or one of them zero): jet(at, force) returns f and
/// its first three derivatives at the angle `at` given the force's jet there (Forcing::Jet).
/// Halley's iteration, kept inside the shrinking bracket (bisection whenever a step would
/// leave it or converge too slowly, as in SafeNewtonFrom), started from the chord's zero.
/// Each iterate's cosine and sine come from the previous one by angle addition
/// (Angle::Toward), so the converging steps cost no sincos. Near the zero a Halley step s
/// leaves an error of about (M^2 - f'''/(6 f')) s^3, M = f''/(2 f') (a Newton step, taken
/// where Halley's would more than double it: M s^2); the iteration stops when the step is
/// below kRootAbsTol or when the bound (M^2 + |f'''/(6 f')|) |s|^3 (M |s|^2) on that error is
/// below kRootErrorTol, and then takes Phi at the zero from the last iterate's values by
/// Taylor's series (Phi' = Pi, Phi'' = F, Phi''' = F'): the force is not evaluated at the
/// zero itself.
template <class Jet>
PhaseZero PhaseRoot(const Forcing& force, const Jet& jet, const Angle& lo, const Angle& hi,
                    double flo, double fhi) {
  if (flo == 0.0) return {lo, force.Values(lo).Phi};
  if (fhi == 0.0) return {hi, force.Values(hi).Phi};
  double neg = flo < 0.0 ? lo.phi : hi.phi, pos = flo < 0.0 ? hi.phi : lo.phi;  // f < 0 < f
  const double chord = lo.phi - flo * (hi.phi - lo.phi) / (fhi - flo);
  double x = chord > lo.phi && chord < hi.phi ? chord : 0.5 * (lo.phi + hi.phi);
  Angle at = (std::abs(flo) <= std::abs(fhi) ? lo : hi).Toward(x);
  double step = hi.phi - lo.phi, step_old = step;  // the last two steps
  for (int it = 0; it < kRootMaxIter; ++it) {
    const ForceJet v = force.Jet(at);
    const PhaseJet j = jet(at, v);
    if (j.f == 0.0) return {at, v.Phi};
    (j.f < 0.0 ? neg : pos) = x;
    const double newton = j.f / j.df, M = 0.5 * j.ddf / j.df;
    const double halley = 1.0 - M * newton;  // Halley's step is newton / halley
    const bool cubic = halley >= 0.5;
    double next = x - (cubic ? newton / halley : newton);
    const double before_last = step_old;
    step_old = step;
    const bool bisect = !(next >= std::min(neg, pos) && next <= std::max(neg, pos)) ||
                        !(std::abs(x - next) <= 0.5 * std::abs(before_last));
    if (bisect) next = 0.5 * (neg + pos);
    step = next - x;
    const double s = std::abs(step);
    const double left =
        cubic ? (M * M + std::abs(j.d3f / (6.0 * j.df))) * s * s * s : std::abs(M) * s * s;
    if (s < kRootAbsTol || (!bisect && s <= kTaylorStep && left < kRootErrorTol)) {
      return {at.Toward(next), v.Phi + step * (v.Pi + 0.5 * step * (v.F + step / 3.0 * v.dF))};
    }
    x = next;
    at = at.Toward(x);
  }
  return {at, force.Values(at).Phi};
}

}  // namespace capsubot::detail
