#pragma once
// P2 of MODEL.md section 7: the harmonic force A sin(phi + phi0) + c (amplitude, mean and
// impact phase) that maximises the step I under the validity conditions, given to NLopt as
// inequality constraints.

#include <limits>
#include <string>
#include <vector>

#include "capsubot/optimize_result.hpp"
#include "capsubot/params.hpp"

namespace capsubot {

/// The global stage that needs no NLopt algorithm: local polishes from the best valid points
/// of a scan over (A, c, phi0).
inline constexpr const char* kMultistart = "multistart";

struct ForcingDesignOptions {
  /// Bound on the force: A + c <= force_bound (= max |F|); NaN means T0. Must satisfy
  /// 0 < force_bound <= T0 (a larger force moves the capsule without impacts, section 6).
  double force_bound = std::numeric_limits<double>::quiet_NaN();
  /// Global stage: "multistart" or an NLopt global algorithm with inequality constraints
  /// (GN_ISRES, GN_ORIG_DIRECT, GN_ORIG_DIRECT_L, GN_AGS), by NLopt name.
  std::string global_algorithm = kMultistart;
  /// Local constrained polish, by NLopt name: LN_COBYLA, LD_SLSQP, LD_MMA, LD_CCSAQ
  /// (gradients by central differences).
  std::string local_algorithm = "LN_COBYLA";
  /// Grid points per axis of the scan over (A/bound, c/bound) that seeds the multistart; >= 2.
  int grid = 16;
  /// Local polishes, from the best distinct valid scan points; >= 1.
  int starts = 10;
  /// Basin-hopping restarts after the starts: local polishes from random perturbations of
  /// the best point so far (A and c by about 20 %, phi0 by about 0.2 rad); >= 0.
  int hops = 20;
  /// Evaluations (P1 runs) of the final phase-exact polish: LN_SBPLX over (A + c, c/(A + c))
  /// of the best valid phase (P1) at each point; 0 switches it off; >= 0.
  int phase_exact_evaluations = 600;
  /// Relative tolerance of the local polish on the variables and on I; > 0.
  double rel_tol = 1e-10;
  /// Evaluation budget of each local polish; >= 10.
  int local_evaluations = 20000;
  /// Evaluation budget of an NLopt global stage; >= 10.
  int global_evaluations = 5000;
  /// Seed of the random numbers (hops, NLopt's stochastic global algorithms).
  unsigned seed = 1;
  /// Require a stable orbit: spectral radius (MODEL.md section 8) <= rho_max.
  bool stable = false;
  /// Largest admissible spectral radius when `stable`; > 0.
  double rho_max = 1.0;
  /// Slack at or below which a constraint is reported active; >= 0.
  double active_tol = 1e-7;

  /// Throws std::invalid_argument naming the first bad field, its value and the rule
  /// (unknown algorithm names list the valid ones).
  void Validate() const;
};

/// The global algorithm names accepted by ForcingDesignOptions (and FourierOptions).
std::vector<std::string> GlobalAlgorithmNames();
/// The local algorithm names accepted.
std::vector<std::string> LocalAlgorithmNames();

/// P2: A, c, phi0 maximising I subject to x_min >= margin, x_max <= 1 - margin,
/// 0 < alpha < 1, the stick condition, separation, A + c <= bound (and stability if asked).
/// The returned optimum is re-checked through Solve and is valid whenever status is kOk.
/// Throws std::invalid_argument for bad params or options.
OptimizeResult OptimizeForcing(const Params& params, const ForcingDesignOptions& options = {});

}  // namespace capsubot
