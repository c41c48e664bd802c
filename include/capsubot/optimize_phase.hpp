#pragma once
// P1 of docs/model.md section 7: the impact phase phi0 that maximises the step I for a given force
// shape, over valid orbits (and, optionally, stable ones).

#include "capsubot/forcing.hpp"
#include "capsubot/optimize_result.hpp"
#include "capsubot/params.hpp"

namespace capsubot {

struct PhaseOptions {
  /// Points of the initial scan of the circle phi0 in [-pi, pi); at least 16. The valid set
  /// may be several disjoint arcs: an arc narrower than tau/scan_points can be missed.
  int scan_points = 720;
  /// Absolute tolerance [rad] on phi0 for the arc edges (bisection) and the polish inside arcs.
  double phase_tol = 1e-12;
  /// Require a stable orbit: spectral radius of the impact map (docs/model.md section 8) <= rho_max.
  bool stable = false;
  /// Largest admissible spectral radius when `stable`; 0 < rho_max (1: marginal stability).
  double rho_max = 1.0;
  /// A constraint is reported active when its slack is at most this (units of L for
  /// positions, of T0 for forces, plain for alpha and rho); >= 0.
  double active_tol = 1e-7;

  /// Throws std::invalid_argument naming the first bad field, its value and the rule.
  void Validate() const;
};

/// P1: the phi0 maximising I over valid orbits for this force shape (forcing.phi0() is
/// ignored; the result's forcing carries the optimal phi0). Scans the circle, brackets the
/// valid arcs, bisects their edges (validity flips) and polishes I inside each arc (Brent),
/// returning the best point; never worse than the best valid point of its scan.
/// Status kOk, or kNoValidOrbit with the point nearest to validity. Throws
/// std::invalid_argument for bad params or options. Uses params.margin as the clearance.
OptimizeResult OptimizePhase(const Forcing& forcing, const Params& params,
                             const PhaseOptions& options = {});

}  // namespace capsubot
