// The end of a branch at a grazing, located by the flight's distance from the wall.

#include "continue/wall_end.hpp"

#include <algorithm>
#include <cmath>

#include "continue/wall_approach.hpp"

namespace capsubot::detail {
namespace {

// Search steps (each a correction): the secant on g converges in a few, the bisection that
// backs it up halves the bracket each time.
constexpr int kMaxSteps = 100;
// The secant's estimate of the grazing is probed this fraction of the tolerance beyond it, so
// that a probe past the grazing closes the bracket.
constexpr double kBeyond = 0.4;
// At the end the flight must touch the wall: |g| at the motion side of the bracket at most this
// times the slope of g over the bracket (else the motion ends there for another reason).
constexpr double kTouch = 2.0;

// a's motion (its events) at arclength sigma along a's tangent, predicted from `from` (at
// sigma_from); its grazing condition at the flight `w` into *g. False when there is none with
// a's events or its flight does not turn back before the wall.
bool MotionWithEvents(BranchSystem& system, const Node& a, const Node& from, double sigma_from,
                      double sigma, const WallApproach& w, Node* node, double* g) {
  Vec4 y = from.y;
  for (std::size_t i = 0; i < 4; ++i) y[i] += (sigma - sigma_from) * a.t[i];
  int iterations = 0;
  // The Jacobian of a alone: next to the wall the differences of a new one may reach it.
  if (system.Correct(Condition::Arclength(a.t, a.y, sigma), a.J, y, &iterations, true) !=
          BranchSystem::Outcome::kConverged ||
      !system.Measure(y, node) || !SameEvents(*node, a)) {
    return false;
  }
  return GrazingCondition(system.Robot(y[3]), system.State(y), w, system.motion(), g) && *g < 0.0;
}

}  // namespace

bool LocateWallEnd(BranchSystem& system, const Node& a, double back_step, double limit, Wall wall,
                   double tolerance, Node* end, SpecialPoint* sp) {
  const RobotModel robot = system.Robot(a.y[3]);
  WallApproach w;
  double g_lo = 0.0;
  if (!FindWallApproach(robot, system.State(a.y), system.period(), system.motion(), &w, wall) ||
      !GrazingCondition(robot, system.State(a.y), w, system.motion(), &g_lo) || !(g_lo < 0.0)) {
    return false;
  }
  // The bracket [lo, hi] in the arclength along a's tangent from a; g_back at `back` < lo.
  Node lo_node = a, m;
  double lo = 0.0, back = -back_step, g_back = 0.0, hi = limit, slope = NAN;
  if (!MotionWithEvents(system, a, a, 0.0, back, w, &m, &g_back)) return false;
  for (int k = 0; k < kMaxSteps && !(hi - lo <= tolerance); ++k) {
    slope = (g_lo - g_back) / (lo - back);
    double c = lo - g_lo / slope + kBeyond * tolerance;
    if (!(c > lo && (std::isnan(hi) || c < hi))) {
      if (std::isnan(hi)) return false;  // g does not rise towards the wall
      c = 0.5 * (lo + hi);
    }
    double g = 0.0;
    if (MotionWithEvents(system, a, lo_node, lo, c, w, &m, &g)) {
      back = lo;
      g_back = g_lo;
      lo = c;
      g_lo = g;
      lo_node = m;
    } else {
      hi = c;
    }
  }
  if (!(std::abs(g_lo) <= kTouch * slope * (hi - lo))) return false;
  if (lo_node.J.size() == 0 && !system.Complete(lo_node.y, a.t, &lo_node)) return false;
  *end = lo_node;
  end->s = a.s + lo;
  sp->type = SpecialPointType::kGrazing;
  sp->parameter = lo_node.y[3];
  // The bracket along the arclength (|d lambda/ds| <= 1: it bounds the parameter's), or the
  // distance to the root of g's secant if that lies beyond it.
  sp->accuracy = std::max(hi - lo, -g_lo / slope);
  sp->located = sp->accuracy <= tolerance;
  sp->wall = w.right ? Wall::kRight : Wall::kLeft;
  sp->motion = end->motion;
  sp->arclength = end->s;
  return true;
}

}  // namespace capsubot::detail
