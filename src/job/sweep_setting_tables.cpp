#include "capsubot/job/sweep_setting_tables.hpp"

#include <fmt/format.h>

#include <string>

#include "capsubot/job/search_settings.hpp"
#include "capsubot/optimize/optimize_phase.hpp"
#include "capsubot/optimize/optimize_search.hpp"

namespace capsubot {

const SettingTable<SweepSettings>& SweepModeSettings() {
  using S = SweepSettings;
  // The help that states the rule's bounds (PhaseOptions).
  static const std::string scan_points = fmt::format(
      "points of the optimiser's initial scan of phi0, {} to {}", kMinScanPoints, kMaxScanPoints);
  // Each help opens with the modes that use its setting (WithModes).
  static const SettingTable<SweepSettings> table = WithModes<SweepSettings>(
      {{"stability", &S::stability,
        "add the columns spectral_radius (of the impact map, docs/model.md section 8), "
        "lambda_re, lambda_im (its largest multiplier), stable (1 when < 1) and loss (fold, flip "
        "or torus when unstable)"},
       {"optimize", &S::optimize,
        "the best gait at every point: phi0 (P1: the impact phase for the given force shape; "
        "adds column phi0), forcing (P2: A, c, phi0 with A + c <= {bound}; adds A, c, phi0), "
        "fourier (P3: a {harmonics} K force with max |F| <= {bound}; adds c, a1..aK, b1..bK) or "
        "reach (the fastest motion from rest, as optimize's problem reach: A, c, phi0, alpha, "
        "mean_velocity, ..., the robust seed's seed_v_mean and seed_mean_velocity_from_rest; "
        "seconds per point); adds a status column"},
       {"scan_points", &S::scan_points, scan_points.c_str()},
       {"alpha", &S::alpha, "a fixed mass ratio 0 < alpha < 1 (default: alpha is optimised too)"}},
      SweepSettingUses(), SweepModes());
  return table;
}

const SettingTable<GaitRequirements>& SweepGaitSettings() {
  static const SettingTable<GaitRequirements> table =
      WithModes(GaitBoundMeanings(), SweepSettingUses(), SweepModes());
  return table;
}

const SettingTable<SearchRequest>& SweepSearchSettings() {
  static const SettingTable<SearchRequest> table = [] {
    SettingTable<SearchRequest> t;
    for (SettingRow<SearchRequest> row :
         WithModes(SearchMeanings(), SweepSettingUses(), SweepModes())) {
      if (std::string(row.field) == "max_time") continue;  // a sweep runs no clock
      // Each mode has its own default of the budget (SweepModeDefaults).
      if (std::string(row.field) == "global_evaluations") row.default_shown = false;
      t.push_back(row);
    }
    return t;
  }();
  return table;
}

const SettingTable<GridFileOptions>& SweepFileSettings() {
  using F = GridFileOptions;
  static const SettingTable<GridFileOptions> table = {
      {"output", &F::output,
       "the CSV file to write (required); - writes to standard output (no {resume} then)", 0, 0,
       "FILE"},
      {"resume", &F::resume,
       "continue an interrupted sweep from <output>.checkpoint (same options required; the "
       "checkpoint's checksums are verified); without it a sweep always starts again"},
      {"checkpoint_seconds", &F::checkpoint_seconds,
       "minimum time [s] between two checkpoints (each one fsyncs the partial file); 0: after "
       "every block of rows"}};
  return table;
}

}  // namespace capsubot
