#pragma once
// Results of the optimiser built by hand for the tests of its reports: round numbers, so that
// each number a report prints is known.

#include <cmath>
#include <string>

#include "capsubot/optimize/optimize_result.hpp"
#include "capsubot/reach/optimize_reach.hpp"

namespace capsubot::testing {

/// A valid gait of the sine A sin(phi + phi0) + c moving I per period with mass ratio alpha.
inline OptimizeResult HandMadeGait(double A, double c, double I, double alpha) {
  OptimizeResult r;
  r.status = OptimizeStatus::kOk;
  r.message = "hand-made gait";
  Orbit& o = r.solution.orbit;
  o.forcing = Forcing::Harmonic(A, c, -2.5);
  o.T0 = 0.8;
  o.e = 1.0;
  o.status = OrbitStatus::kOk;
  o.phi1 = 1.5;
  o.alpha = alpha;
  o.u = 0.75;
  o.v_plus = 0.125;
  o.I = I;
  o.v_mean = I / kTau;
  r.solution.validity.checked = true;
  r.solution.validity.x_min = 0.25;
  r.spectral_radius = 0.5;
  r.evaluations = 100;
  r.algorithm = "hand";
  return r;
}

/// A winner of the reach search with mean velocity `v` from rest over 64 starts, 48 of them on
/// its most common motion.
inline ReachResult HandMadeReach(double v) {
  ReachResult r;
  r.status = OptimizeStatus::kOk;
  r.message = "hand-made reach";
  r.forcing = Forcing::Harmonic(0.5, 0.25, -2.0);
  r.alpha = 0.25;
  r.mean_velocity = v;
  r.attractors.starts = 64;
  Attractor top;
  top.motion.status = MotionStatus::kPeriodic;
  top.motion.period = 1;
  top.motion.impacts_right = 1;
  top.starts = 48;
  top.fraction = 0.75;
  top.motion.mean_velocity = top.mean_velocity = v;  // periodic: every start the same
  r.attractors.attractors.push_back(top);
  r.attractors.mean_velocity = v;
  r.summary = "64 starts: 48 end in the most common motion";
  r.robust_to_settings = true;
  r.force_bound = 0.8;
  r.max_abs_force = 0.75;
  r.algorithm = "hand";
  return r;
}

}  // namespace capsubot::testing
