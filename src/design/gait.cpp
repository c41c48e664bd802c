// The robust one-impact gait of one physical robot, in the user's units (docs/model.md
// sections 8, 9, 11 and 12).

#include <algorithm>
#include <array>
#include <cmath>
#include <iterator>
#include <limits>

#include "capsubot/design/design.hpp"
#include "capsubot/model/detail/enum_names.hpp"
#include "capsubot/optimize/optimize_options.hpp"
#include "capsubot/orbit/orbit_energy.hpp"
#include "capsubot/orbit/robot_orbits.hpp"
#include "capsubot/orbit/validity.hpp"
#include "design/search.hpp"
#include "design/user_units.hpp"

namespace capsubot {
namespace {

// A limit binds when its slack is below this (units: x in L, |F| in T0, multiplier modulus).
// The searches locate the edge of a feasible set to 1e-9 in log(m2) or log(f); slacks vanish
// there at least like the square root of the distance (a fold), so 1e-4 is well above them.
constexpr double kBindingTol = 1e-4;

// The robustness limits of docs/model.md section 12, in the order of Gait::binding: the walls
// at the required clearance (validity's max(d, d_s * stroke)), the stick margin, the force
// bound and the stability bound.
constexpr std::size_t kLimits = 5;
const char* LimitName(std::size_t k) {
  switch (k) {
    case 0:
      return ConditionName(Condition::kLeftWall);
    case 1:
      return ConditionName(Condition::kRightWall);
    case 2:
      return ConditionName(Condition::kStick);
    case 3:
      return kForceBoundName;
    default:
      return MarginName(Margin::kRhoMax);
  }
}

// The slack of each limit at an orbit, positive inside it: x_min - clearance,
// 1 - clearance - x_max, (1 - s) - max|F|/T0 at rest, 1 - max|F|/T0, rho_max - spectral
// radius. NaN where the limit has nothing to measure (no interior maximum of x: the right
// wall; no multipliers).
std::array<double, kLimits> LimitSlacks(const DesignInput& in, const Validity& v, double T0,
                                        double spectral_radius) {
  return {v.x_min - v.clearance, 1.0 - v.clearance - v.x_max,
          (1.0 - in.stick_margin) - v.rest_force / T0, 1.0 - v.max_force / T0,
          in.rho_max - spectral_radius};
}

// The limits whose slack at the gait is below kBindingTol (a NaN slack never binds).
std::vector<std::string> Binding(const DesignInput& in, const Gait& gait) {
  const std::array<double, kLimits> slack = LimitSlacks(
      in, gait.solution.validity, gait.model.robot.params.T0, gait.stability.spectral_radius);
  std::vector<std::string> names;
  for (std::size_t k = 0; k < kLimits; ++k) {
    if (slack[k] <= kBindingTol) names.emplace_back(LimitName(k));
  }
  return names;
}

// Conditions of docs/model.md section 5 without a slack that varies continuously with the
// robot: an orbit that violates one of them is as far from a gait as can be.
constexpr unsigned kAllOrNothing = (1U << static_cast<unsigned>(Condition::kPositiveMeanForce)) |
                                   (1U << static_cast<unsigned>(Condition::kMassRatio)) |
                                   (1U << static_cast<unsigned>(Condition::kFinite));

// An orbit's feasibility measure: the smallest slack of its limits (and, for e = 0, of the
// separation x''(0+) < 0), taken >= 0 when the orbit is a robust gait and <= 0 when it is
// not; -infinity when it violates a condition without slack.
double OrbitSlack(const DesignInput& in, const Solution& s, const Stability& st, bool robust) {
  const Validity& v = s.validity;
  if ((v.violations & kAllOrNothing) != 0 || !s.orbit.ok()) {
    return -std::numeric_limits<double>::infinity();
  }
  double least = std::numeric_limits<double>::infinity();
  for (const double slack : LimitSlacks(in, v, s.orbit.T0, st.spectral_radius)) {
    if (!std::isnan(slack)) least = std::min(least, slack);
  }
  if (s.orbit.e == 0.0) least = std::min(least, -s.orbit.ddx(0.0));
  return robust ? std::max(least, 0.0) : std::min(least, 0.0);
}

}  // namespace

const char* GaitStatusName(GaitStatus status) {
  static constexpr const char* kNames[] = {"not_run", "ok", "motor_slides_shell", "no_orbit",
                                           "not_robust"};
  static_assert(std::size(kNames) == static_cast<std::size_t>(GaitStatus::kNotRobust) + 1);
  return detail::EnumName(kNames, status);
}

Gait EvaluateGait(const DesignInput& input, double m2, double frequency) {
  return detail::EvaluateGait(input, m2, frequency, nullptr);
}

namespace detail {

Gait EvaluateGait(const DesignInput& input, double m2, double frequency, double* slack) {
  input.Validate();
  if (slack != nullptr) *slack = -std::numeric_limits<double>::infinity();
  Gait gait;
  gait.m2_kg = m2;
  gait.frequency_hz = frequency;
  gait.model = MapToModel(input, m2, frequency);
  const DesignModel& m = gait.model;
  if (!WithinForceBound(m.robot.forcing.MaxAbs(), m.robot.params.T0)) {
    gait.status = GaitStatus::kMotorSlidesShell;
    return gait;
  }
  const std::vector<Solution> orbits =
      FindRobotOrbits(m.robot, m.margins, &gait.complete, input.orbit_evaluations);
  gait.orbits = static_cast<int>(orbits.size());
  gait.status = orbits.empty() ? GaitStatus::kNoOrbit : GaitStatus::kNotRobust;
  for (const Solution& s : orbits) {
    if (!s.validity.valid() && slack == nullptr) continue;
    const Stability st = ComputeStability(s.orbit);
    const bool robust = s.validity.valid() && st.computed && st.spectral_radius <= input.rho_max;
    if (slack != nullptr) *slack = std::max(*slack, OrbitSlack(input, s, st, robust));
    if (!robust) continue;
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

}  // namespace detail

}  // namespace capsubot
