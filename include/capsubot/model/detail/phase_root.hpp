#pragma once
// Zeros in the phase of a function of the force's values: the root finder of the analytic
// orbit (the force seen from the impact, Forcing) and of the simulator's events (the force seen
// from a segment's origin, detail::SegmentForce).

#include <algorithm>
#include <cmath>

#include "capsubot/model/forcing.hpp"
#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/numerics/safe_newton.hpp"

namespace capsubot::detail {

/// A function of the phase with its first three derivatives, at one phase.
struct PhaseJet {
  double f;
  double df;   ///< f'
  double ddf;  ///< f''
  double d3f;  ///< f'''
};

/// A zero found by PhaseRoot: its phase with cosine and sine, and the force's values there.
struct PhaseZero {
  Angle at;
  ForceValues values;
};

/// How PhaseRoot moves from one iterate's angle to the next one for the force seen from the
/// impact: angle addition for short steps (Angle::Toward).
inline Angle StepAngle(const Forcing& force, const Angle& from, double to) {
  (void)force;
  return from.Toward(to);
}

/// Largest last step after which the values at the zero come from their Taylor series at the
/// last iterate (PhaseRoot): the first terms omitted, step^4 F''/24 in Phi, step^4 F'''/24 in
/// Pi and step^3 F'''/6 in F, are below 1e-21 |F''|, 1e-21 |F'''| and 2e-16 |F'''|.
inline constexpr double kTaylorStep = 1e-5;
/// PhaseRoot stops when the error left after a step is estimated below this, a small fraction
/// of the spacing of doubles near 1: one more step would not move the zero by more than about
/// an ulp.
inline constexpr double kRootErrorTol = 1e-17;

/// One end of a bracket: the angle, and f, f', f'' there.
struct BracketEnd {
  Angle at;
  double f, df, ddf;
};

/// The zero next to e of the parabola of f at e, f + f' h + f'' h^2/2 (in the form without
/// cancellation); NaN when it has none.
inline double ParabolaZero(const BracketEnd& e) {
  const double disc = e.df * e.df - 2.0 * e.f * e.ddf;
  if (!(disc >= 0.0)) return kNaN;
  return e.at.phi - 2.0 * e.f / (e.df + std::copysign(std::sqrt(disc), e.df));
}

/// A first iterate for PhaseRoot where the zero may lie close to one end of a long bracket
/// (a short flight, a short slide), which the chord places badly: ParabolaZero of the end
/// whose Newton step -f/f' is the shorter; NaN when it is not strictly inside the bracket.
inline double ParabolaStart(const BracketEnd& lo, const BracketEnd& hi) {
  const double x = ParabolaZero(std::abs(lo.f * hi.df) <= std::abs(hi.f * lo.df) ? lo : hi);
  return x > lo.at.phi && x < hi.at.phi ? x : kNaN;
}

/// The zero in [lo, hi] of a function of the phase whose values at the bracket's ends are
/// known, flo and fhi of opposite signs (or one of them zero): jet(at, force) returns f and
/// its first three derivatives at the angle `at` given the force's jet there (force.Jet(at)).
/// Halley's iteration, kept inside the shrinking bracket (bisection whenever a step would
/// leave it or converge too slowly, as in SafeNewtonFrom), started from `start` when it lies
/// inside the bracket (stepping its angle from the nearer end), else from the chord's zero.
/// Each iterate's cosine and sine come from the previous one by angle addition
/// (Angle::Toward), so the converging steps cost no sincos. Near the zero a Halley step s
/// leaves an error of about (M^2 - f'''/(6 f')) s^3, M = f''/(2 f') (a Newton step, taken
/// where Halley's would more than double it: M s^2); the iteration stops when the step is
/// below kRootAbsTol or when the bound (M^2 + |f'''/(6 f')|) |s|^3 (M |s|^2) on that error is
/// below kRootErrorTol, and then takes F, Pi and Phi at the zero from the last iterate's jet
/// by Taylor's series (Phi' = Pi, Pi' = F): the force is not evaluated at the zero itself.
/// `force` is a Forcing or a detail::SegmentForce (Jet and Values of an Angle, and StepAngle).
template <class Force, class Jet>
PhaseZero PhaseRoot(const Force& force, const Jet& jet, const Angle& lo, const Angle& hi,
                    double flo, double fhi, double start = kNaN) {
  if (flo == 0.0) return {lo, force.Values(lo)};
  if (fhi == 0.0) return {hi, force.Values(hi)};
  double neg = flo < 0.0 ? lo.phi : hi.phi, pos = flo < 0.0 ? hi.phi : lo.phi;  // f < 0 < f
  double x = start;
  const Angle* from = &lo;  // the end whose angle the first iterate's is stepped from
  if (start > lo.phi && start < hi.phi) {
    if (hi.phi - x < x - lo.phi) from = &hi;
  } else {
    const double chord = lo.phi - flo * (hi.phi - lo.phi) / (fhi - flo);
    x = chord > lo.phi && chord < hi.phi ? chord : 0.5 * (lo.phi + hi.phi);
    if (std::abs(flo) > std::abs(fhi)) from = &hi;
  }
  Angle at = StepAngle(force, *from, x);
  double step = hi.phi - lo.phi, step_old = step;  // the last two steps
  for (int it = 0; it < kRootMaxIter; ++it) {
    const ForceJet v = force.Jet(at);
    const PhaseJet j = jet(at, v);
    if (j.f == 0.0) return {at, {v.F, v.Pi, v.Phi}};
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
      const double h = step;
      return {StepAngle(force, at, next),
              {v.F + h * (v.dF + 0.5 * h * v.ddF),
               v.Pi + h * (v.F + 0.5 * h * (v.dF + h / 3.0 * v.ddF)),
               v.Phi + h * (v.Pi + 0.5 * h * (v.F + h / 3.0 * v.dF))}};
    }
    x = next;
    at = StepAngle(force, at, x);
  }
  return {at, force.Values(at)};
}

}  // namespace capsubot::detail
