#include "capsubot/orbit/validity.hpp"

#include <algorithm>
#include <cmath>
#include <iterator>

#include "capsubot/model/detail/enum_names.hpp"
#include "orbit/velocity_pieces.hpp"

namespace capsubot {
namespace {

void Set(Validity& v, Condition c, bool violated) {
  if (violated) v.violations |= 1U << static_cast<unsigned>(c);
}

// Exact extrema of x: x' is monotone on each piece of detail::ForEachMonotonePiece, so each
// piece holds at most one zero of x', a minimum where x' rises through it, else a maximum.
void PositionExtrema(const Orbit& o, Validity& v) {
  v.x_min = 1.0;  // x(0) = x(tau) = 1
  v.phi_x_min = 0.0;
  detail::ForEachMonotonePiece(o, [&](const Angle& lo, const Angle& hi, double dlo, double dhi) {
    if (!(dlo * dhi < 0.0)) return;
    const detail::PhaseZero r = detail::VelocityZero(o, lo, hi, dlo, dhi);
    const double xr = detail::RelativePosition(o, r.at.phi, r.values.Phi, o.Phi1);
    if (dlo < 0.0) {  // x' from - to +: local minimum
      if (xr < v.x_min) {
        v.x_min = xr;
        v.phi_x_min = r.at.phi;
      }
    } else if (!(xr <= v.x_max)) {  // local maximum (x_max starts as NaN)
      v.x_max = xr;
      v.phi_x_max = r.at.phi;
    }
  });
}

}  // namespace

const char* ConditionName(Condition condition) {
  static constexpr const char* kNames[] = {"positive_mean_force",
                                           "mass_ratio",
                                           "force_below_friction",
                                           "stick",
                                           "left_wall",
                                           "right_wall",
                                           "separation",
                                           "clearance",
                                           "finite"};
  static_assert(std::size(kNames) == static_cast<std::size_t>(Condition::kCount));
  return detail::EnumName(kNames, condition);
}

std::vector<std::string> Validity::ViolationNames() const {
  std::vector<std::string> names;
  for (int i = 0; i < static_cast<int>(Condition::kCount); ++i) {
    if (violated(static_cast<Condition>(i))) names.emplace_back(ConditionName(Condition(i)));
  }
  return names;
}

Validity CheckValidity(const Orbit& o, const Margins& margins) {
  Validity v;
  v.checked = true;
  v.max_force = o.forcing.MaxAbs();
  Set(v, Condition::kForceBelowFriction, !WithinForceBound(v.max_force, o.T0));
  if (o.status == OrbitStatus::kNonFinite || !std::isfinite(v.max_force)) {
    Set(v, Condition::kFinite, true);
    return v;
  }
  if (o.status == OrbitStatus::kNonPositiveMeanForce) {
    Set(v, Condition::kPositiveMeanForce, true);
    return v;
  }
  const Range rest = o.forcing.Bounds(detail::StopAngle(o), Angle::Of(kTau));
  v.rest_force = std::max(std::abs(rest.min), std::abs(rest.max));
  Set(v, Condition::kStick, !WithinForceBound(v.rest_force, (1.0 - margins.stick) * o.T0));
  if (!o.ok()) {
    Set(v, Condition::kMassRatio, true);
    return v;
  }
  PositionExtrema(o, v);
  Set(v, Condition::kLeftWall, !(v.x_min >= 0.0));
  Set(v, Condition::kRightWall, v.x_max > 1.0);
  // After the impact x' = -e u < 0; for e = 0 the inner body must accelerate away: x''(0+) < 0.
  Set(v, Condition::kSeparation, !(o.e * o.u > 0.0 || (o.e == 0.0 && o.ddx(0.0) < 0.0)));
  v.stroke = (v.x_max > 1.0 ? v.x_max : 1.0) - v.x_min;
  v.clearance = std::max(margins.clearance, margins.clearance_stroke * v.stroke);
  if (v.clearance > 0.0) {
    Set(v, Condition::kClearance, !(v.x_min >= v.clearance) || v.x_max > 1.0 - v.clearance);
  }
  // x_max is NaN when x has no interior maximum; an infinite one overflowed.
  Set(v, Condition::kFinite,
      !std::isfinite(v.x_min) || std::isinf(v.x_max) || !std::isfinite(v.rest_force));
  return v;
}

Solution Solve(const Forcing& forcing, const Params& params, const Margins& margins) {
  // The members are initialized in order, so the check sees the finished orbit (and the
  // solution is not cleared first, as it is when the validity starts as Validity{}).
  // ComputeOrbit validates the params, then the margins are (in that order, as messages go).
  Solution s{ComputeOrbit(forcing, params), (margins.Validate(), CheckValidity(s.orbit, margins))};
  return s;
}

}  // namespace capsubot
