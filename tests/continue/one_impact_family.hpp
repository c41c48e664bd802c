#pragma once
// The robots of docs/continuation.md's example and their analytic one-impact orbits, shared by
// the continuation tests: the references are the analytic orbit (orbit.hpp), read at the impact
// phase of a continued motion found by the exact simulator, and root finders written here.

#include <cmath>
#include <functional>

#include "capsubot/continue/continuation.hpp"
#include "capsubot/orbit/orbit.hpp"
#include "test_utils.hpp"

namespace capsubot::testing {

// The stable one-impact orbit with clearance (docs/orbit.md, `solve --stability`): A = 0.05,
// c = 0.02, T0 = 0.1, e = 0.5, impact at motor phase -2.842.
constexpr double kA = 0.05, kC = 0.02, kPhi0 = -2.842;

inline Params OrbitParams() {
  Params p;
  p.T0 = 0.1;
  p.e = 0.5;
  return p;
}

// The orbit of the force with amplitude A and impact at motor phase phi0 (docs/model.md
// section 4).
inline Orbit OrbitAt(double A, double phi0) {
  return ComputeOrbit(Forcing::Harmonic(A, kC, phi0), OrbitParams());
}

// The state right after the impact at forcing phase psi = 0 of a robot whose motor phase is
// kPhi0: the orbit with impact phase phi0 is at psi = phi0 - kPhi0.
inline PhaseState AfterImpact(const Orbit& o, double phi0) {
  return {1.0, -o.e * o.u, o.v_plus, phi0 - kPhi0};
}

// The robot with mass ratio alpha and amplitude A (motor phase kPhi0).
inline RobotModel Robot(double alpha, double A = kA) {
  return {Forcing::Harmonic(A, kC, kPhi0), OrbitParams(), alpha};
}

// The motor phase of the first right-wall impact after the section of a periodic motion of
// robot r (the exact simulator: its event phase): the phi0 of the analytic orbit it is.
inline double ImpactPhase(const RobotModel& r, const PeriodicMotion& m) {
  struct FirstImpact : SimObserver {
    double phase = std::nan("");
    void OnEvent(const SimEvent& e) override {
      if (e.kind == EventKind::kImpactRight && std::isnan(phase)) phase = e.after.phi;
    }
  } observer;
  const SimOptions o = StartAt(r.alpha, m.state.x, m.state.u, m.state.v, 1.0);
  Simulate(r.forcing.WithPhase(r.forcing.phi0() + m.state.psi), r.params, o, &observer);
  return r.forcing.phi0() + m.state.psi + observer.phase;
}

inline ContinuationOptions Range(double from, double to, double start) {
  ContinuationOptions o;
  o.from = from;
  o.to = to;
  o.start = start;
  return o;
}

// The root of f in [lo, hi] (f(lo) f(hi) < 0) by bisection to the spacing of doubles.
inline double Bisect(const std::function<double(double)>& f, double lo, double hi) {
  const bool rising = f(hi) > 0.0;
  for (int i = 0; i < 200 && lo < hi; ++i) {
    const double mid = 0.5 * (lo + hi);
    if (mid == lo || mid == hi) break;
    ((f(mid) > 0.0) == rising ? hi : lo) = mid;
  }
  return 0.5 * (lo + hi);
}

// The largest mass ratio of the analytic family of amplitude A with impact phase in [lo, hi]
// (where alpha(phi0) rises, then falls): the root of the central difference of its slope
// (step 1e-5, error ~1e-10 in the slope; alpha is insensitive to the phase there).
inline double LargestMassRatio(double A, double lo, double hi) {
  const auto slope = [A](double phi0) {
    return (OrbitAt(A, phi0 + 1e-5).alpha - OrbitAt(A, phi0 - 1e-5).alpha) / 2e-5;
  };
  return OrbitAt(A, Bisect([&](double p) { return -slope(p); }, lo, hi)).alpha;
}

// The one-impact orbit of the robot with mass ratio alpha at amplitude A: Newton on
// alpha(phi0) = alpha from phi0.
inline double RobotOrbitPhase(double A, double alpha, double phi0) {
  for (int i = 0; i < 60; ++i) {
    const double f = OrbitAt(A, phi0).alpha - alpha;
    const double df = (OrbitAt(A, phi0 + 1e-7).alpha - OrbitAt(A, phi0 - 1e-7).alpha) / 2e-7;
    const double step = f / df;
    phi0 -= step;
    if (std::abs(step) < 1e-15) break;
  }
  return phi0;
}

// The stable orbit's branch in alpha over [0.2, 0.3] (docs/continuation.md's example): a period
// doubling at 0.2229, a speed extremum at 0.2399, a fold at 0.29035.
inline Branch AlphaBranch(double max_step) {
  const Orbit o = OrbitAt(kA, kPhi0);
  ContinuationOptions opt = Range(0.2, 0.3, o.alpha);
  opt.max_step = max_step;
  opt.initial_step = std::min(opt.initial_step, max_step);
  return ContinueBranch([](double alpha) { return Robot(alpha); }, AfterImpact(o, kPhi0), opt);
}

// The unstable one-impact orbit of the robot with kA (impact near motor phase 2.94, `capsubot
// orbits`) continued in A over [0.03, 0.079] towards larger A: it grazes the right wall at
// A = 0.0631462, where the analytic orbit's x_max = 1 (continuation_test.cpp).
inline Branch UnstableBranchInA() {
  const double alpha = OrbitAt(kA, kPhi0).alpha;
  const double phi_start = RobotOrbitPhase(kA, alpha, 2.9423);
  ContinuationOptions opt = Range(0.03, 0.079, kA);
  opt.both_directions = false;
  return ContinueBranch([alpha](double A) { return Robot(alpha, A); },
                        AfterImpact(OrbitAt(kA, phi_start), phi_start), opt);
}

// The robust gait of results/optimum.json (`capsubot optimize` at T0 = 1, e = 1, default
// margins): its force and the analytic one-impact orbit of docs/model.md section 4.
inline Orbit RobustGait() {
  Params p;
  p.T0 = 1.0;
  p.e = 1.0;
  return ComputeOrbit(
      Forcing::Harmonic(0.31611673290226067, 0.0623092212807503, -3.089378590956282), p);
}

// The first special point of the type on the branch (null if none).
inline const SpecialPoint* Find(const Branch& b, SpecialPointType type) {
  for (const SpecialPoint& s : b.special_points) {
    if (s.type == type) return &s;
  }
  return nullptr;
}

}  // namespace capsubot::testing
