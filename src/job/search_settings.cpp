#include "capsubot/job/search_settings.hpp"

#include <fmt/format.h>

#include <string>

#include "capsubot/optimize/optimize_search.hpp"

namespace capsubot {

const SettingTable<GaitRequirements>& GaitBoundSettings() {
  using G = GaitRequirements;
  static const SettingTable<GaitRequirements> table = {
      {"bound", &G::force_bound,
       "force bound for forcing/fourier: A + c (max |F|) <= bound, 0 < bound <= T0, same unit "
       "as A (default: T0)"},
      {"rho_max", &G::rho_max,
       "largest spectral radius of the impact map (docs/model.md sections 8, 12); inf: no "
       "stability requirement"}};
  return table;
}

const SettingTable<SearchRequest>& SearchSettings() {
  using S = SearchRequest;
  // The helps that state the job's bounds on the budgets (OptimizeJobFrom).
  static const std::string global_evaluations = fmt::format(
      "evaluation budget of an NLopt global algorithm (not used by multistart), {} to {}",
      kMinStageEvaluations, kMaxStageEvaluations);
  static const std::string hops = fmt::format(
      "forcing: basin-hopping restarts from random perturbations of the best point after the "
      "starts, 0 to {}",
      kMaxStarts);
  static const SettingTable<SearchRequest> table = {
      {"max_time", &S::max_time,
       "time limit [s] of each optimisation; when reached, the best point so far is reported "
       "with status max_time (inf: none)"},
      {"harmonics", &S::harmonics,
       "number K of harmonics of the Fourier force: fourier (P3), or reach (the fastest Fourier "
       "drive from rest, climbing from the sine: K = 1 is the sine)"},
      {"global_algorithm", &S::global_algorithm,
       "global stage of forcing/fourier: multistart (scan + local polishes) or an NLopt "
       "algorithm: GN_ISRES, GN_ORIG_DIRECT, GN_ORIG_DIRECT_L, GN_AGS"},
      {"local_algorithm", &S::local_algorithm,
       "local constrained polish, NLopt name: LN_COBYLA, LD_SLSQP, LD_MMA, LD_CCSAQ (LD_*: "
       "gradients by central differences)"},
      {"global_evaluations", &S::global_evaluations, global_evaluations.c_str()},
      {"hops", &S::hops, hops.c_str()}};
  return table;
}

}  // namespace capsubot
