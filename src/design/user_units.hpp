#pragma once
// The physical units of a motion of the robot (docs/model.md sections 2, 9 and 11): speed,
// step, impact velocity, energy, power and cost of transport from their dimensionless values.
// Shared by the one-impact gait and the motion reached from rest, whose results have the same
// field names.

#include <cmath>

#include "capsubot/design/design.hpp"
#include "capsubot/model/energy.hpp"

namespace capsubot::detail {

/// Fills the SI fields of `r` (m2_kg and frequency_hz already set) from the mean velocity
/// v_mean (units of omega L), the displacement per forcing period I (units of L), the impact
/// velocity u (units of omega L; NaN: none) and the energy per forcing period `en` of a robot
/// with friction bound T0 and angular frequency omega.
template <class Result>
void FillUserUnits(const DesignInput& in, double T0, double omega, double v_mean, double I,
                   double u, const Energy& en, Result& r) {
  const double L = in.L, M = in.m1 + r.m2_kg;
  const double energy_unit = M * omega * omega * L * L;  // (m1+m2) omega^2 L^2 [J]
  r.speed_mm_s = 1e3 * omega * L * v_mean;
  r.displacement_mm = 1e3 * L * I;
  r.impact_velocity_m_s = omega * L * u;
  r.energy_mj = 1e3 * energy_unit * en.motor_work;
  r.power_mw = r.energy_mj * r.frequency_hz;  // energy per period / period
  r.power_positive_mw = 1e3 * energy_unit * en.motor_work_positive * r.frequency_hz;
  r.friction_loss_mj = 1e3 * energy_unit * en.friction_loss;
  r.impact_loss_mj = 1e3 * energy_unit * en.impact_loss;
  // COT = W/((m1+m2) g L |I|) = mu W/(T0 |I|); its reciprocal times mu is the efficiency.
  r.cot = in.mu * en.motor_work / (T0 * std::abs(I));
  r.efficiency = in.mu / r.cot;
}

}  // namespace capsubot::detail
