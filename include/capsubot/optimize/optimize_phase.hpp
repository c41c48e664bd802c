#pragma once
// P1 of docs/model.md section 7: the impact phase phi0 that maximises the step I for a given force
// shape, over valid orbits (with the margins of its options, section 12, and optionally a bound on
// the spectral radius).

#include "capsubot/model/forcing.hpp"
#include "capsubot/model/params.hpp"
#include "capsubot/optimize/optimize_options.hpp"
#include "capsubot/optimize/optimize_result.hpp"

namespace capsubot {

/// Smallest and largest initial scan of P1 (the largest bounds its work and memory).
inline constexpr int kMinScanPoints = 16;
inline constexpr int kMaxScanPoints = 1000000;

/// P1's options: the shared ones (rho_max, max_time, active_tol) and the phase search.
struct PhaseOptions : OptimizeOptions {
  /// Points of the initial scan of the circle phi0 in [-pi, pi); kMinScanPoints <=
  /// scan_points <= kMaxScanPoints. The valid set may be several disjoint arcs: an arc narrower
  /// than tau/scan_points can be missed.
  int scan_points = 720;
  /// Absolute tolerance [rad] on phi0 for the arc edges (bisection) and the polish inside arcs.
  double phase_tol = 1e-12;

  /// Throws std::invalid_argument naming the first bad field, its value and the rule.
  void Validate() const;
};

/// P1: the phi0 maximising I over valid orbits for this force shape (forcing.phi0() is
/// ignored; the result's forcing carries the optimal phi0). Scans the circle, brackets the
/// valid arcs, bisects their edges (validity flips) and polishes I inside each arc (Brent),
/// returning the best point; never worse than the best valid point of its scan.
/// Status kOk, kNoValidOrbit with the point nearest to validity, or kMaxTime (the best point
/// of the part searched). Throws std::invalid_argument for bad params or options. Validity
/// includes the margins of options.gait (clearance, stick margin).
OptimizeResult OptimizePhase(const Forcing& forcing, const Params& params,
                             const PhaseOptions& options = {});

}  // namespace capsubot
