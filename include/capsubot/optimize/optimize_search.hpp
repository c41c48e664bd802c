#pragma once
// What the NLopt problems P2 and P3 of docs/model.md section 7 share: the gait asked for
// (GaitRequirements: the force bound, the stability requirement), the time limit, the global
// and local stages and their budgets (SearchEffort).

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
/// Smallest and largest evaluation budget of one NLopt stage.
inline constexpr int kMinStageEvaluations = 10;
inline constexpr int kMaxStageEvaluations = 10000000;

/// How hard a problem is searched: the global stage, the local polishes and their budgets.
struct SearchEffort {
  /// Global stage: "multistart" or an NLopt global algorithm name (GlobalAlgorithmNames()).
  std::string global_algorithm = kMultistart;
  /// Local polishes; 1 <= starts <= kMaxStarts.
  int starts = 10;
  /// Relative tolerance of the local polish on the variables and on I; > 0.
  double rel_tol = 1e-10;
  /// Evaluation budget of each local polish; kMinStageEvaluations <= .. <= kMaxStageEvaluations.
  int local_evaluations = 20000;
  /// Evaluation budget of an NLopt global stage; kMinStageEvaluations <= .. <=
  /// kMaxStageEvaluations.
  int global_evaluations = 5000;

  /// Throws std::invalid_argument naming the first bad field, its value and the rule
  /// (unknown algorithm names list the valid ones).
  void Validate() const;
};

/// P2's options besides its own scan and restarts (and those of the P2 optimum P3 starts from):
/// the gait asked for, the time limit and report tolerance (OptimizeOptions), the search
/// effort, the local algorithm and the seed.
struct SearchOptions : OptimizeOptions {
  // Not an aggregate: GCC 12 misreads the aggregate initialisation of a struct whose base
  // holds strings (ForcingDesignOptions{} warns -Wmaybe-uninitialized without this).
  SearchOptions() {}  // NOLINT(modernize-use-equals-default)
  /// How hard the problem is searched: global stage, local polishes and their budgets.
  SearchEffort effort;
  /// Local constrained polish, by NLopt name (LocalAlgorithmNames(); gradients of the LD_
  /// algorithms by central differences).
  std::string local_algorithm = "LN_COBYLA";
  /// Seed of the random numbers (restarts, NLopt's stochastic global algorithms).
  unsigned seed = 1;

  /// Throws std::invalid_argument naming the first bad field, its value and the rule
  /// (unknown algorithm names list the valid ones).
  void Validate() const;
};

}  // namespace capsubot
