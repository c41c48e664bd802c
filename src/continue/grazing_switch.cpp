// Branch switching at a grazing (docs/continuation.md): the motion with other impacts per
// period just beyond the grazing, found by Newton shooting from the grazing's state, followed
// as a branch of its own.

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "capsubot/attract/detail/period_map.hpp"
#include "capsubot/continue/branch_switch.hpp"

namespace capsubot {
namespace {

// Displacements of the parameter beyond the grazing (relative to max(1, |lambda|)), nearest
// first. The grazing's own bracket is about 1e-9 wide, yet the motion of the grazing's side can
// persist a few 1e-6 past it (docs/continuation.md, Limits): the nearest trial lies beyond that.
constexpr double kOffsets[] = {1e-5, 1e-4, 1e-3};
// Periods of the simulator from the grazing's state before the second Newton shooting.
constexpr int kSettlePeriods = 50;
constexpr double kFar = std::numeric_limits<double>::infinity();

// Same impacts per period (right and left): the motions' impacts over a common multiple of
// their periods agree.
bool SameImpactsPerPeriod(const PeriodicMotion& a, const PeriodicMotion& b) {
  return a.impacts_right * b.period == b.impacts_right * a.period &&
         a.impacts_left * b.period == b.impacts_left * a.period;
}

// +1 when the branch met the grazing with its parameter rising, -1 falling: the sign of
// d lambda/ds at the point of the grazing's side times the direction of the arclength from it
// to the point of the other side; at a branch that ends at the grazing (both points on its
// side), the sign of d lambda/ds outwards at that end.
double BeyondSign(const Branch& branch, const SpecialPoint& grazing) {
  const auto k = static_cast<std::size_t>(grazing.after_point);
  const bool first = SameImpactsPerPeriod(branch.points[k].motion, grazing.motion);
  if (first && SameImpactsPerPeriod(branch.points[k + 1].motion, grazing.motion)) {
    const bool forward_end = k + 2 == branch.points.size();
    const double outwards = forward_end ? branch.points[k + 1].tangent : -branch.points[k].tangent;
    return outwards >= 0.0 ? 1.0 : -1.0;
  }
  const BranchPoint& side = branch.points[first ? k : k + 1];
  const BranchPoint& other = branch.points[first ? k + 1 : k];
  return side.tangent * (other.arclength - side.arclength) >= 0.0 ? 1.0 : -1.0;
}

// The smallest distance (largest of |dx|, |du|, |dv|) between the motion m of robot r and the
// state z where m passes z's phase (p times in its period p); infinite at the work bound.
double DistanceAtPhase(const RobotModel& r, const PeriodicMotion& m, const PhaseState& z,
                       const ShootingOptions& so) {
  const detail::PeriodMap map(r, detail::SimulationOf(so));
  detail::MapState s{m.state, m.mode};
  const double shift = std::fmod(std::fmod(z.psi - m.state.psi, kTau) + kTau, kTau) / kTau;
  double nearest = kFar;
  for (int k = 0; k < m.period; ++k) {
    const double periods = k == 0 ? shift : 1.0;
    if (periods > 0.0 && !map.Shift(s, periods)) return kFar;
    nearest = std::min(
        nearest, std::max({std::abs(s.z.x - z.x), std::abs(s.z.u - z.u), std::abs(s.z.v - z.v)}));
  }
  return nearest;
}

// The motion at robot r with other impacts per period than the grazing's, within `near` of
// its state: Newton shooting from that state, then the same after kSettlePeriods periods of
// the simulator. Status kNotRun when neither is kept.
PeriodicMotion MotionBeyond(const RobotModel& r, const SpecialPoint& grazing, double near,
                            ShootingOptions so) {
  for (int transient : {0, kSettlePeriods}) {
    so.transient = transient;
    const PeriodicMotion m = FindPeriodicMotion(r, grazing.motion.state, so);
    if (m.status == ShootingStatus::kConverged && !SameImpactsPerPeriod(m, grazing.motion) &&
        DistanceAtPhase(r, m, grazing.motion.state, so) <= near) {
      return m;
    }
  }
  return {};
}

}  // namespace

Branch SwitchAtGrazing(const RobotFamily& family, const Branch& branch, const SpecialPoint& grazing,
                       ContinuationOptions options) {
  if (grazing.type != SpecialPointType::kGrazing || grazing.after_point < 0 ||
      static_cast<std::size_t>(grazing.after_point) + 1 >= branch.points.size()) {
    throw std::invalid_argument(fmt::format(
        "special point type = {} (after_point = {}) is invalid: expected a grazing of the branch",
        SpecialPointTypeName(grazing.type), grazing.after_point));
  }
  options.start = grazing.parameter;
  options.Validate();
  const double side = BeyondSign(branch, grazing);
  const double scale = std::max(1.0, std::abs(grazing.parameter));
  int trials = 0;
  for (double offset : kOffsets) {
    const double lambda = grazing.parameter + side * offset * scale;
    if (offset * scale <= grazing.accuracy || lambda < options.from || lambda > options.to) {
      continue;
    }
    ++trials;
    const PeriodicMotion m =
        MotionBeyond(family(lambda), grazing, std::sqrt(offset), options.shooting);
    if (m.status != ShootingStatus::kConverged) continue;
    options.start = lambda;
    options.shooting.max_period = m.period;
    options.shooting.transient = 0;
    return ContinueBranch(family, m.state, options);
  }
  Branch none;
  none.status = ContinuationStatus::kNoMotion;
  none.message =
      trials == 0
          ? fmt::format(
                "no parameter {:+g} to {:+g} beyond the grazing lies inside the range [{}, {}] "
                "and outside its bracket (+-{:.2g})",
                side * kOffsets[0] * scale, side * kOffsets[2] * scale, options.from, options.to,
                grazing.accuracy)
          : fmt::format(
                "no periodic motion with other impacts per period at the parameter {:+g} to "
                "{:+g} beyond the grazing (Newton shooting from its state, also after {} "
                "periods of the simulator): the motion ends at the grazing",
                side * kOffsets[0] * scale, side * kOffsets[2] * scale, kSettlePeriods);
  return none;
}

}  // namespace capsubot
