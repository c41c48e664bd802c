#include "capsubot/orbit/stability.hpp"

#include <cmath>
#include <utility>

namespace capsubot {

// Impact map of docs/model.md section 8, differentiated implicitly. Let phi be measured from the
// impact at motor phase theta, so F(phi) = G(theta + phi), and write
//   Pi_theta(phi)  = P(theta + phi) - P(theta),
//   Phi_theta(phi) = Q(theta + phi) - Q(theta) - phi P(theta)
// with P' = G, Q' = P. Then  d Pi_theta(phi)/d theta = F(phi) - F(0)  and
// d Phi_theta(phi)/d theta = Pi(phi) - phi F(0).
//
// Stop (section 4): g(phi1) = alpha (1-alpha)(1+e) u - T0 phi1 - Pi_theta(phi1) = 0.
// During the rest phase (integrating section 3 and using g(phi1) = 0):
//   x(phi)  = 1 - e u phi + Phi_theta(phi)/alpha + (T0 phi1^2/2 + Phi_theta(phi1))/(1-alpha)
//             + (phi - phi1) alpha (1+e) u,
//   x'(phi) = (alpha (1+e) - e) u + Pi_theta(phi)/alpha.
// dx/dphi1 = (T0 phi1 + Pi_theta(phi1))/(1-alpha) - alpha (1+e) u = g(phi1)/(1-alpha) = 0, so
// the stop phase drops out of the first derivatives (an envelope argument). The next impact
// phi2 solves h = x(phi2) - 1 = 0, hence dphi2 = -(h_theta dtheta + h_u du)/h_phi2 with
//   h_phi2 = x'(phi2) = u',
//   h_theta = (Pi(phi2) - phi2 F(0))/alpha + (Pi(phi1) - phi1 F(0))/(1-alpha),
//   h_u = -e phi2 + (phi2 - phi1) alpha (1+e),
// and the map is theta' = theta + phi2, u' = x'(phi2).
Eigen::Matrix2d ImpactMapJacobian(const Forcing& motor, double T0, double e, double alpha, double u,
                                  double phi1, double phi2) {
  (void)T0;  // T0 enters only through phi1 (the envelope argument above)
  const double F0 = motor.F(0.0), F2 = motor.F(phi2);
  const double Pi1 = motor.Pi(phi1), Pi2 = motor.Pi(phi2);
  const double kick = alpha * (1.0 + e) - e;  // du'/du at fixed phi2
  const double u2 = kick * u + Pi2 / alpha;   // x'(phi2), the next impact velocity
  const double h_theta = (Pi2 - phi2 * F0) / alpha + (Pi1 - phi1 * F0) / (1.0 - alpha);
  const double h_u = -e * phi2 + (phi2 - phi1) * alpha * (1.0 + e);
  const double p = -h_theta / u2, q = -h_u / u2;  // dphi2/dtheta, dphi2/du
  Eigen::Matrix2d J;
  J(0, 0) = 1.0 + p;
  J(0, 1) = q;
  J(1, 0) = (F2 - F0) / alpha + F2 / alpha * p;
  J(1, 1) = kick + F2 / alpha * q;
  return J;
}

Stability ComputeStability(const Orbit& orbit) {
  Stability s;
  if (!orbit.ok()) return s;
  s.jacobian =
      ImpactMapJacobian(orbit.forcing, orbit.T0, orbit.e, orbit.alpha, orbit.u, orbit.phi1, kTau);
  // Eigenvalues of a 2x2 matrix from its trace and determinant.
  const Eigen::Matrix2d& J = s.jacobian;
  const double tr = J(0, 0) + J(1, 1), det = J(0, 0) * J(1, 1) - J(0, 1) * J(1, 0);
  const double half = 0.5 * tr, disc = half * half - det;
  using C = std::complex<double>;
  if (disc >= 0.0) {
    // Stable form: the larger-modulus root first, the other from the product det.
    const double big = half + std::copysign(std::sqrt(disc), half);
    s.multipliers = {C(big, 0.0), C(big != 0.0 ? det / big : 0.0, 0.0)};
  } else {
    const double im = std::sqrt(-disc);
    s.multipliers = {C(half, im), C(half, -im)};
  }
  if (std::abs(s.multipliers[1]) > std::abs(s.multipliers[0])) {
    std::swap(s.multipliers[0], s.multipliers[1]);
  }
  s.spectral_radius = std::abs(s.multipliers[0]);
  s.stable = s.spectral_radius < 1.0;
  s.computed = std::isfinite(s.spectral_radius);
  return s;
}

const char* StabilityLossName(StabilityLoss loss) {
  switch (loss) {
    case StabilityLoss::kNone:
      return "";
    case StabilityLoss::kFold:
      return "fold";
    case StabilityLoss::kFlip:
      return "flip";
    case StabilityLoss::kTorus:
      return "torus";
  }
  return "";
}

StabilityLoss ClassifyLoss(const Stability& stability) {
  if (!stability.computed || !(stability.spectral_radius >= 1.0)) return StabilityLoss::kNone;
  // ComputeStability gives a real pair an imaginary part of exactly 0 and a complex pair
  // +-sqrt(-disc) != 0.
  const std::complex<double> largest = stability.multipliers[0];
  if (largest.imag() != 0.0) return StabilityLoss::kTorus;
  return largest.real() > 0.0 ? StabilityLoss::kFold : StabilityLoss::kFlip;
}

}  // namespace capsubot
