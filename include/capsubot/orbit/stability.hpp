#pragma once
// Stability of the one-impact orbit through its impact map (docs/model.md section 8).
//
// The state just before a right-wall impact is (theta, u): the motor phase at the impact and
// the relative velocity. One period of the orbit structure impact -> slide -> stop -> rest ->
// next impact maps it to (theta', u'); the orbit of section 4 is a fixed point (theta' =
// theta + tau). The Jacobian is obtained analytically by implicit differentiation of the two
// event equations, g(phi1) = 0 (stop) and x(phi2) = 1 (next impact): no simulation.

#include <Eigen/Core>
#include <array>
#include <complex>

#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/orbit/orbit.hpp"

namespace capsubot {

struct Stability {
  bool computed = false;  ///< false: not computed (orbit did not exist)
  /// Jacobian d(theta', u')/d(theta, u) of the impact map at the fixed point; rows and
  /// columns ordered (theta, u).
  Eigen::Matrix2d jacobian = Eigen::Matrix2d::Constant(kNaN);
  /// Its eigenvalues (Floquet multipliers), ordered by decreasing modulus.
  std::array<std::complex<double>, 2> multipliers{std::complex<double>(kNaN, kNaN),
                                                  std::complex<double>(kNaN, kNaN)};
  double spectral_radius = kNaN;  ///< max |multiplier|
  bool stable = false;            ///< spectral_radius < 1
};

/// How an unstable orbit loses its stability: which multiplier of largest modulus is outside
/// the unit circle (docs/model.md sections 8 and 13).
enum class StabilityLoss {
  kNone,   ///< stable (spectral radius < 1), or stability not computed
  kFold,   ///< the largest multiplier is real and positive (through +1: a fold)
  kFlip,   ///< the largest multiplier is real and negative (through -1: period doubling)
  kTorus,  ///< the largest multipliers are a complex pair (through the circle off the axis)
};

/// "" for kNone (an empty CSV cell), else "fold", "flip", "torus".
const char* StabilityLossName(StabilityLoss loss);

/// The loss of a computed stability with spectral radius >= 1; kNone otherwise.
StabilityLoss ClassifyLoss(const Stability& stability);

/// Stability of the orbit (needs orbit.ok(), else `computed` stays false; never throws).
/// Allocation-free and closed form: a few evaluations of F, Pi and Phi (docs/model.md section 8).
Stability ComputeStability(const Orbit& orbit);

/// The impact map's Jacobian at a general pre-impact state, for checks away from the fixed
/// point. `motor` is the force with phi0 = theta (the motor phase at the impact), `u` the
/// relative velocity before it; `phi1` and `phi2` are the stop phase and the phase of the
/// next right-wall impact, measured from this impact (found by the caller, e.g. by the
/// simulator). Assumes the structure impact -> slide -> stop at phi1 -> rest -> impact at phi2.
Eigen::Matrix2d ImpactMapJacobian(const Forcing& motor, double T0, double e, double alpha, double u,
                                  double phi1, double phi2);

}  // namespace capsubot
