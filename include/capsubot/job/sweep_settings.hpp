#pragma once
// The settings of the sweep job as a front end receives them, and the rules that make them a
// job: which mode (the orbit of a force, or optimize's phi0, forcing, fourier, reach) reads
// which setting, a value given both as a setting and by the grid, no evaluation budget under
// the multistart stage, no pulse force, each mode's own defaults. Both front ends fill
// SweepSettings (their flag or keyword syntax only) and call SweepJobFrom; the messages name
// the settings in the front end's names.

#include <set>
#include <string>
#include <utility>
#include <vector>

#include "capsubot/attract/start_grid.hpp"
#include "capsubot/job/setting_use.hpp"
#include "capsubot/job/sweep_job.hpp"
#include "capsubot/model/setting_names.hpp"
#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/reach/reach_effort.hpp"

namespace capsubot {

/// The settings of the sweep job by field. A mode takes a setting only when it is in `given`;
/// otherwise it keeps its own default (SweepModeNamed), and the value here is the command's
/// default, which a front end shows.
struct SweepSettings {
  std::string optimize;  ///< "" (the orbit of the force), "phi0", "forcing", "fourier", "reach"
  Grid grid;             ///< the axes; a parameter the grid gives cannot be given here too
  double A = kNaN;       ///< the force (orbit, phi0): F = A sin(phi + phi0) + c
  double c = kNaN;
  double phi0 = kNaN;            ///< orbit: the motor phase at the impact
  std::vector<double> sin, cos;  ///< the Fourier force's b_1..b_K and a_1..a_K
  /// The force's kind, as the front end names it. A pulse force (waveform "pulse", or the
  /// settings "levels" or "switches" given: its parts, which hold no value here) is refused:
  /// a sweep solves the analytic one-impact orbit.
  std::string waveform;
  Params params;             ///< T0, e (every mode)
  Margins margins;           ///< the margins d, d_s, s (every mode)
  bool stability = false;    ///< the stability columns (not reach)
  bool stable_only = false;  ///< rho_max = 1 (the modes that optimise)
  /// The search of P2, P3 and of the reach search's seed: the bound (gait.force_bound),
  /// rho_max (P1's too), starts, hops, harmonics (P3), the algorithms and global_evaluations.
  SearchRequest search;
  int scan_points = PhaseOptions{}.scan_points;  ///< P1: points of the initial scan of phi0
  double alpha = kNaN;                           ///< reach: a fixed mass ratio (NaN: free)
  /// reach: the seed's check from rest and the starts inside the search, NXxNPSI.
  std::string from_rest_starts = StartGrid{}.Text();
  std::string reach_starts = StartGrid{ReachEffort{}.n_x, ReachEffort{}.n_psi}.Text();
  int reach_evaluations = ReachOptions{}.global_evaluations;  ///< reach: the search's budgets
  int reach_local_evaluations = ReachOptions{}.local_evaluations;
  GridFileOptions file;  ///< the CSV file: output, threads, shard, resume, comment lines
  /// The fields given by the user.
  std::set<std::string> given;

  bool Given(const std::string& field) const { return given.count(field) > 0; }
};

/// The modes that read each setting ("": the orbit of the force; the other modes by their
/// optimize name), in the command line's order of its options; a setting not listed (T0, e,
/// the margins) shapes every mode.
const std::vector<SettingUse>& SweepSettingUses();

/// The modes as the helps name them: {optimize} phi0, forcing, fourier, reach, and the orbit of
/// the force (no {optimize}).
const ModeSet& SweepModes();

/// The job `settings` ask for, validated (SweepJobOptions::Validate). Throws
/// std::invalid_argument, in `names`, for an unknown mode, a value given both as a setting and
/// by the grid, a pulse force, a bad grid of starts, a setting given to a mode that does not
/// read it, an evaluation budget under the multistart stage, and what Validate refuses (in the
/// fields of the lower stages: a front end renames them).
SweepJobOptions SweepJobFrom(const SweepSettings& settings, const SettingNames& names);

/// The numbers the mode of `settings` (valid: SweepJobFrom accepts them) takes from defaults of
/// its own, different from those of `settings`, where they are not given (the reach search's
/// robust margins and rho_max): (field, the mode's value as FormatNumber writes it), for a
/// record of what ran.
std::vector<std::pair<std::string, std::string>> SweepModeDefaults(const SweepSettings& settings);

}  // namespace capsubot
