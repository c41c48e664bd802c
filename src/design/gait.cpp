// The robust one-impact gait of one physical robot, in the user's units (docs/model.md
// sections 8, 9, 11 and 12).

#include <algorithm>
#include <cmath>
#include <iterator>

#include "capsubot/design.hpp"
#include "capsubot/optimize_options.hpp"
#include "capsubot/orbit_energy.hpp"
#include "capsubot/robot_orbits.hpp"
#include "capsubot/validity.hpp"
#include "design/user_units.hpp"
#include "model/enum_names.hpp"

namespace capsubot {
namespace {

// A limit binds when its slack is below this (units: x in L, |F| in T0, multiplier modulus).
// The searches locate the edge of a feasible set to 1e-9 in log(m2) or log(f); slacks vanish
// there at least like the square root of the distance (a fold), so 1e-4 is well above them.
constexpr double kBindingTol = 1e-4;

// The robustness limits of docs/model.md section 12 whose slack at the gait is below
// kBindingTol, in the order of design.hpp: the walls at the required clearance (validity's
// max(d, d_s * stroke)), the stick margin, the force bound and the stability bound.
std::vector<std::string> Binding(const DesignInput& in, const Gait& gait) {
  const Validity& v = gait.solution.validity;
  const double T0 = gait.model.params.T0;
  std::vector<std::string> names;
  if (v.x_min - v.clearance <= kBindingTol) names.emplace_back(ConditionName(Condition::kLeftWall));
  if (1.0 - v.clearance - v.x_max <= kBindingTol) {  // NaN (no interior maximum): not binding
    names.emplace_back(ConditionName(Condition::kRightWall));
  }
  if ((1.0 - in.stick_margin) - v.rest_force / T0 <= kBindingTol) {
    names.emplace_back(ConditionName(Condition::kStick));
  }
  if (1.0 - v.max_force / T0 <= kBindingTol) names.emplace_back(kForceBoundName);
  if (in.rho_max - gait.stability.spectral_radius <= kBindingTol) {
    names.emplace_back(MarginName(Margin::kRhoMax));
  }
  return names;
}

}  // namespace

const char* GaitStatusName(GaitStatus status) {
  static constexpr const char* kNames[] = {"not_run", "ok", "motor_slides_shell", "no_orbit",
                                           "not_robust"};
  static_assert(std::size(kNames) == static_cast<std::size_t>(GaitStatus::kNotRobust) + 1);
  return detail::EnumName(kNames, status);
}

Gait EvaluateGait(const DesignInput& input, double m2, double frequency) {
  input.Validate();
  Gait gait;
  gait.m2_kg = m2;
  gait.frequency_hz = frequency;
  gait.model = MapToModel(input, m2, frequency);
  const DesignModel& m = gait.model;
  if (!WithinForceBound(m.forcing.MaxAbs(), m.params.T0)) {
    gait.status = GaitStatus::kMotorSlidesShell;
    return gait;
  }
  const std::vector<Solution> orbits =
      FindRobotOrbits(m.forcing, m.params, m.alpha, &gait.complete, input.orbit_evaluations);
  gait.orbits = static_cast<int>(orbits.size());
  gait.status = orbits.empty() ? GaitStatus::kNoOrbit : GaitStatus::kNotRobust;
  for (const Solution& s : orbits) {
    if (!s.validity.valid()) continue;
    const Stability st = ComputeStability(s.orbit);
    if (!(st.computed && st.spectral_radius <= input.rho_max)) continue;
    if (gait.ok() && !(s.orbit.v_mean > gait.solution.orbit.v_mean)) continue;
    gait.status = GaitStatus::kOk;
    gait.solution = s;
    gait.stability = st;
  }
  if (!gait.ok()) return gait;
  gait.energy = OrbitEnergy(gait.solution.orbit);
  const Orbit& o = gait.solution.orbit;
  detail::FillUserUnits(input, o.T0, m.omega, o.v_mean, o.I, o.u, gait.energy, gait);
  gait.binding = Binding(input, gait);
  return gait;
}

}  // namespace capsubot
