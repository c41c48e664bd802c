#pragma once
// P3 of MODEL.md section 7: a force given by K harmonics, F = c + sum_k (a_k cos k phi +
// b_k sin k phi) seen from the impact, with mean c > 0 and max |F| <= bound, maximising I.

#include <limits>
#include <string>

#include "capsubot/optimize_result.hpp"
#include "capsubot/params.hpp"

namespace capsubot {

struct FourierOptions {
  /// Number of harmonics K; 1 <= K <= kMaxHarmonics.
  int harmonics = 3;
  /// Bound on max |F|; NaN means T0. 0 < force_bound <= T0.
  double force_bound = std::numeric_limits<double>::quiet_NaN();
  /// Local constrained polish, by NLopt name (see LocalAlgorithmNames()).
  std::string local_algorithm = "LN_COBYLA";
  /// Global stage: "multistart" (random perturbations of the P2 optimum and of the best
  /// points found so far) or an NLopt global algorithm name (see GlobalAlgorithmNames()).
  std::string global_algorithm = "multistart";
  /// Local polishes; >= 1.
  int starts = 20;
  /// Relative tolerance of the local polish; > 0.
  double rel_tol = 1e-9;
  /// Evaluation budget of each local polish; >= 10.
  int local_evaluations = 20000;
  /// Evaluation budget of an NLopt global stage; >= 10.
  int global_evaluations = 5000;
  /// Seed of the random perturbations.
  unsigned seed = 1;
  /// Require a stable orbit: spectral radius <= rho_max.
  bool stable = false;
  /// Largest admissible spectral radius when `stable`; > 0.
  double rho_max = 1.0;
  /// Slack at or below which a constraint is reported active; >= 0.
  double active_tol = 1e-7;

  void Validate() const;  ///< throws std::invalid_argument naming the bad field
};

/// P3: maximise I over K-harmonic forces (impact phase free: the coefficients are relative to
/// the impact, phi0 = 0). Starts from the P2 optimum at the same bound, so its I is never
/// below it; result.baseline_I holds that P2 value. The result's forcing is a Fourier force.
OptimizeResult OptimizeFourier(const Params& params, const FourierOptions& options = {});

}  // namespace capsubot
