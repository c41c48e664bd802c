#pragma once
// Internals of the design's search shared with its tests: a robot's gait together with how far
// it is from having one (the feasibility measure that the window search brackets), and the
// windows of inner mass that the search brackets at one frequency (docs/design.md, "How the
// search works").

#include <vector>

#include "capsubot/design/design.hpp"

namespace capsubot::detail {

/// EvaluateGait, and when slack is not null the robot's feasibility measure in *slack: the
/// largest over its orbits of the smallest slack of the limits of a robust gait (x_min -
/// clearance, 1 - clearance - x_max, the stick margin and the force bound in units of T0,
/// rho_max - spectral radius, and for e = 0 the separation -x''(0+)), >= 0 when the robot has
/// a gait and <= 0 when it has not; -infinity without an orbit (or when the motor slides the
/// shell). Between the masses where a robot's orbit count changes (folds of alpha(phi0)) it
/// is continuous.
Gait EvaluateGait(const DesignInput& input, double m2, double frequency, double* slack);

/// A window of inner masses [kg] with a robust gait, as the search brackets it: the first and
/// last robots of the window it evaluated (feasible) and the robots next to them (infeasible,
/// or the ends of the range when the window reaches them).
struct M2Window {
  double outer_lo = 0.0;  ///< infeasible robot below the window, or M2Min
  double inner_lo = 0.0;  ///< first feasible robot evaluated
  double inner_hi = 0.0;  ///< last feasible robot evaluated
  double outer_hi = 0.0;  ///< infeasible robot above the window, or M2Max
};

/// The m2 search of Design at the frequency f: its fastest gait, and in *windows (if not null)
/// every window it bracketed, by m2.
Gait BestOverM2(const DesignInput& input, double frequency, std::vector<M2Window>* windows);

}  // namespace capsubot::detail
