#include "capsubot/job/search_settings.hpp"

#include <fmt/format.h>

#include <string>

#include "capsubot/job/optimize_settings.hpp"
#include "capsubot/optimize/optimize_search.hpp"

namespace capsubot {

const SettingTable<GaitRequirements>& GaitBoundMeanings() {
  using G = GaitRequirements;
  static const SettingTable<GaitRequirements> table = {
      {"bound", &G::force_bound,
       "the force bound A + c (max |F|) <= bound, 0 < bound <= T0, same unit as A (default: "
       "T0)"},
      {"rho_max", &G::rho_max,
       "largest spectral radius of the impact map (docs/model.md sections 8, 12); infinity: no "
       "stability requirement"}};
  return table;
}

const SettingTable<SearchRequest>& SearchMeanings() {
  using S = SearchRequest;
  // The helps that state the job's bounds on the budgets (SearchEffort's rules).
  static const std::string global_evaluations = fmt::format(
      "evaluation budget of an NLopt global algorithm (not used by multistart), {} to {}",
      kMinStageEvaluations, kMaxStageEvaluations);
  static const std::string hops = fmt::format(
      "basin-hopping restarts from random perturbations of the best point after the starts, 0 "
      "to {}",
      kMaxStarts);
  static const SettingTable<SearchRequest> table = {
      {"max_time", &S::max_time,
       "time limit [s] of each optimisation; when reached, the best point so far is reported "
       "with status max_time (infinity: none)"},
      {"harmonics", &S::harmonics, "number K of harmonics of the Fourier force (K = 1: the sine)"},
      {"global_algorithm", &S::global_algorithm,
       "global stage: multistart (scan + local polishes) or an NLopt algorithm: GN_ISRES, "
       "GN_ORIG_DIRECT, GN_ORIG_DIRECT_L, GN_AGS"},
      {"local_algorithm", &S::local_algorithm,
       "local constrained polish, NLopt name: LN_COBYLA, LD_SLSQP, LD_MMA, LD_CCSAQ (LD_*: "
       "gradients by central differences)"},
      {"global_evaluations", &S::global_evaluations, global_evaluations.c_str()},
      {"hops", &S::hops, hops.c_str()}};
  return table;
}

const SettingTable<GaitRequirements>& GaitBoundSettings() {
  static const SettingTable<GaitRequirements> table =
      WithModes(GaitBoundMeanings(), OptimizeSettingUses(), OptimizeModes());
  return table;
}

const SettingTable<SearchRequest>& SearchSettings() {
  static const SettingTable<SearchRequest> table = [] {
    SettingTable<SearchRequest> t =
        WithModes(SearchMeanings(), OptimizeSettingUses(), OptimizeModes());
    for (SettingRow<SearchRequest>& row : t) {
      if (std::string(row.field) != "harmonics") continue;
      // Reach searches the sine unless a Fourier drive is asked for.
      row.default_shown = false;
      row.help = KeptText(fmt::format(
          "{}; default: {}, but reach searches the sine unless {{harmonics}} or {{waveform}} "
          "fourier is given (K >= 2: the fastest Fourier drive, climbed from the sine: ladder "
          "and speed_ratio_to_sine in the result)",
          row.help, SearchRequest{}.harmonics));
    }
    return t;
  }();
  return table;
}

}  // namespace capsubot
