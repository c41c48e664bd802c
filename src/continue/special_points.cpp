// Detection and location of the special points of a branch (docs/continuation.md).

#include "continue/special_points.hpp"

#include <algorithm>
#include <cmath>
#include <functional>

#include "continue/wall_end.hpp"

namespace capsubot::detail {
namespace {

// Searches stop after this many corrections (the bracket halves at least every other step, so a
// step of the branch is narrowed to far below any tolerance long before).
constexpr int kMaxLocationSteps = 100;
// A Neimark-Sacker point needs a complex pair there: imaginary parts above this.
constexpr double kComplexPair = 1e-6;
// A located fold, period doubling or Neimark-Sacker point must have a multiplier this close to
// +1, -1 or the unit circle: a test function can also change sign where the central differences
// straddle a grazing or the branch has a corner (the map is not smooth there), which is no
// bifurcation of a smooth branch.
constexpr double kOnCircle = 1e-5;
// ... and keep it, within this, when the motion is shot anew with the finite-difference step
// 10 times larger and 10 times smaller: the multipliers of a smooth map move by the square of
// the step, those of differences that straddle a grazing by far more.
constexpr double kOnCircleAtOtherSteps = 1e-3;
constexpr double kStepFactor = 10.0;
// A speed extremum needs d mean velocity / ds to change sign significantly: at one point at
// least its modulus exceeds this times the mean velocity's scale max(|V_a|, |V_b|, floor) (the
// central differences of the displacement carry its rounding over the step, about 1e-10 of
// it; a branch of constant speed, as in phi0, has speeds of that size and random sign at every
// point, while an extremum that lies on a point has a significant one next to it)...
constexpr double kSpeedNoise = 1e-8;
constexpr double kSpeedFloor = 1e-12;
// Changes of the events are bracketed with the parameter fixed when the tangent's parameter
// component is at least this (else along the arclength).
constexpr double kParameterProbe = 0.1;
// A grazing between two points is located by its flight's distance from the wall, the slope of
// that distance first taken this fraction of the step back from the point.
constexpr double kGrazingBackStep = 0.1;

// The point of the branch at arclength sigma past a along a's tangent (the corrector closed by
// t_a . (y - y_a) = sigma, from the chord between a and b); `complete` adds the Jacobian,
// tangent and multipliers, else only the impacts and events.
bool PointAt(SmoothSystem& system, const Node& a, const Node& b, double sigma_b, double sigma,
             bool complete, Node* node) {
  Vec4 y;
  for (std::size_t i = 0; i < 4; ++i) y[i] = a.y[i] + (sigma / sigma_b) * (b.y[i] - a.y[i]);
  int iterations = 0;
  if (system.Correct(Condition::Arclength(a.t, a.y, sigma), a.J, y, &iterations) !=
      SmoothSystem::Outcome::kConverged) {
    return false;
  }
  node->s = a.s + sigma;
  return complete ? system.Complete(y, a.t, node) : system.Measure(y, node);
}

double Sigma(const Node& a, const Node& b) {
  double s = 0.0;
  for (std::size_t i = 0; i < 4; ++i) s += a.t[i] * (b.y[i] - a.y[i]);
  return s;
}

// The motion of a at the parameter lambda_a + sigma t_lambda (the corrector with the
// parameter fixed, predicted from `near`, a point of a's motion at sigma_near): only its
// impacts and events.
bool MotionAt(SmoothSystem& system, const Node& a, const Node& near, double sigma_near,
              double sigma, Node* node) {
  Vec4 y;
  for (std::size_t i = 0; i < 4; ++i) y[i] = near.y[i] + (sigma - sigma_near) * a.t[i];
  y[3] = a.y[3] + sigma * a.t[3];
  int iterations = 0;
  return system.Correct(Condition::Fixed(3, y[3]), a.J, y, &iterations) ==
             SmoothSystem::Outcome::kConverged &&
         system.Measure(y, node);
}

// The wall whose impacts per period differ between a and b (kNone when neither's do).
Wall ChangedWall(const Node& a, const Node& b) {
  if (a.motion.impacts_right != b.motion.impacts_right) return Wall::kRight;
  if (a.motion.impacts_left != b.motion.impacts_left) return Wall::kLeft;
  return Wall::kNone;
}

// Bisection on "a's motion exists there with a's events" along a's tangent towards b. The
// search fixes the parameter at each probe, so it finds where a's motion ends even when the
// other side's motion lies on a branch that turns back at the change (a grazing impact often
// makes such a corner); near a fold of a's branch (tangent almost normal to the parameter) the
// arclength condition is used instead.
SpecialPoint LocateChange(SmoothSystem& system, const Node& a, const Node& b, double tolerance) {
  SpecialPoint sp;
  sp.wall = ChangedWall(a, b);
  sp.type = sp.wall != Wall::kNone ? SpecialPointType::kGrazing : SpecialPointType::kSegmentChange;
  const double sigma_b = Sigma(a, b);
  const bool by_parameter = std::abs(a.t[3]) >= kParameterProbe;
  double lo = 0.0, hi = sigma_b, lambda_lo = a.y[3], lambda_hi = b.y[3];
  Node last = a;
  for (int k = 0; k < kMaxLocationSteps && std::abs(lambda_hi - lambda_lo) > tolerance; ++k) {
    const double mid = 0.5 * (lo + hi);
    Node m;
    const bool found = by_parameter ? MotionAt(system, a, last, lo, mid, &m)
                                    : PointAt(system, a, b, sigma_b, mid, false, &m);
    if (found && SameEvents(m, a)) {
      lo = mid;
      lambda_lo = m.y[3];
      last = m;
    } else {
      hi = mid;
      lambda_hi = found ? m.y[3] : a.y[3] + mid * a.t[3];
    }
  }
  sp.parameter = lambda_lo;
  sp.accuracy = std::abs(lambda_hi - lambda_lo);
  sp.located = sp.accuracy <= tolerance;
  if (last.J.size() == 0) system.Complete(last.y, a.t, &last);  // a point of the search
  sp.motion = last.motion;
  sp.arclength = a.s + lo;
  return sp;
}

// Regula falsi (Illinois) on the test function f between a and b.
SpecialPoint LocateRoot(SmoothSystem& system, const Node& a, const Node& b, SpecialPointType type,
                        const std::function<double(const Node&)>& f, double tolerance) {
  SpecialPoint sp;
  sp.type = type;
  const double sigma_b = Sigma(a, b);
  double lo = 0.0, hi = sigma_b, flo = f(a), fhi = f(b);
  double previous = hi, sigma = hi;
  int side = 0;
  Node best = b;
  double change = hi - lo;
  for (int k = 0; k < kMaxLocationSteps && hi - lo > tolerance && change > 0.25 * tolerance; ++k) {
    sigma = (lo * fhi - hi * flo) / (fhi - flo);
    if (!(sigma > lo && sigma < hi)) sigma = 0.5 * (lo + hi);
    Node m;
    if (!PointAt(system, a, b, sigma_b, sigma, true, &m)) break;
    best = m;
    change = std::abs(sigma - previous);
    previous = sigma;
    const double fm = f(m);
    if (fm == 0.0) {
      change = 0.0;
      break;
    }
    if ((fm < 0.0) == (flo < 0.0)) {
      lo = sigma;
      flo = fm;
      if (side == -1) fhi *= 0.5;
      side = -1;
    } else {
      hi = sigma;
      fhi = fm;
      if (side == +1) flo *= 0.5;
      side = +1;
    }
  }
  sp.parameter = best.y[3];
  sp.accuracy = std::min(hi - lo, 4.0 * change);
  sp.located = sp.accuracy <= tolerance;
  sp.motion = best.motion;
  sp.arclength = best.s;
  return sp;
}

// Whether `m` has the multiplier of a `type` point, within `tolerance`.
bool HasCriticalMultiplier(SpecialPointType type, const PeriodicMotion& m, double tolerance) {
  for (const auto& mu : m.multipliers) {
    if (type == SpecialPointType::kFold && std::abs(mu - 1.0) <= tolerance) return true;
    if (type == SpecialPointType::kPeriodDoubling && std::abs(mu + 1.0) <= tolerance) return true;
    if (type == SpecialPointType::kNeimarkSacker && std::abs(mu.imag()) > kComplexPair &&
        std::abs(std::abs(mu) - 1.0) <= tolerance) {
      return true;
    }
  }
  return false;
}

// ... and the same sign at each significant point when the Jacobian's finite-difference step
// is 10 times larger and 10 times smaller (a difference that straddles an event gives a speed
// that moves with the step).
bool SpeedChangesSign(SmoothSystem& system, const Node& a, const Node& b) {
  const double scale =
      std::max({std::abs(a.motion.mean_velocity), std::abs(b.motion.mean_velocity), kSpeedFloor});
  const auto significant = [&](const Node& n) { return std::abs(n.speed) > kSpeedNoise * scale; };
  if (!significant(a) && !significant(b)) return false;
  for (const double factor : {kStepFactor, 1.0 / kStepFactor}) {
    for (const Node* n : {&a, &b}) {
      if (significant(*n) && !(system.SpeedWithStep(*n, factor) * n->speed > 0.0)) return false;
    }
  }
  return true;
}

// The located point is the bifurcation its test function announced, whatever the step of the
// finite differences.
bool Confirmed(const SmoothSystem& system, const SpecialPoint& sp) {
  if (sp.type == SpecialPointType::kSpeedExtremum) return true;
  if (!HasCriticalMultiplier(sp.type, sp.motion, kOnCircle)) return false;
  for (const double factor : {kStepFactor, 1.0 / kStepFactor}) {
    const PeriodicMotion m = system.Reshoot(sp.parameter, sp.motion.state, factor);
    if (m.status != ShootingStatus::kConverged ||
        !HasCriticalMultiplier(sp.type, m, kOnCircleAtOtherSteps)) {
      return false;
    }
  }
  return true;
}

}  // namespace

// A grazing between a and b located by the flight that reaches the wall: from a's side (its
// motion ends there) or else from b's (the motion that begins there, followed back). False
// when neither side's flight touches a wall between them.
bool LocateGrazing(BranchSystem& system, const Node& a, const Node& b, double tolerance,
                   SpecialPoint* sp) {
  const Wall wall = ChangedWall(a, b);
  const double sigma_b = Sigma(a, b);
  const double back_step = kGrazingBackStep * std::abs(sigma_b);
  Node end;
  if (LocateWallEnd(system, a, back_step, sigma_b, wall, tolerance, &end, sp)) return true;
  Node reversed = b;
  for (double& t : reversed.t) t = -t;
  if (!LocateWallEnd(system, reversed, back_step, -Sigma(b, a), wall, tolerance, &end, sp)) {
    return false;
  }
  sp->arclength = a.s + Sigma(a, end);
  return true;
}

void FindSpecialPoints(SmoothSystem& system, const Node& a, const Node& b, double tolerance,
                       std::vector<SpecialPoint>* out) {
  if (!SameEvents(a, b)) {
    SpecialPoint sp;
    // Only the capsule's period map has walls to graze.
    auto* capsule = dynamic_cast<BranchSystem*>(&system);
    if (capsule == nullptr || !LocateGrazing(*capsule, a, b, tolerance, &sp)) {
      sp = LocateChange(system, a, b, tolerance);
    }
    out->push_back(std::move(sp));
    return;
  }
  const std::size_t before = out->size();
  struct Test {
    SpecialPointType type;
    std::function<double(const Node&)> f;
  };
  const Test tests[] = {
      {SpecialPointType::kFold, [](const Node& n) { return n.t[3]; }},
      {SpecialPointType::kPeriodDoubling, [](const Node& n) { return n.period_doubling; }},
      {SpecialPointType::kNeimarkSacker, [](const Node& n) { return n.neimark_sacker; }},
      {SpecialPointType::kSpeedExtremum, [](const Node& n) { return n.speed; }},
  };
  for (const Test& test : tests) {
    const double fa = test.f(a), fb = test.f(b);
    if (!(fa * fb < 0.0)) continue;
    if (test.type == SpecialPointType::kSpeedExtremum && !SpeedChangesSign(system, a, b)) continue;
    SpecialPoint sp = LocateRoot(system, a, b, test.type, test.f, tolerance);
    // A real pair with product 1 (a neutral saddle) also changes the sign of the
    // Neimark-Sacker function: only a complex pair on the circle is one.
    if (!Confirmed(system, sp)) continue;
    out->push_back(std::move(sp));
  }
  std::stable_sort(
      out->begin() + static_cast<std::ptrdiff_t>(before), out->end(),
      [](const SpecialPoint& x, const SpecialPoint& y) { return x.arclength < y.arclength; });
}

}  // namespace capsubot::detail
