#pragma once
// Roots in the phase of a function of the force's values (private helper of the orbit stage).

#include <cmath>
#include <utility>

#include "capsubot/forcing.hpp"
#include "numerics/safe_newton.hpp"

namespace capsubot::detail {

/// The root in [lo, hi] of a function of the phase whose values at the bracket's ends are
/// known, flo and fhi of opposite signs (or one of them zero): fdf(at, values) returns
/// {f, f'} at the angle `at` given the force's values there. A bracketed Newton iteration
/// (SafeNewtonBracket) started from the chord's zero; each iterate's cosine and sine come from
/// the previous one by angle addition (Angle::Toward), so the converging steps cost no sincos,
/// and so does the root's angle, returned with it.
template <class FDf>
Angle PhaseRoot(const Forcing& force, const FDf& fdf, const Angle& lo, const Angle& hi, double flo,
                double fhi) {
  Angle at = std::abs(flo) <= std::abs(fhi) ? lo : hi;  // the chord's zero is nearer this end
  const auto step = [&](double phi) {
    at = at.Toward(phi);
    return fdf(at, force.Values(at));
  };
  const double root =
      SafeNewtonBracket(step, lo.phi, hi.phi, flo, fhi, NewtonStart::kFalsePosition);
  if (root == lo.phi) return lo;
  if (root == hi.phi) return hi;
  return at.Toward(root);
}

}  // namespace capsubot::detail
