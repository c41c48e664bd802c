// The grazing condition: the extremum of x of a free flight, continued past the wall in closed
// form (docs/continuation.md, docs/model.md section 3).

#include "continue/wall_approach.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

namespace capsubot::detail {
namespace {

// Samples of u per flight when the extrema are looked for, and bisection steps on a bracket of
// u = 0 (each halves it: 60 reach the spacing of doubles from any flight).
constexpr int kSamples = 64;
constexpr int kBisections = 60;
// Newton on u(q) = 0 near a known extremum: iterations and the step at which it has converged
// (x is stationary there, so the phase's error enters x squared).
constexpr int kNewtonIterations = 30;
constexpr double kPhaseTolerance = 1e-13;

bool FreeFlight(SimMode mode) {
  return mode == SimMode::kRest || mode == SimMode::kSlideForward ||
         mode == SimMode::kSlideBackward;
}

// The closed-form relative motion of one mode from (x0, u0) at phase q0, the force seen from
// the section (docs/model.md section 3: u' = kx (F + b)).
class Flight {
 public:
  Flight(const RobotModel& r, double section_psi, SimMode mode, double q0, double x0, double u0)
      : force_(r.forcing.WithPhase(r.forcing.phi0() + section_psi)), q0_(q0), x0_(x0), u0_(u0) {
    const double alpha = r.alpha, T0 = r.params.T0;
    kx_ = mode == SimMode::kRest ? 1.0 / alpha : 1.0 / (alpha * (1.0 - alpha));
    b_ = mode == SimMode::kSlideForward    ? alpha * T0
         : mode == SimMode::kSlideBackward ? -alpha * T0
                                           : 0.0;
    at0_ = force_.Values(q0);
  }
  double U(double q) const {
    const ForceValues f = force_.Values(q);
    return u0_ + kx_ * (f.Pi - at0_.Pi + b_ * (q - q0_));
  }
  double X(double q) const {
    const ForceValues f = force_.Values(q);
    const double d = q - q0_;
    return x0_ + u0_ * d + kx_ * (f.Phi - at0_.Phi - at0_.Pi * d + 0.5 * b_ * d * d);
  }
  double dU(double q) const { return kx_ * (force_.Values(q).F + b_); }

 private:
  Forcing force_;
  double q0_, x0_, u0_, kx_ = 0.0, b_ = 0.0;
  ForceValues at0_;
};

// Collects the events of a run with their phases since its start.
struct EventLog : SimObserver {
  std::vector<SimEvent> events;
  void OnEvent(const SimEvent& e) override { events.push_back(e); }
};

// The root of u in [lo, hi] (u changes sign there) by bisection.
double Root(const Flight& f, double lo, double hi) {
  const bool rising = f.U(hi) > 0.0;
  for (int i = 0; i < kBisections; ++i) {
    const double mid = 0.5 * (lo + hi);
    ((f.U(mid) > 0.0) == rising ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

// The extrema of x of the flight over [start, end] that turn back from a wall, into *best when
// nearer to its wall than *best.
void ScanFlight(const Flight& f, SimMode mode, double start, double end, Wall only,
                WallApproach* best) {
  double q_prev = start, u_prev = f.U(start);
  for (int k = 1; k <= kSamples; ++k) {
    const double q = start + (end - start) * k / kSamples;
    const double u = f.U(q);
    const bool right = u_prev > 0.0;  // u falls through 0: a maximum of x
    if ((u_prev > 0.0) != (u > 0.0) && (only == Wall::kNone || right == (only == Wall::kRight))) {
      const double phase = Root(f, q_prev, q);
      const double x = f.X(phase);
      const double distance = right ? 1.0 - x : x;
      if (distance >= 0.0 && distance < best->distance) {
        *best = {right, mode, start, phase, distance};
      }
    }
    q_prev = q;
    u_prev = u;
  }
}

}  // namespace

bool FindWallApproach(const RobotModel& robot, const PhaseState& z, int p,
                      const MotionOptions& motion, WallApproach* approach, Wall only) {
  const PeriodMap map(robot, motion);
  MapState s{z, SimMode::kRest};
  EventLog log;
  if (!map.Shift(s, p, &log)) return false;
  // The flights: from the section to the first event is the end of the flight after the last
  // one, p periods earlier.
  const double span = p * kTau;
  WallApproach best;
  best.distance = HUGE_VAL;
  const std::size_t n = log.events.size();
  for (std::size_t i = 0; i < n; ++i) {
    const SimState& a = log.events[i].after;
    if (!FreeFlight(a.mode)) continue;
    const double end = i + 1 < n ? log.events[i + 1].after.phi : log.events[0].after.phi + span;
    ScanFlight(Flight(robot, z.psi, a.mode, a.phi, a.x, a.u), a.mode, a.phi, end, only, &best);
  }
  if (n == 0 && FreeFlight(s.mode)) {
    ScanFlight(Flight(robot, z.psi, s.mode, 0.0, z.x, z.u), s.mode, 0.0, span, only, &best);
  }
  if (!std::isfinite(best.distance)) return false;
  *approach = best;
  return true;
}

bool GrazingCondition(const RobotModel& robot, const PhaseState& z, const WallApproach& approach,
                      const MotionOptions& motion, double* g) {
  const PeriodMap map(robot, motion);
  const double q0 = 0.5 * (approach.start + approach.phase);
  MapState s{z, SimMode::kRest};
  if (!map.Shift(s, q0 / kTau) || s.mode != approach.mode) return false;
  const Flight f(robot, z.psi, approach.mode, q0, s.z.x, s.z.u);
  // Newton on u(q) = 0 from the known extremum, its steps bounded by the distance from q0.
  const double reach = approach.phase - q0;
  double q = approach.phase;
  for (int i = 0; i < kNewtonIterations; ++i) {
    const double slope = f.dU(q);
    if (slope == 0.0) return false;
    const double step = std::clamp(-f.U(q) / slope, -reach, reach);
    q += step;
    if (std::abs(step) <= kPhaseTolerance * std::max(1.0, std::abs(q))) {
      const double x = f.X(q);
      *g = approach.right ? x - 1.0 : -x;
      return q > q0;
    }
  }
  return false;
}

}  // namespace capsubot::detail
