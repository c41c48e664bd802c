#include "optimize/nlopt_constraints.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "capsubot/orbit/stability.hpp"

namespace capsubot::detail {
namespace {

// Smallest factor of the separation constraint -e u (e > 0): the restitutions of the studies
// (e >= 1e-3) keep e itself; a smaller one would leave the constraint far below the others.
constexpr double kSeparationScaleFloor = 1e-3;

bool ClearanceRequired(const Margins& m) { return m.clearance > 0.0 || m.clearance_stroke > 0.0; }

// The validity condition that row i checks (kCount for the problem's own requirements).
Condition ConditionOf(int index) {
  switch (index) {
    case kLeftWallIndex:
      return Condition::kLeftWall;
    case kRightWallIndex:
      return Condition::kRightWall;
    case kClearanceLeftIndex:
    case kClearanceRightIndex:
      return Condition::kClearance;
    case kAlphaLowIndex:
    case kAlphaHighIndex:
      return Condition::kMassRatio;
    case kStickIndex:
      return Condition::kStick;
    case kSeparationIndex:
      return Condition::kSeparation;
    default:
      return Condition::kCount;
  }
}

// rho <= rho_max, up to setup.rho_rel_tol relative.
bool WithinRhoMax(const Evaluation& ev, const ConstraintSetup& setup) {
  return ev.g[kRhoMaxIndex] <= setup.rho_rel_tol * setup.rho_max;
}

}  // namespace

const char* ConstraintName(int index) {
  if (index == kForceBoundIndex) return kForceBoundName;
  if (index == kRhoMaxIndex) return MarginName(Margin::kRhoMax);
  return ConditionName(ConditionOf(index));
}

bool ConstraintSetup::Applies(int index) const {
  switch (index) {
    case kLeftWallIndex:
    case kRightWallIndex:
      return !ClearanceRequired(margins);
    case kClearanceLeftIndex:
    case kClearanceRightIndex:
      return ClearanceRequired(margins);
    case kForceBoundIndex:
      return std::isfinite(force_bound);
    case kRhoMaxIndex:
      return rho_max < OptimizeOptions::kInf;
    default:
      return index >= 0 && index < kConstraintCount;
  }
}

double ConstraintSetup::length() const { return std::min(1.0, params.T0); }

Evaluation Evaluate(const Forcing& forcing, const ConstraintSetup& setup, double force) {
  Evaluation ev;
  const Params& p = setup.params;
  Solution& s = ev.solution;
  s.orbit = ComputeOrbit(forcing, p);
  s.validity = CheckValidity(s.orbit, setup.margins);
  const Orbit& o = s.orbit;
  const Validity& v = s.validity;
  const double length = setup.length();
  const bool stability_required = setup.Applies(kRhoMaxIndex);
  ev.g.fill(kNoOrbitConstraint);
  ev.force = std::isnan(force) ? v.max_force : force;
  ev.g[kForceBoundIndex] = (ev.force - setup.force_bound) / p.T0;
  if (!std::isnan(v.rest_force)) {
    ev.g[kStickIndex] = (v.rest_force - (1.0 - setup.margins.stick) * p.T0) / p.T0;
  }
  ev.g[kRhoMaxIndex] = stability_required ? kNoOrbitConstraint : 0.0;
  if (o.ok()) {
    ev.I = o.I;
    const bool interior_max = !std::isnan(v.x_max);
    ev.g[kLeftWallIndex] = -v.x_min;
    ev.g[kRightWallIndex] = interior_max ? (v.x_max - 1.0) / length : -1.0;
    ev.g[kClearanceLeftIndex] = v.clearance - v.x_min;
    ev.g[kClearanceRightIndex] = interior_max ? (v.x_max - (1.0 - v.clearance)) / length : -1.0;
    ev.g[kAlphaLowIndex] = -o.alpha;
    ev.g[kAlphaHighIndex] = o.alpha - 1.0;
    // For e > 0 the separation e u > 0 is u > 0, whatever positive factor scales it: the
    // factor e is floored at kSeparationScaleFloor, so that the constraint never falls below
    // what COBYLA's arithmetic resolves (-e u at e = 1e-300: its squares underflow and its
    // steps became NaN).
    ev.g[kSeparationIndex] =
        (o.e > 0.0 ? -std::max(o.e, kSeparationScaleFloor) * o.u : o.ddx(0.0)) / p.T0;
    if (stability_required) {
      const Stability st = ComputeStability(o);
      ev.rho = st.spectral_radius;
      if (st.computed && std::isfinite(ev.rho)) ev.g[kRhoMaxIndex] = ev.rho - setup.rho_max;
    }
  }
  ev.violation = 0.0;
  for (int i = 0; i < kConstraintCount; ++i) {
    // A value that is not a number (an orbit at the edge of what doubles resolve) is no orbit:
    // NLopt must never see one (COBYLA does not return from NaN constraints).
    if (!std::isfinite(ev.g[i])) ev.g[i] = kNoOrbitConstraint;
    if (setup.Applies(i)) ev.violation += std::max(ev.g[i], 0.0);
  }
  if (!std::isfinite(ev.I)) ev.I = -std::numeric_limits<double>::infinity();
  ev.valid = v.valid() && ev.I > -std::numeric_limits<double>::infinity() &&
             WithinForceBound(ev.force, setup.force_bound) &&
             (!stability_required || WithinRhoMax(ev, setup));
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
    if (!setup.Applies(i) || !(std::abs(ev.g[i]) <= tol)) continue;
    const char* name = ConstraintName(i);
    if (std::find(names.begin(), names.end(), name) == names.end()) names.emplace_back(name);
  }
  return names;
}

