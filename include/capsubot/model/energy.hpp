#pragma once
// The energy budget of a motion over a span of phase (docs/model.md section 11), dimensionless:
// physical energy = (m1+m2) omega^2 L^2 times these numbers.

#include "capsubot/numerics/not_computed.hpp"

namespace capsubot {

struct Energy {
  double motor_work = kNaN;           ///< integral of F u dphi: net work of the motor
  double motor_work_positive = kNaN;  ///< integral of max(F u, 0): what a drive that cannot
                                      ///< recover energy pays
  double friction_loss = kNaN;        ///< T0 times the integral of |v| dphi
  double impact_loss = kNaN;          ///< sum over impacts of alpha (1-alpha) (1-e^2) u_i^2 / 2
};

}  // namespace capsubot
