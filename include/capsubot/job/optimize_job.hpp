#pragma once
// The job of `capsubot optimize` (and the Python module's optimize) in one call: the main job
// (the paper's problem, the fastest robust gait checked from rest, the fastest motion from rest,
// how far the robust gait's motion carries, the exact optima), one problem P1, P2 or P3 checked
// from rest, or the reach problem (docs/model.md sections 7, 12, 13).

#include <string>
#include <variant>
#include <vector>

#include "capsubot/attract/attractors.hpp"
#include "capsubot/attract/gait_from_rest.hpp"
#include "capsubot/continue/gait_robustness.hpp"
#include "capsubot/job/stage_callback.hpp"
#include "capsubot/model/params.hpp"
#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/optimize/optimize_request.hpp"
#include "capsubot/optimize/optimize_result.hpp"
#include "capsubot/reach/drive_ladder.hpp"
#include "capsubot/reach/optimize_reach.hpp"
#include "capsubot/reach/reach_effort.hpp"

namespace capsubot {

/// The main job: P1 at c = A = T0/2 without margins, P2 with the job's margins checked from
/// rest, the reach search seeded with it, the fastest Fourier drives of up to `drive_harmonics`
/// harmonics climbing from its winner, both motions continued in T0, e and alpha with the speed
/// bands of their robots, P2 without margins (valid; stable).
struct MainJob {
  ReachEffort reach;
  /// The levels of the speed bands of both motions (SpeedBandOptions::levels: fractions of the
  /// speed from rest, each in (0, 1)); the bands' starts are the job's check from rest.
  std::vector<double> band_levels = {0.95};
  /// The budgets of the drive part (150 Halton points and 2 polishes of 80, without the random
  /// search and the screens of `--problem reach`), smaller than those of
  /// `--problem reach --harmonics K`, so that the whole job takes seconds; its starts and time
  /// limit are those of `reach`.
  ReachEffort drives = MainJobDriveEffort();
  int drive_harmonics = 3;  ///< the largest K of the drive part; 2 <= K <= kMaxHarmonics
  int pulse_levels = 3;     ///< the levels N of the drive part's pulse drive; 2 <= N <= 16

  /// The drive part's budgets: 150 Halton points and 2 polishes of 80 evaluations a step.
  static ReachEffort MainJobDriveEffort();
};
/// P1: the best impact phase phi0 for the force shape F = A sin(phi + phi0) + c.
struct PhaseProblem {
  double A = kNaN;  ///< amplitude, finite and >= 0
  double c = kNaN;  ///< mean force, finite
};
/// P2: the best A, c, phi0 with A + c <= the force bound.
struct ForcingProblem {};
/// P3: the best force of SearchRequest::harmonics harmonics with max |F| <= the force bound.
struct FourierProblem {};
/// The fastest motion from rest, seeded with the robust gait (P2): of the sine, of a Fourier
/// drive of K >= 2 harmonics, climbing from the sine (drive_ladder.hpp), or of a pulse drive
/// (after the sine's, for the comparison).
struct ReachProblem {
  ReachEffort reach;
  double alpha = kNaN;  ///< fixed 0 < alpha < 1; NaN: free
  DriveFamily drive{};  ///< the forces searched (the sine by default)
  /// The motor's frequency free: T0 in [T0_min, T0_max] with the bound tied to it, the
  /// objective v_mean / sqrt(T0) (ReachOptions::T0_min); NaN: T0 fixed.
  double T0_min = kNaN;
  double T0_max = kNaN;
};

/// What the job runs: each mode holds the settings only it uses.
using OptimizeMode =
    std::variant<MainJob, PhaseProblem, ForcingProblem, FourierProblem, ReachProblem>;

/// The name of a mode: "" (the main job), "phase", "forcing", "fourier", "reach".
const char* OptimizeModeName(const OptimizeMode& mode);

struct OptimizeJobOptions {
  OptimizeMode mode;
  /// The robot's T0 and e.
  Params params;
  /// The gait asked for (by default the robust gait of docs/model.md section 12: its margins,
  /// force bound and rho_max) and the search of P1-P3; its interrupt is asked by every stage
  /// of the job.
  SearchRequest search = RobustRequest();
  /// The from-rest check of every reported gait (the reach winner's re-check too).
  FromRestOptions check;
  /// Told each stage of the job.
  StageCallback on_stage;

  /// SearchRequest{} asking for the robust gait of docs/model.md section 12: the margins
  /// RobustMargins() and spectral radius <= kRobustRhoMax.
  static SearchRequest RobustRequest();

  /// The options of a reach search of this job with `effort` and mass ratio `alpha` (NaN:
  /// free): the request's force bound, the job's check from rest (asking the request's
  /// interrupt), and the seeds the search computes itself (one per motor frequency when T0 is
  /// free) asking for the request's gait (its margins and rho_max), as the robust gait that
  /// seeds it does.
  ReachOptions ReachOptionsOf(const ReachEffort& effort, double alpha) const;

  /// Throws std::invalid_argument naming the first bad field, its value and the rule.
  void Validate() const;
};

/// The main job's results (MainJob).
struct MainJobResult {
  Params params;
  GaitRequirements gait;  ///< the margins, the force bound (T0 when not given) and rho_max
  OptimizeResult paper;   ///< P1 at c = A = T0/2, no margins
  OptimizeResult robust;  ///< P2 with the margins (its from-rest check: reach.seed)
  ReachResult reach;      ///< the fastest motion from rest (of the sine)
  /// The fastest Fourier drives under the same bound: K = 1 (the sine: `reach`), 2, ...,
  /// drive_harmonics.
  std::vector<ReachResult> drives;
  /// The fastest pulse drive (pulse_levels levels) under the same bound.
  ReachResult pulse;
  GaitRobustness robustness;  ///< the robust gait's motion continued (empty without it)
  /// The most common motion from rest of the reach winner continued, when it is periodic (its
  /// speed bands alone otherwise); empty without a winner.
  GaitRobustness reach_robustness;
  OptimizeResult fastest;  ///< P2 without margins
  OptimizeResult stable;   ///< P2 without margins, spectral radius <= 1
};

/// One problem P1, P2 or P3 and its optimum checked from rest.
struct ProblemJobResult {
  std::string problem;  ///< "phase", "forcing" or "fourier"
  Params params;
  GaitRequirements gait;  ///< the margins and rho_max asked for
  OptimizeResult result;
  GaitFromRest from_rest;
};

/// The reach problem's result.
struct ReachJobResult {
  Params params;
  GaitRequirements gait;  ///< the seed's margins and stability requirement
  ReachResult reach;      ///< the winner of the family asked for
  /// A Fourier drive's ladder: the winners of K = 1 (the sine), 2, ..., K; a pulse drive's: the
  /// sine's winner and the pulse's; empty for the sine.
  std::vector<ReachResult> ladder;
};

using OptimizeJobResult = std::variant<MainJobResult, ProblemJobResult, ReachJobResult>;

/// Runs the job (options.Validate() first). Throws what the interrupt throws.
OptimizeJobResult RunOptimizeJob(const OptimizeJobOptions& options);

/// The force the job recommends: the robust gait's (main job), the winner's (reach), the
/// optimum's (a problem).
const Forcing& RecommendedForcing(const OptimizeJobResult& result);

}  // namespace capsubot