std::vector<Margin> BindingMargins(const Evaluation& ev, const ConstraintSetup& setup, double tol) {
  std::vector<Margin> margins;
  if (!ev.solution.orbit.ok()) return margins;
  auto active = [&](int i) { return setup.Applies(i) && std::abs(ev.g[i]) <= tol; };
  const Margins& m = setup.margins;
  if (active(kClearanceLeftIndex) || active(kClearanceRightIndex)) {
    const double stroke_clearance = m.clearance_stroke * ev.solution.validity.stroke;
    margins.push_back(m.clearance >= stroke_clearance ? Margin::kClearance
                                                      : Margin::kClearanceStroke);
  }
  if (m.stick > 0.0 && active(kStickIndex)) margins.push_back(Margin::kStickMargin);
  if (active(kRhoMaxIndex)) margins.push_back(Margin::kRhoMax);
  return margins;
}

std::string RequirementWords(const ConstraintSetup& setup) {
  const Margins& m = setup.margins;
  std::string words;
  if (m.Any()) {
    words = fmt::format("margins d = {:g}, d_s = {:g}, s = {:g}", m.clearance, m.clearance_stroke,
                        m.stick);
  }
  if (setup.Applies(kRhoMaxIndex)) {
    words += fmt::format("{}spectral radius <= {:g}", words.empty() ? "" : "; ", setup.rho_max);
  }
  return words.empty() ? words : " (" + words + ")";
}

std::string DescribeViolations(const Evaluation& ev, const ConstraintSetup& setup) {
  const Solution& s = ev.solution;
  const Validity& v = s.validity;
  const Params& p = setup.params;
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
        add(fmt::format("clearance (x_min = {:.6g}, x_max = {:.6g}, clearance {:.6g})", v.x_min,
                        v.x_max, v.clearance));
        break;
      case Condition::kStick:
        add(fmt::format("stick (max |F| at rest = {:.6g} > (1 - s) T0 = {:g})", v.rest_force,
                        (1.0 - setup.margins.stick) * p.T0));
        break;
      case Condition::kForceBelowFriction:
        add(fmt::format("force_below_friction (max |F| = {:.6g} > T0 = {:g})", v.max_force, p.T0));
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
    add(fmt::format("{} (max |F| = {:.6g} > {:g})", kForceBoundName, ev.force, setup.force_bound));
  }
  if (setup.Applies(kRhoMaxIndex) && v.valid() && !WithinRhoMax(ev, setup)) {
    add(fmt::format("{} (spectral radius = {:.6g} > {:g})", MarginName(Margin::kRhoMax), ev.rho,
                    setup.rho_max));
  }
  return out;
}

}  // namespace capsubot::detail
