#include "capsubot/job/sweep_setting_tables.hpp"

#include <fmt/format.h>

#include <string>

#include "capsubot/optimize/optimize_phase.hpp"
#include "capsubot/optimize/optimize_search.hpp"

namespace capsubot {

const SettingTable<SweepSettings>& SweepModeSettings() {
  using S = SweepSettings;
  // The help that states the rule's bounds (PhaseOptions).
  static const std::string scan_points = fmt::format(
      "with {{optimize}} phi0: points of the optimiser's initial scan of phi0, {} to {}",
      kMinScanPoints, kMaxScanPoints);
  static const SettingTable<SweepSettings> table = {
      {"stability", &S::stability,
       "add the columns spectral_radius (of the impact map, docs/model.md section 8), "
       "lambda_re, lambda_im (its largest multiplier), stable (1 when < 1) and loss (fold, flip "
       "or torus when unstable)"},
      {"optimize", &S::optimize,
       "the best gait at every point: phi0 (P1: the impact phase for the given force shape; "
       "adds column phi0), forcing (P2: A, c, phi0 with A + c <= {bound}; adds A, c, phi0), "
       "fourier (P3: a {harmonics} K force with max |F| <= {bound}; adds c, a1..aK, b1..bK) or "
       "reach (the fastest motion from rest, as `optimize --problem reach`: A, c, phi0, alpha, "
       "mean_velocity, ..., the robust seed's seed_v_mean and seed_mean_velocity_from_rest; "
       "seconds per point); adds a status column"},
      {"scan_points", &S::scan_points, scan_points.c_str()},
      {"alpha", &S::alpha,
       "with {optimize} reach: a fixed mass ratio 0 < alpha < 1 (default: alpha is optimised "
       "too)"}};
  return table;
}

const SettingTable<GaitRequirements>& SweepGaitSettings() {
  using G = GaitRequirements;
  static const SettingTable<GaitRequirements> table = {
      {"rho_max", &G::rho_max,
       "with {optimize}: maximise over orbits whose spectral radius is at most rho_max > 0 "
       "(docs/model.md sections 8, 12); inf: no stability requirement"},
      {"bound", &G::force_bound,
       "with {optimize} forcing|fourier|reach: the force bound A + c (max |F|) <= bound <= T0 "
       "(default: T0)"}};
  return table;
}

const SettingTable<SearchRequest>& SweepSearchSettings() {
  using R = SearchRequest;
  // The help that states the rule's bounds (SearchEffort).
  static const std::string global_evaluations = fmt::format(
      "with {{optimize}} forcing|fourier|reach: evaluation budget of an NLopt global algorithm "
      "(not multistart), {} to {}",
      kMinStageEvaluations, kMaxStageEvaluations);
  static const SettingTable<SearchRequest> table = {
      {"harmonics", &R::harmonics, "with {optimize} fourier: the number K of harmonics"},
      {"hops", &R::hops, "with {optimize} forcing|reach: basin-hopping restarts after the starts"},
      {"global_algorithm", &R::global_algorithm,
       "with {optimize} forcing|fourier|reach: multistart or an NLopt global algorithm "
       "(GN_ISRES, GN_ORIG_DIRECT, GN_ORIG_DIRECT_L, GN_AGS)"},
      {"local_algorithm", &R::local_algorithm,
       "with {optimize} forcing|fourier|reach: the local polish (LN_COBYLA, LD_SLSQP, LD_MMA, "
       "LD_CCSAQ)"},
      {"global_evaluations", &R::global_evaluations, global_evaluations.c_str(),
       // Each mode has its own default (SweepModeDefaults).
       0, 0, nullptr, false}};
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
