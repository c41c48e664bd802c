#include "optimize/nlopt_constraints.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "capsubot/optimize_result.hpp"
#include "capsubot/stability.hpp"

namespace capsubot::detail {

const char* ConstraintName(int index) {
  namespace n = constraint_names;
  switch (index) {
    case kLeftWallIndex:
      return n::kLeftWall;
    case kRightWallIndex:
      return n::kRightWall;
    case kAlphaLowIndex:
      return n::kMassRatioLow;
    case kAlphaHighIndex:
      return n::kMassRatioHigh;
    case kStickIndex:
      return n::kStick;
    case kForceBoundIndex:
      return n::kForceBound;
    case kSeparationIndex:
      return n::kSeparation;
    case kStabilityIndex:
      return n::kStability;
    default:
      return "unknown";
  }
}

Evaluation Evaluate(const Forcing& forcing, const ConstraintSetup& setup, double force) {
  Evaluation ev;
  const Params& p = setup.params;
  Solution& s = ev.solution;
  s.orbit = ComputeOrbit(forcing, p);
  s.validity = CheckValidity(s.orbit, p.margin);
  const Orbit& o = s.orbit;
  const Validity& v = s.validity;
  ev.g.fill(kNoOrbitConstraint);
  ev.force = std::isnan(force) ? v.max_force : force;
  ev.g[kForceBoundIndex] = (ev.force - setup.force_bound) / p.T0;
  if (!std::isnan(v.rest_force)) ev.g[kStickIndex] = (v.rest_force - p.T0) / p.T0;
  ev.g[kStabilityIndex] = setup.stable ? kNoOrbitConstraint : 0.0;
  if (o.ok()) {
    ev.I = o.I;
    ev.g[kLeftWallIndex] = p.margin - v.x_min;
    ev.g[kRightWallIndex] = std::isnan(v.x_max) ? -1.0 : v.x_max - (1.0 - p.margin);
    ev.g[kAlphaLowIndex] = -o.alpha;
    ev.g[kAlphaHighIndex] = o.alpha - 1.0;
    ev.g[kSeparationIndex] = o.e > 0.0 ? -o.e * o.u : o.ddx(0.0);
    if (setup.stable) {
      const Stability st = ComputeStability(o);
      ev.rho = st.spectral_radius;
      if (st.computed && std::isfinite(ev.rho)) ev.g[kStabilityIndex] = ev.rho - setup.rho_max;
    }
  }
  ev.violation = 0.0;
  for (double g : ev.g) ev.violation += std::max(g, 0.0);
  ev.valid = v.valid() && WithinForceBound(ev.force, setup.force_bound) &&
             (!setup.stable || ev.g[kStabilityIndex] <= 0.0);
  // CheckValidity and the g_i agree on the orbit conditions; a valid orbit has no violation.
  if (ev.valid) ev.violation = 0.0;
  return ev;
}

double SpectralRadius(const Evaluation& ev) {
  if (!std::isnan(ev.rho) || !ev.solution.orbit.ok()) return ev.rho;
  const Stability st = ComputeStability(ev.solution.orbit);
  return st.computed ? st.spectral_radius : ev.rho;
}

bool Better(const Evaluation& a, const Evaluation& b) {
  if (a.valid != b.valid) return a.valid;
  if (a.valid) return a.I > b.I;
  if (a.violation != b.violation) return a.violation < b.violation;
  return a.I > b.I;
}

std::vector<std::string> ActiveConstraints(const Evaluation& ev, const ConstraintSetup& setup,
                                           double tol) {
  std::vector<std::string> names;
  if (!ev.solution.orbit.ok()) return names;
  for (int i = 0; i < kConstraintCount; ++i) {
    if (i == kForceBoundIndex && !std::isfinite(setup.force_bound)) continue;
    if (i == kStabilityIndex && !setup.stable) continue;
    if (std::abs(ev.g[i]) <= tol) names.emplace_back(ConstraintName(i));
  }
  return names;
}

std::string DescribeViolations(const Evaluation& ev, const ConstraintSetup& setup) {
  const Solution& s = ev.solution;
  const Validity& v = s.validity;
  std::string out;
  auto add = [&out](const std::string& item) { out += (out.empty() ? "" : ", ") + item; };
  for (int i = 0; i < static_cast<int>(Condition::kCount); ++i) {
    const auto c = static_cast<Condition>(i);
    if (!v.violated(c)) continue;
    switch (c) {
      case Condition::kLeftWall:
        add(fmt::format("left_wall (x_min = {:.6g} < 0)", v.x_min));
        break;
      case Condition::kRightWall:
        add(fmt::format("right_wall (x_max = {:.6g} > 1)", v.x_max));
        break;
      case Condition::kClearance:
        add(fmt::format("clearance (x_min = {:.6g}, x_max = {:.6g}, margin {:g})", v.x_min, v.x_max,
                        setup.params.margin));
        break;
      case Condition::kStick:
        add(fmt::format("stick (max |F| at rest = {:.6g} > T0 = {:g})", v.rest_force,
                        setup.params.T0));
        break;
      case Condition::kForceBelowFriction:
        add(fmt::format("force_below_friction (max |F| = {:.6g} > T0 = {:g})", v.max_force,
                        setup.params.T0));
        break;
      case Condition::kMassRatio:
        add("mass_ratio (no alpha in (0, 1) closes the orbit)");
        break;
      default:
        add(ConditionName(c));
    }
  }
  if (!WithinForceBound(ev.force, setup.force_bound) &&
      !v.violated(Condition::kForceBelowFriction)) {
    add(fmt::format("force_bound (max |F| = {:.6g} > {:g})", ev.force, setup.force_bound));
  }
  if (setup.stable && v.valid() && !(ev.g[kStabilityIndex] <= 0.0)) {
    add(fmt::format("stability (spectral radius = {:.6g} > {:g})", ev.rho, setup.rho_max));
  }
  return out;
}

}  // namespace capsubot::detail
