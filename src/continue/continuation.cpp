// Pseudo-arclength continuation of periodic motions (docs/continuation.md).

#include "capsubot/continue/continuation.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <iterator>
#include <stdexcept>

#include "capsubot/attract/detail/period_map.hpp"
#include "capsubot/attract/detail/stroboscopic.hpp"
#include "capsubot/model/detail/enum_names.hpp"
#include "continue/branch_system.hpp"
#include "continue/special_points.hpp"
#include "continue/walk.hpp"
#include "continue/wall_end.hpp"

namespace capsubot {
namespace {

// The most points of a branch: a point holds its motion, Jacobian and events, about 1 KB, and
// about 4 KB more in a JSON document (docs/continuation.md, Options).
constexpr int kMaxPointsLimit = 100000;
// Consecutive tangents must agree this well (cosine of their angle), and the corrected point
// must lie within one step of the predicted one: otherwise the corrector may have jumped to
// another branch, and the step is halved.
constexpr double kMinTangentCosine = 0.5;
// At a lost end, the slope of the wall distance is first taken this fraction of the last step
// back from the last point.
constexpr double kBackFraction = 0.1;

using detail::Node;
using detail::Vec4;

// One direction of the branch from the start.
struct Direction {
  std::vector<Node> nodes;  // in the order found, the start excluded
  // Special points with after_point = k: between node k - 1 (the start for k = 0) and node k.
  std::vector<SpecialPoint> special;
  BranchEnd end = BranchEnd::kMaxPoints;
};

double Dot(const Vec4& a, const Vec4& b) {
  double s = 0.0;
  for (std::size_t i = 0; i < 4; ++i) s += a[i] * b[i];
  return s;
}

using Outcome = detail::BranchSystem::Outcome;

// The point found from a by a step h along its tangent. kOutOfRange: the predictor or an
// iterate of the corrector left the range (*beyond is that point).
Outcome Step(detail::BranchSystem& system, const Node& a, double h, const ContinuationOptions& o,
             Node* b, Vec4* beyond) {
  Vec4 y;
  for (std::size_t i = 0; i < 4; ++i) y[i] = a.y[i] + h * a.t[i];
  const Vec4 predicted = y;
  *beyond = y;
  if (y[3] > o.to || y[3] < o.from) return Outcome::kOutOfRange;
  int iterations = 0;
  const Outcome r = system.Correct(detail::Condition::Arclength(a.t, a.y, h), a.J, y, &iterations);
  *beyond = y;
  if (r != Outcome::kConverged) return r;
  if (!system.Complete(y, a.t, b)) return Outcome::kFailed;
  double moved = 0.0;
  for (std::size_t i = 0; i < 4; ++i) moved = std::max(moved, std::abs(y[i] - predicted[i]));
  b->iterations = iterations;
  b->s = a.s + h;
  // Across a change of the events the branch may have a corner (a grazing impact bends it
  // sharply): only a smooth stretch must keep its direction, every step its length.
  if (moved > h) return Outcome::kFailed;
  return Dot(a.t, b->t) >= kMinTangentCosine || !detail::SameEvents(a, *b) ? Outcome::kConverged
                                                                           : Outcome::kFailed;
}

// The point at the end of the range that a step towards `beyond` passed: the corrector with
// the parameter fixed at the end, from the chord between a and `beyond`.
bool AtEnd(detail::BranchSystem& system, const Node& a, const Vec4& beyond, double edge, Node* b) {
  const double f = (edge - a.y[3]) / (beyond[3] - a.y[3]);
  Vec4 y;
  for (std::size_t i = 0; i < 4; ++i) y[i] = a.y[i] + f * (beyond[i] - a.y[i]);
  y[3] = edge;
  const Vec4 chord = y;
  int iterations = 0;
  if (system.Correct(detail::Condition::Fixed(3, edge), a.J, y, &iterations) !=
          Outcome::kConverged ||
      !system.Complete(y, a.t, b)) {
    return false;
  }
  // As any step: within the step's own length of the prediction, else another motion.
  double moved = 0.0, step = 0.0;
  for (std::size_t i = 0; i < 4; ++i) {
    moved = std::max(moved, std::abs(y[i] - chord[i]));
    step = std::max(step, std::abs(chord[i] - a.y[i]));
  }
  if (moved > step) return false;
  Vec4 d;
  for (std::size_t i = 0; i < 4; ++i) d[i] = y[i] - a.y[i];
  b->iterations = iterations;
  b->s = a.s + Dot(a.t, d);
  return true;
}

// The walk is lost after a (`previous` before it): it ends at a grazing instead when a free
// flight of a's motion reaches a wall there, the grazing's point the last of the direction.
void EndLost(detail::BranchSystem& system, const Node& previous, const Node& a,
             const ContinuationOptions& o, Direction* out) {
  out->end = BranchEnd::kLost;
  Node end;
  SpecialPoint sp;
  double back_step = 0.0;
  for (std::size_t i = 0; i < 4; ++i) back_step += a.t[i] * (a.y[i] - previous.y[i]);
  back_step = std::max(kBackFraction * std::abs(back_step), 10.0 * o.location_tolerance);
  if (!detail::LocateWallEnd(system, a, back_step, NAN, Wall::kNone, o.location_tolerance, &end,
                             &sp))
    return;
  if (end.y != a.y) out->nodes.push_back(std::move(end));
  sp.after_point = static_cast<int>(out->nodes.size()) - 1;
  out->special.push_back(std::move(sp));
  out->end = BranchEnd::kGrazing;
}

Direction Follow(detail::BranchSystem system, Node a, int budget, const ContinuationOptions& o) {
  Direction out;
  Node previous = a;
  detail::StepControl step(o, budget);
  while (static_cast<int>(out.nodes.size()) < budget && step.Attempt()) {
    Poll(o.interrupt);
    Node b;
    Vec4 beyond;
    Outcome r = Step(system, a, step.h(), o, &b, &beyond);
    bool end = false;
    if (r == Outcome::kOutOfRange) {
      const double edge = beyond[3] > o.to ? o.to : o.from;
      if (a.y[3] == edge) {  // already on the end
        out.end = BranchEnd::kRangeEnd;
        return out;
      }
      end = AtEnd(system, a, beyond, edge, &b);
      r = end ? Outcome::kConverged : Outcome::kFailed;
    }
    if (r != Outcome::kConverged) {
      if (!step.Failed()) {
        EndLost(system, previous, a, o, &out);
        return out;
      }
      continue;
    }
    if (Dot(a.half, b.half) < 0.0) {  // through the motion of half the period: retraced beyond
      out.end = BranchEnd::kHalfPeriod;
      return out;
    }
    const int k = static_cast<int>(out.nodes.size());
    const std::size_t before = out.special.size();
    detail::FindSpecialPoints(system, a, b, o.location_tolerance, &out.special);
    for (std::size_t i = before; i < out.special.size(); ++i) out.special[i].after_point = k;
    if (!detail::KeepPoint(system, std::move(b), end, step, &out.nodes, &out.end)) return out;
    previous = std::move(a);
    a = out.nodes.back();
  }
  out.end = BranchEnd::kMaxPoints;
  return out;
}

BranchPoint PointOf(const Node& n, double sign) {
  BranchPoint p;
  p.parameter = n.y[3];
  p.arclength = sign * n.s;
  p.tangent = sign * n.t[3];
  p.motion = n.motion;
  p.corrector_iterations = n.iterations;
  return p;
}

void AddLabel(BranchPoint& p, SpecialPointType type) {
  if (!p.label.empty()) p.label += ";";
  p.label += SpecialPointTypeName(type);
}

// The branch in increasing arclength: backward part reversed, start, forward part.
void Assemble(const Node& start, const Direction& backward, const Direction& forward, Branch& b) {
  const int nb = static_cast<int>(backward.nodes.size());
  for (int k = nb - 1; k >= 0; --k) {
    b.points.push_back(PointOf(backward.nodes[static_cast<std::size_t>(k)], -1.0));
  }
  b.start_index = nb;
  b.points.push_back(PointOf(start, 1.0));
  for (const Node& n : forward.nodes) b.points.push_back(PointOf(n, 1.0));
  for (auto it = backward.special.rbegin(); it != backward.special.rend(); ++it) {
    SpecialPoint sp = *it;
    sp.after_point = nb - 1 - it->after_point;
    sp.arclength = -sp.arclength;
    b.special_points.push_back(std::move(sp));
  }
  for (SpecialPoint sp : forward.special) {
    sp.after_point = nb + sp.after_point;
    b.special_points.push_back(std::move(sp));
  }
  for (const SpecialPoint& sp : b.special_points) {
    AddLabel(b.points[static_cast<std::size_t>(sp.after_point) + 1], sp.type);
  }
  b.backward_end = backward.end;
  b.forward_end = forward.end;
  b.backward_parameter = b.points.front().parameter;
  b.forward_parameter = b.points.back().parameter;
}

void CheckRobot(const RobotFamily& family, double lambda, const PhaseState& start) {
  const RobotModel r = family(lambda);
  r.params.Validate();
  ValidateStart(r.alpha, start);
}

}  // namespace

const char* SpecialPointTypeName(SpecialPointType type) {
  static constexpr const char* kNames[] = {"fold",    "period_doubling", "neimark_sacker",
                                           "grazing", "segment_change",  "speed_extremum"};
  static_assert(std::size(kNames) ==
                static_cast<std::size_t>(SpecialPointType::kSpeedExtremum) + 1);
  return detail::EnumName(kNames, type);
}

const char* BranchEndName(BranchEnd end) {
  static constexpr const char* kNames[] = {"not_run",      "range_end", "lost",       "max_points",
                                           "event_change", "grazing",   "half_period"};
  static_assert(std::size(kNames) == static_cast<std::size_t>(BranchEnd::kHalfPeriod) + 1);
  return detail::EnumName(kNames, end);
}

const char* WallName(Wall wall) {
  static constexpr const char* kNames[] = {"none", "right", "left"};
  static_assert(std::size(kNames) == static_cast<std::size_t>(Wall::kLeft) + 1);
  return detail::EnumName(kNames, wall);
}

const char* ContinuationStatusName(ContinuationStatus status) {
  static constexpr const char* kNames[] = {"not_run", "ok", "no_motion", "event_limit"};
  static_assert(std::size(kNames) == static_cast<std::size_t>(ContinuationStatus::kEventLimit) + 1);
  return detail::EnumName(kNames, status);
}

void ContinuationOptions::Validate() const {
  const auto fail = [](const char* name, double value, const std::string& rule) {
    throw std::invalid_argument(fmt::format("{} = {} is invalid: expected {}", name, value, rule));
  };
  if (!std::isfinite(from)) fail("from", from, "a finite number");
  if (!std::isfinite(to) || !(to > from))
    fail("to", to, fmt::format("a finite number > from = {}", from));
  if (!(start >= from && start <= to)) {
    fail("start", start, fmt::format("from = {} <= start <= to = {}", from, to));
  }
  if (max_points < 2 || max_points > kMaxPointsLimit) {
    fail("max_points", max_points, "2 <= max_points <= 100000");
  }
  if (!(min_step > 0.0) || !std::isfinite(min_step))
    fail("min_step", min_step, "a finite number > 0");
  if (!(max_step >= min_step) || !std::isfinite(max_step)) {
    fail("max_step", max_step, fmt::format("a finite number >= min_step = {}", min_step));
  }
  if (!(initial_step >= min_step && initial_step <= max_step)) {
    fail("initial_step", initial_step,
         fmt::format("min_step = {} <= initial_step <= max_step = {}", min_step, max_step));
  }
  if (!(residual_tolerance > 0.0) || !std::isfinite(residual_tolerance)) {
    fail("residual_tolerance", residual_tolerance, "a finite number > 0");
  }
  if (max_corrector_iterations < 1) {
    fail("max_corrector_iterations", max_corrector_iterations, ">= 1");
  }
  if (!(location_tolerance > 0.0) || !std::isfinite(location_tolerance)) {
    fail("location_tolerance", location_tolerance, "a finite number > 0");
  }
  shooting.Validate();
  RequireDifferencesInRange(shooting.step, "from", from, "to", to);
}

void RequireDifferencesInRange(double step, const char* lo_name, double lo, const char* hi_name,
                               double hi) {
  const double reach = 3.0 * step * std::max({1.0, std::abs(lo), std::abs(hi)});
  if (!(reach <= hi - lo)) {
    throw std::invalid_argument(
        fmt::format("step = {} is invalid: expected 3 step max(1, |{}|, |{}|) <= {} - {} = {} (the "
                    "finite differences in the parameter stay in its range)",
                    step, lo_name, hi_name, hi_name, lo_name, hi - lo));
  }
}

Branch ContinueBranch(const RobotFamily& family, const PhaseState& start,
                      const ContinuationOptions& options) {
  options.Validate();
  for (double lambda : {options.from, options.start, options.to}) CheckRobot(family, lambda, start);
  Branch branch;
  const RobotModel r = family(options.start);
  const PeriodicMotion pm = FindPeriodicMotion(r, start, options.shooting);
  if (pm.status != ShootingStatus::kConverged) {
    branch.status = pm.status == ShootingStatus::kEventLimit ? ContinuationStatus::kEventLimit
                                                             : ContinuationStatus::kNoMotion;
    branch.message = fmt::format("no periodic motion at the start: Newton shooting ended with {}",
                                 ShootingStatusName(pm.status));
    return branch;
  }
  detail::BranchSystem system(
      family, options, pm.period,
      {pm.state.psi, pm.mode, detail::FreeCoordinates(pm.mode, pm.state.v)});
  Node first;
  if (!system.Complete({pm.state.x, pm.state.u, pm.state.v, options.start}, {0.0, 0.0, 0.0, 1.0},
                       &first)) {
    branch.status = ContinuationStatus::kEventLimit;
    branch.message = "the simulation of the start hit the work bound";
    return branch;
  }
  const int forward_budget =
      options.both_directions ? options.max_points / 2 : options.max_points - 1;
  const Direction forward = Follow(system, first, forward_budget, options);
  Direction backward;
  backward.end = BranchEnd::kNotRun;
  if (options.both_directions) {
    Node reversed = first;
    for (double& t : reversed.t) t = -t;
    reversed.speed = -reversed.speed;
    const int left = options.max_points - 1 - static_cast<int>(forward.nodes.size());
    backward = Follow(system, reversed, left, options);
  }
  branch.status = ContinuationStatus::kOk;
  Assemble(first, backward, forward, branch);
  return branch;
}

}  // namespace capsubot
