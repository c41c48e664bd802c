#pragma once
// What the NLopt problems P2 and P3 of docs/model.md section 7 share: the force bound, the global
// and local stages and their budgets, the stability requirement.

#include <limits>
#include <string>
#include <vector>

#include "capsubot/params.hpp"

namespace capsubot {

/// The global stage that needs no NLopt algorithm: local polishes from the best valid points
/// of a scan (P2) or from perturbations of the best point so far (P3).
inline constexpr const char* kMultistart = "multistart";

/// The global algorithm names accepted: "multistart" and NLopt's GN_ISRES, GN_ORIG_DIRECT,
/// GN_ORIG_DIRECT_L, GN_AGS (those that take inequality constraints).
std::vector<std::string> GlobalAlgorithmNames();
/// The local algorithm names accepted: LN_COBYLA, LD_SLSQP, LD_MMA, LD_CCSAQ.
std::vector<std::string> LocalAlgorithmNames();

struct SearchOptions {
  /// Bound on the force, max |F| (A + c for the harmonic force); NaN means T0. Must satisfy
  /// 0 < force_bound <= T0 (a larger force moves the capsule without impacts, section 6).
  double force_bound = std::numeric_limits<double>::quiet_NaN();
  /// Global stage: "multistart" or an NLopt global algorithm name (GlobalAlgorithmNames()).
  std::string global_algorithm = kMultistart;
  /// Local constrained polish, by NLopt name (LocalAlgorithmNames(); gradients of the LD_
  /// algorithms by central differences).
  std::string local_algorithm = "LN_COBYLA";
  /// Local polishes; >= 1.
  int starts = 10;
  /// Relative tolerance of the local polish on the variables and on I; > 0.
  double rel_tol = 1e-10;
  /// Evaluation budget of each local polish; >= 10.
  int local_evaluations = 20000;
  /// Evaluation budget of an NLopt global stage; >= 10.
  int global_evaluations = 5000;
  /// Seed of the random numbers (restarts, NLopt's stochastic global algorithms).
  unsigned seed = 1;
  /// Require a stable orbit: spectral radius (docs/model.md section 8) <= rho_max.
  bool stable = false;
  /// Largest admissible spectral radius when `stable`; > 0.
  double rho_max = 1.0;
  /// Slack at or below which a constraint is reported active; >= 0.
  double active_tol = 1e-7;

  /// Throws std::invalid_argument naming the first bad field, its value and the rule
  /// (unknown algorithm names list the valid ones).
  void Validate() const;
  /// The bound in force for these params: force_bound, or T0 when it is NaN; throws
  /// std::invalid_argument when it exceeds T0.
  double BoundFor(const Params& params) const;
};

}  // namespace capsubot
