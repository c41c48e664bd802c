#pragma once
// The settings of the optimize job as a front end receives them, and the rules that make them a
// job: which problem uses which setting, which settings go together, the ranges of what is
// given. Both front ends fill OptimizeSettings (their flag or keyword syntax only) and call
// OptimizeJobFrom; the messages name the settings in the front end's names.

#include <set>
#include <string>
#include <vector>

#include "capsubot/attract/start_grid.hpp"
#include "capsubot/job/optimize_job.hpp"
#include "capsubot/job/setting_table.hpp"
#include "capsubot/job/setting_use.hpp"
#include "capsubot/model/setting_names.hpp"

namespace capsubot {

/// The settings of the optimize job by field; those not in `given` hold their defaults.
struct OptimizeSettings {
  std::string problem;  ///< "" (the main job), "phase", "forcing", "fourier" or "reach"
  double A = kNaN;      ///< phase: the amplitude of F = A sin(phi + phi0) + c
  double c = kNaN;      ///< phase: the mean force
  Params params;        ///< T0, e
  /// The gait asked for (its margins, bound and rho_max: by default the robust gait) and the
  /// search of P1-P3 (`bound` is search.gait.force_bound).
  SearchRequest search = OptimizeJobOptions::RobustRequest();
  /// The check from rest of every gait, NXxNPSI (StartGrid::Text; default 8x8).
  std::string from_rest_starts = StartGrid{}.Text();
  /// The starts inside the reach search, NXxNPSI (default: ReachEffort's grid, 4x4).
  std::string reach_starts = StartGrid{ReachEffort{}.n_x, ReachEffort{}.n_psi}.Text();
  ReachEffort reach;     ///< the reach search's budgets (its grid: reach_starts)
  int threads = 0;       ///< worker threads of the checks (0: all cores)
  double alpha = kNaN;   ///< reach: a fixed mass ratio (NaN: free)
  double T0_min = kNaN;  ///< reach: the motor's frequency free (T0_range)
  double T0_max = kNaN;
  std::string waveform;  ///< reach: "", "sine", "fourier" or "pulse"
  int pulse_levels = 3;  ///< reach --waveform pulse: the levels N
  std::vector<double> band_levels = MainJob{}.band_levels;  ///< main job: the speed bands
  /// The fields given by the user; every other one holds its default.
  std::set<std::string> given;

  bool Given(const std::string& field) const { return given.count(field) > 0; }
};

/// problem, A, c, alpha, waveform, pulse_levels: the problem and the settings of its own that a
/// front end reads as values (the search's: search_settings.hpp; the reach search's effort:
/// reach_effort_settings.hpp). The range of T0 and the speed bands are read as text.
const SettingTable<OptimizeSettings>& OptimizeProblemSettings();

/// The problems that use each setting ("": the main job); a setting not listed shapes every one.
const std::vector<SettingUse>& OptimizeSettingUses();

/// The problems as the helps name them: {problem} phase, forcing, fourier, reach, and the main
/// job.
const ModeSet& OptimizeModes();

/// The problem `problem` in `names`: "--problem forcing", or the main job ("the main job (no
/// --problem)") for "".
std::string OptimizeProblemName(const std::string& problem, const SettingNames& names);

/// The settings that do not shape the output of the problem `settings` asks for: those its
/// problem does not use, global_evaluations under the multistart global stage, and for the
/// reach problem the drive budgets without a drive search beyond the sine and pulse_levels
/// without a pulse drive.
std::vector<std::string> UnusedOptimizeSettings(const OptimizeSettings& settings);

/// The job `settings` ask for. Throws std::invalid_argument, in `names`, for a setting given to
/// a problem that does not use it, settings that do not go together, a given value that is not
/// admissible, and whatever OptimizeJobOptions::Validate refuses (the job is validated).
OptimizeJobOptions OptimizeJobFrom(const OptimizeSettings& settings, const SettingNames& names);

}  // namespace capsubot
