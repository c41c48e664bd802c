// Two-parameter curves of special points: the start on a branch's special point, the steps
// along the curve and its ends (docs/continuation.md, "Two-parameter curves").

#include "capsubot/continue/special_curve.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "continue/curve_system.hpp"
#include "continue/walk.hpp"

namespace capsubot {
namespace {

// As for a branch (continuation.cpp): consecutive tangents must agree to kMinTangentCosine; the
// step and the corrector's tolerances are the walk's (walk.hpp).
constexpr double kMinTangentCosine = 0.5;
// A grazing is followed from the side where the flight turns back before the wall: at the
// branch's grazing that flight comes this close to the wall (the location tolerance moves it
// by far less), while seen from the side with the new impact none does.
constexpr double kTouching = 1e-6;

constexpr SpecialPointType kFollowable[] = {
    SpecialPointType::kFold, SpecialPointType::kPeriodDoubling, SpecialPointType::kGrazing,
    SpecialPointType::kSpeedExtremum};

using detail::CurveClosure;
using detail::CurveNode;
using detail::CurveSystem;
using detail::Vec5;
using Outcome = CurveSystem::Outcome;

double Dot(const Vec5& a, const Vec5& b) {
  double s = 0.0;
  for (std::size_t i = 0; i < 5; ++i) s += a[i] * b[i];
  return s;
}

bool SameEvents(const CurveNode& a, const CurveNode& b) {
  return a.motion.impacts_right == b.motion.impacts_right &&
         a.motion.impacts_left == b.motion.impacts_left && a.marks == b.marks;
}

// One direction of the curve from the start.
struct CurveDirection {
  std::vector<CurveNode> nodes;  // in the order found, the start excluded
  BranchEnd end = BranchEnd::kMaxPoints;
};

enum class StepResult { kAccepted, kRejected, kEventChange, kOutOfRange };

// The point found from a by a step h along its tangent. kOutOfRange: the predictor or an
// iterate of the corrector left the box (*beyond is that point).
StepResult Advance(CurveSystem& system, const CurveNode& a, double h, CurveNode* b, Vec5* beyond) {
  Vec5 y;
  for (std::size_t i = 0; i < 5; ++i) y[i] = a.y[i] + h * a.t[i];
  const Vec5 predicted = y;
  *beyond = y;
  if (!system.InBox(y)) return StepResult::kOutOfRange;
  int iterations = 0;
  const Outcome r = system.Correct(CurveClosure::Arclength(a.t, a.y, h), a.J, y, &iterations);
  *beyond = y;
  if (r == Outcome::kOutOfRange) return StepResult::kOutOfRange;
  if (r != Outcome::kConverged || !system.Complete(y, a.t, b)) return StepResult::kRejected;
  double moved = 0.0;
  for (std::size_t i = 0; i < 5; ++i) moved = std::max(moved, std::abs(y[i] - predicted[i]));
  b->iterations = iterations;
  b->s = a.s + h;
  if (!SameEvents(a, *b)) return StepResult::kEventChange;
  return Dot(a.t, b->t) >= kMinTangentCosine && moved <= h ? StepResult::kAccepted
                                                           : StepResult::kRejected;
}

// The point on the edge of the box that a step from a towards `beyond` crossed first: the
// corrector with that parameter fixed at the edge, from the chord. False when a already lies
// on that edge (*on_edge) or the corrector fails there.
bool AtEdge(CurveSystem& system, const CurveOptions& o, const CurveNode& a, const Vec5& beyond,
            CurveNode* b, bool* on_edge) {
  std::size_t index = 3;
  double edge = 0.0, fraction = 2.0;
  for (std::size_t k : {std::size_t{3}, std::size_t{4}}) {
    const double lo = k == 3 ? o.continuation.from : o.from2;
    const double hi = k == 3 ? o.continuation.to : o.to2;
    if (beyond[k] >= lo && beyond[k] <= hi) continue;
    const double e = beyond[k] > hi ? hi : lo;
    const double f = beyond[k] == a.y[k] ? 0.0 : (e - a.y[k]) / (beyond[k] - a.y[k]);
    if (f < fraction) {
      fraction = f;
      index = k;
      edge = e;
    }
  }
  *on_edge = a.y[index] == edge;
  if (*on_edge || fraction > 1.0) return false;
  Vec5 y;
  for (std::size_t i = 0; i < 5; ++i) y[i] = a.y[i] + fraction * (beyond[i] - a.y[i]);
  y[index] = edge;
  int iterations = 0;
  if (system.Correct(CurveClosure::Fixed(index, edge), a.J, y, &iterations) !=
          Outcome::kConverged ||
      !system.Complete(y, a.t, b) || !SameEvents(a, *b)) {
    return false;
  }
  Vec5 d;
  for (std::size_t i = 0; i < 5; ++i) d[i] = y[i] - a.y[i];
  b->iterations = iterations;
  b->s = a.s + Dot(a.t, d);
  return true;
}

CurveDirection Follow(CurveSystem system, CurveNode a, int budget, const CurveOptions& options) {
  const ContinuationOptions& o = options.continuation;
  CurveDirection out;
  detail::StepControl step(o, budget);
  while (static_cast<int>(out.nodes.size()) < budget && step.Attempt()) {
    Poll(o.interrupt);
    CurveNode b;
    Vec5 beyond;
    StepResult r = Advance(system, a, step.h(), &b, &beyond);
    bool end = false;
    if (r == StepResult::kOutOfRange) {
      bool on_edge = false;
      end = AtEdge(system, options, a, beyond, &b, &on_edge);
      if (on_edge) {
        out.end = BranchEnd::kRangeEnd;
        return out;
      }
      r = end ? StepResult::kAccepted : StepResult::kRejected;
    }
    if (r != StepResult::kAccepted) {
      if (!step.Failed()) {
        out.end = r == StepResult::kEventChange ? BranchEnd::kEventChange : BranchEnd::kLost;
        return out;
      }
      continue;
    }
    if (!detail::KeepPoint(system, std::move(b), end, step, &out.nodes, &out.end)) return out;
    a = out.nodes.back();
  }
  out.end = BranchEnd::kMaxPoints;
  return out;
}

CurvePoint PointOf(const CurveNode& n, double sign) {
  CurvePoint p;
  p.parameter = n.y[3];
  p.parameter2 = n.y[4];
  p.arclength = sign * n.s;
  p.condition = n.condition;
  p.motion = n.motion;
  return p;
}

// The curve in increasing arclength: backward part reversed, start, forward part.
void Assemble(const CurveNode& start, const CurveDirection& backward, const CurveDirection& forward,
              Curve& c) {
  for (auto it = backward.nodes.rbegin(); it != backward.nodes.rend(); ++it) {
    c.points.push_back(PointOf(*it, -1.0));
  }
  c.start_index = static_cast<int>(backward.nodes.size());
  c.points.push_back(PointOf(start, 1.0));
  for (const CurveNode& n : forward.nodes) c.points.push_back(PointOf(n, 1.0));
  c.backward_end = backward.end;
  c.forward_end = forward.end;
}

Curve NoCurve(const Curve& base, ContinuationStatus status, std::string message) {
  Curve c = base;
  c.status = status;
  c.message = std::move(message);
  return c;
}

// The first point of the curve: the extended system solved at mu = start2 from the special
// point's motion, oriented towards increasing mu. False when it does not converge.
bool StartNode(CurveSystem& system, const SpecialPoint& sp, double start2, CurveNode* first) {
  const PhaseState& z = sp.motion.state;
  Vec5 y = {z.x, z.u, z.v, sp.parameter, start2};
  const Vec5 up = {0.0, 0.0, 0.0, 0.0, 1.0};
  CurveNode guess;
  int iterations = 0;
  return system.Complete(y, up, &guess) &&
         system.Correct(CurveClosure::Fixed(4, start2), guess.J, y, &iterations) ==
             Outcome::kConverged &&
         system.Complete(y, up, first);
}

}  // namespace

bool IsFollowable(SpecialPointType type) {
  return std::find(std::begin(kFollowable), std::end(kFollowable), type) != std::end(kFollowable);
}

SpecialPointType ParseFollowType(const std::string& name) {
  for (SpecialPointType type : kFollowable) {
    if (name == SpecialPointTypeName(type)) return type;
  }
  throw std::invalid_argument(fmt::format(
      "follow = {} is invalid: expected one of fold, period_doubling, grazing, speed_extremum",
      name));
}

void CurveOptions::Validate() const {
  if (!std::isfinite(from2)) {
    throw std::invalid_argument(
        fmt::format("from2 = {} is invalid: expected a finite number", from2));
  }
  if (!std::isfinite(to2) || !(to2 > from2)) {
    throw std::invalid_argument(
        fmt::format("to2 = {} is invalid: expected a finite number > from2 = {}", to2, from2));
  }
  if (!(start2 >= from2 && start2 <= to2)) {
    throw std::invalid_argument(fmt::format(
        "start2 = {} is invalid: expected from2 = {} <= start2 <= to2 = {}", start2, from2, to2));
  }
  ContinuationOptions range = continuation;  // its own rules; the start is the special point's
  range.start = range.from;
  range.Validate();
  RequireDifferencesInRange(continuation.shooting.step, "from2", from2, "to2", to2);
}

Curve FollowSpecialPoint(const RobotSurface& surface, const SpecialPoint& sp,
                         const CurveOptions& options) {
  if (!IsFollowable(sp.type) || !sp.located) {
    throw std::invalid_argument(
        fmt::format("special point type = {} (located = {}) is invalid: expected a located fold, "
                    "period_doubling, grazing or speed_extremum",
                    SpecialPointTypeName(sp.type), sp.located));
  }
  options.Validate();
  const ContinuationOptions& o = options.continuation;
  if (!(sp.parameter >= o.from && sp.parameter <= o.to)) {
    throw std::invalid_argument(
        fmt::format("special point parameter = {} is invalid: expected from = {} <= it <= to = {}",
                    sp.parameter, o.from, o.to));
  }
  for (double lambda : {o.from, o.to}) {
    for (double mu : {options.from2, options.to2}) surface(lambda, mu).params.Validate();
  }
  Curve curve;
  curve.type = sp.type;
  const PhaseState& z = sp.motion.state;
  CurveSystem system(surface, options, sp.type, sp.motion.period,
                     {z.psi, sp.motion.mode, detail::FreeCoordinates(sp.motion.mode, z.v)});
  const Vec5 y = {z.x, z.u, z.v, sp.parameter, options.start2};
  if (sp.type == SpecialPointType::kGrazing &&
      !(system.Approach(y) && system.approach().distance <= kTouching)) {
    return NoCurve(curve, ContinuationStatus::kNoMotion,
                   "no free flight of the motion at the grazing touches a wall: it is the side "
                   "with the new impact, follow the grazing from the other side");
  }
  CurveNode first;
  if (system.dimension() == 0 || !StartNode(system, sp, options.start2, &first)) {
    return NoCurve(curve, ContinuationStatus::kNoMotion,
                   fmt::format("the extended system of the {} found no solution next to the "
                               "special point",
                               SpecialPointTypeName(sp.type)));
  }
  const int forward_budget = o.max_points / 2;
  const CurveDirection forward = Follow(system, first, forward_budget, options);
  CurveNode reversed = first;
  for (double& t : reversed.t) t = -t;
  const int left = o.max_points - 1 - static_cast<int>(forward.nodes.size());
  const CurveDirection backward = Follow(system, reversed, left, options);
  curve.status = ContinuationStatus::kOk;
  Assemble(first, backward, forward, curve);
  return curve;
}

}  // namespace capsubot
