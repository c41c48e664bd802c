#pragma once
// What the NLopt problems P2 and P3 of docs/model.md section 7 share: the force bound, the global
// and local stages and their budgets, the stability requirement and the time limit.

#include <limits>
#include <string>
#include <vector>

#include "capsubot/model/params.hpp"
#include "capsubot/optimize/optimize_options.hpp"

namespace capsubot {

/// The global stage that needs no NLopt algorithm: local polishes from the best valid points
/// of a scan (P2) or from perturbations of the best point so far (P3).
inline constexpr const char* kMultistart = "multistart";

/// The global algorithm names accepted: "multistart" and NLopt's GN_ISRES, GN_ORIG_DIRECT,
/// GN_ORIG_DIRECT_L, GN_AGS (those that take inequality constraints).
std::vector<std::string> GlobalAlgorithmNames();
/// The local algorithm names accepted: LN_COBYLA, LD_SLSQP, LD_MMA, LD_CCSAQ.
std::vector<std::string> LocalAlgorithmNames();

/// Largest number of local polishes (starts, restarts) of one search: bounds its work.
inline constexpr int kMaxStarts = 1000;
/// Largest evaluation budget of one NLopt stage.
inline constexpr int kMaxStageEvaluations = 10000000;

/// How hard a problem is searched: the global stage, the local polishes and their budgets.
struct SearchEffort {
  /// Global stage: "multistart" or an NLopt global algorithm name (GlobalAlgorithmNames()).
  std::string global_algorithm = kMultistart;
  /// Local polishes; 1 <= starts <= kMaxStarts.
  int starts = 10;
  /// Relative tolerance of the local polish on the variables and on I; > 0.
  double rel_tol = 1e-10;
  /// Evaluation budget of each local polish; 10 <= local_evaluations <= kMaxStageEvaluations.
  int local_evaluations = 20000;
  /// Evaluation budget of an NLopt global stage; 10 <= .. <= kMaxStageEvaluations.
  int global_evaluations = 5000;

  /// Throws std::invalid_argument naming the first bad field, its value and the rule
  /// (unknown algorithm names list the valid ones).
  void Validate() const;
};

/// The gait asked of P2 (and of P3, which starts from P2's optimum for the same request):
/// stability, time limit, force bound, local algorithm and seed, with P2's search effort.
struct SearchOptions : OptimizeOptions, SearchEffort {
  // Not an aggregate: value-initialised through this constructor (GCC 12 misreads the
  // aggregate initialisation of a struct with two bases holding strings).
  SearchOptions() {}  // NOLINT(modernize-use-equals-default)
  /// Bound on the force, max |F| (A + c for the harmonic force); NaN means T0. Must satisfy
  /// 0 < force_bound <= T0 (a larger force moves the capsule without impacts, section 6).
  double force_bound = std::numeric_limits<double>::quiet_NaN();
  /// Local constrained polish, by NLopt name (LocalAlgorithmNames(); gradients of the LD_
  /// algorithms by central differences).
  std::string local_algorithm = "LN_COBYLA";
  /// Seed of the random numbers (restarts, NLopt's stochastic global algorithms).
  unsigned seed = 1;

  /// Throws std::invalid_argument naming the first bad field, its value and the rule
  /// (unknown algorithm names list the valid ones).
  void Validate() const;
  /// The bound in force for these params: force_bound, or T0 when it is NaN; throws
  /// std::invalid_argument when it exceeds T0.
  double BoundFor(const Params& params) const;
};

}  // namespace capsubot
