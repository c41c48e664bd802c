#pragma once
// The fastest motion from rest (docs/model.md sections 12 and 13): the force A sin(phi + phi0) + c
// (A + c <= bound) and the mass ratio alpha that maximise the mean velocity, over a grid of
// starts from rest, of the long-run motion the exact simulator reaches, whatever it is (one or
// many impacts, one or both walls). Not an orbit formula: every evaluation simulates the robot.
//
// Variables y = (s, r[, alpha]) on a box: A = s (1 - r) bound, c = s r bound, so A + c <= bound
// holds everywhere. A point where any start ends in event_limit (a Zeno sequence: the simulator
// hit its work bound) is infeasible: it scores far below every motion and is never a winner.
// The search (NLopt global stage, then a local polish) uses cheap from-rest settings; the best
// points it found and the seed (the robust one-impact gait of P2) are then re-checked with the
// full settings, and the best of them wins, so the result is never below the seed's own
// from-rest mean velocity. A candidate wins only if it is re-simulated with other numerical
// settings (the chatter cut-off 100 times smaller and larger, e = 0.999 for e = 1) without an
// event_limit start and with nearly the same mean velocity: the motion must be the robot's, not
// the simulator's.

#include <cstdint>
#include <string>
#include <vector>

#include "capsubot/attract/attractors.hpp"
#include "capsubot/attract/gait_from_rest.hpp"
#include "capsubot/model/params.hpp"
#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/optimize/optimize_forcing.hpp"
#include "capsubot/optimize/optimize_result.hpp"
#include "capsubot/reach/drive_family.hpp"

namespace capsubot {

/// The global algorithm names accepted by OptimizeReach: bound-constrained NLopt methods and
/// HALTON, the points of a Halton sequence of the box (an evenly spread random search).
std::vector<std::string> ReachGlobalAlgorithmNames();
/// The local algorithm names accepted by OptimizeReach (derivative-free NLopt methods).
std::vector<std::string> ReachLocalAlgorithmNames();

/// The from-rest settings used inside the search by default: 4 x 4 starts, 100 + 32 periods.
FromRestOptions CheapFromRestOptions();

/// The default seed design: P2 restricted to the robust gait (docs/model.md section 12): the
/// margins RobustMargins() and spectral radius <= kRobustRhoMax.
ForcingDesignOptions RobustSeedDesign();

/// A drive that starts a search: a force of the family (e.g. the winner of a smaller family)
/// with its mass ratio.
struct DriveSeed {
  Forcing forcing;
  double alpha = kNaN;
  double T0 = kNaN;  ///< its T0; NaN: the robot's
};

struct ReachOptions {
  /// The forces searched: the sine A sin(phi + phi0) + c (today's problem) or a Fourier series
  /// of K harmonics (drive_family.hpp).
  DriveFamily drive;
  /// Bound on the force: max |F| <= force_bound (A + c for the sine); NaN means T0;
  /// 0 < force_bound <= T0.
  double force_bound = kNaN;
  /// Drives that start the search besides the robust gait (a smaller family's winner); each is
  /// scored first and re-checked with the full settings, so the result is never below them.
  /// Each must belong to `drive` (DriveCoordinates) with the seed's motor phase; at most
  /// kMaxHarmonics.
  std::vector<DriveSeed> seeds;
  /// Local polishes, each from one of the best distinct points seen before them; >= 1.
  int polish_starts = 1;
  /// A second global stage (controlled random search, GN_CRS2_LM) from the best point of the
  /// first, with this many evaluations (0: none); >= 0.
  int refine_evaluations = 0;
  /// Short local screens between the global stages and the polishes, from the best distinct
  /// points seen, screen_evaluations each (0: none); both >= 0.
  int screen_starts = 0;
  int screen_evaluations = 0;
  /// The motor's frequency free (docs/reach.md, "Frequency"): T0 = mu g/(omega^2 L) is a
  /// variable in [T0_min, T0_max] (log scale; the robot's T0 must lie in it), the force bound
  /// is tied to it (force_bound / T0 stays the robot's ratio: a force bound in newtons tied to
  /// the friction force), and the objective is the speed in units of sqrt(mu g L),
  /// v_mean / sqrt(T0). Both NaN: T0 is the robot's and the objective is v_mean.
  double T0_min = kNaN;
  double T0_max = kNaN;
  /// A fixed mass ratio (0 < alpha < 1); NaN: alpha is a variable in [alpha_min, alpha_max].
  double alpha = kNaN;
  double alpha_min = 0.05;  ///< lower end of the alpha box; 0 < alpha_min < alpha_max
  double alpha_max = 0.95;  ///< upper end of the alpha box; < 1 (see widen_alpha_box)
  /// The alpha box widens to hold the starting drives' alphas; false: it is a hard range, and
  /// a starting drive outside it is left out (a designer's range of inner masses).
  bool widen_alpha_box = true;
  /// The force bound is a motor force in newtons (docs/design.md, "Part (c): the fastest drive"):
  /// NaN, the bound is force_bound in units of (m1+m2) omega^2 L whatever alpha; else force_bound
  /// holds at this mass ratio and the bound at alpha is force_bound (1 - alpha)/(1 - bound_alpha)
  /// (the unit grows with the inner mass m2 = alpha m1/(1 - alpha)), never above T0 (the
  /// friction force: a larger force slides the shell by itself); 0 < bound_alpha < 1.
  double bound_alpha = kNaN;
  /// Global stage over the box, by NLopt name or HALTON (a Halton sampling of the box; see
  /// ReachGlobalAlgorithmNames()).
  std::string global_algorithm = "GN_DIRECT_L";
  /// Local polish from the best point of the global stage (ReachLocalAlgorithmNames()).
  std::string local_algorithm = "LN_SBPLX";
  int global_evaluations = 150;  ///< from-rest evaluations of the global stage; >= 1
  int local_evaluations = 50;    ///< from-rest evaluations of the local polish; >= 0
  /// Wall-clock limit of the search (the starting drives' scores, the global and local stages),
  /// seconds; > 0. It also ends an evaluation under way (its starts poll it after every block),
  /// which then does not count; the status is then kMaxTime. The re-checks of the candidates
  /// with the full settings come on top (a handful of from-rest runs). Infinity:
  /// none; the evaluation budgets alone bound the search, and the result no longer depends on
  /// the machine's speed (deterministic: what a sweep needs).
  double max_seconds = 20.0;
  /// Relative tolerance of the local polish on y and on the mean velocity; > 0.
  double rel_tol = 1e-4;
  /// Best points of the search (besides the seed) re-checked with the full settings; >= 1.
  int candidates = 3;
  /// The candidates differ by more than this in some coordinate of the search box (0: any two
  /// distinct points); 0 <= candidates_apart < 1.
  double candidates_apart = 0.0;
  /// A candidate wins only if its mean velocity changes by at most max_spread (relative) under
  /// the other chatter cut-offs of ReachSpread, by at most max_elastic_change for the nearly
  /// elastic robot (e = 0.999 at e = 1: a physical change, so that a motion that relies on
  /// perfectly elastic impacts does not win), and no start ends in event_limit there; when no
  /// candidate passes, the fastest is reported with robust_to_settings = false. Both >= 0.
  double max_spread = 0.01;
  double max_elastic_change = 0.1;
  unsigned seed = 1;  ///< seed of NLopt's random numbers (GN_CRS2_LM, GN_ISRES)
  /// From-rest settings inside the search (cheap).
  FromRestOptions search = CheapFromRestOptions();
  /// From-rest settings of the re-check, the reported attractors and the spread (full).
  FromRestOptions check;
  /// The seed: the robust gait of P2 (docs/model.md section 12), the same as the main job of
  /// `capsubot optimize`: its margins and spectral radius <= kRobustRhoMax here, force bound
  /// from force_bound.
  ForcingDesignOptions seed_design = RobustSeedDesign();

  // Defined out of line: GCC 12 misreads the value-initialised temporaries of this aggregate
  // (its interrupts "may be used uninitialized").
  ReachOptions();
  /// Throws std::invalid_argument naming the first bad field, its value and the rule.
  void Validate() const;
};

/// The mean velocity of the winner re-simulated with other numerical settings (full from-rest
/// settings); NaN when not computed or when a start ended in event_limit there.
struct ReachSpread {
  double chatter_small = kNaN;  ///< chatter_velocity / 100
  double chatter_large = kNaN;  ///< chatter_velocity * 100
  double e_0999 = kNaN;         ///< restitution 0.999 (computed only when e = 1)
  /// Largest |variant - mean_velocity| / |mean_velocity| over the computed variants (NaN if
  /// none); +inf when a variant ended in event_limit.
  double max_relative_deviation = kNaN;
  std::int64_t event_limit_starts = 0;  ///< event_limit starts over the variants
};

/// The seed of the reach search: the robust one-impact gait and how it fares from rest.
struct ReachSeed {
  OptimizeResult gait;     ///< the P2 gait (its solution: force with impact phase, alpha, I)
  GaitFromRest from_rest;  ///< checked from rest with the full settings (checked = false if none)
};

struct ReachResult {
  /// kOk (search converged or used its budget), kMaxTime (the wall-clock limit stopped the
  /// search; the best point is kept; when it came before the search evaluated anything, the
  /// winner is the best starting drive and the message says so), kNoValidOrbit (every
  /// candidate had an event_limit start).
  OptimizeStatus status = OptimizeStatus::kNotRun;
  std::string message;  ///< one readable sentence
  /// The winner's force (A sin(phi + phi0) + c, or a Fourier series for a Fourier family);
  /// phi0 is the seed's impact phase (the motor phase from which the start phases psi are
  /// counted).
  Forcing forcing;
  DriveFamily drive;            ///< the family searched
  double max_abs_force = kNaN;  ///< the winner's max |F| (exact; <= the bound)
  double force_bound = kNaN;    ///< the bound the winner kept (tied to its T0 when free)
  double T0 = kNaN;             ///< the winner's T0 (the robot's unless T0 was free)
  /// With T0 free: the winner's speed in units of sqrt(mu g L), mean_velocity / sqrt(T0).
  double physical_speed = kNaN;
  double alpha = kNaN;          ///< the winner's mass ratio
  double mean_velocity = kNaN;  ///< mean over the full start grid (units of omega L)
  Attractors attractors;        ///< of the winner, full settings
  std::string summary;          ///< the attractors in one sentence (AttractorsSummary)
  ReachSpread spread;           ///< dependence on the numerical settings
  bool seed_won = false;        ///< the seed itself is the winner
  /// The winner passed the spread test (ReachOptions::max_spread, max_elastic_change).
  bool robust_to_settings = false;
  int evaluations = 0;  ///< from-rest evaluations (search and re-checks)
  /// Search evaluations rejected because a start ended in event_limit.
  int rejected_evaluations = 0;
  double search_seconds = kNaN;  ///< wall-clock time of the search stage
  std::string algorithm;         ///< e.g. "GN_DIRECT_L+LN_SBPLX"
  ReachSeed seed;                ///< the seed and its from-rest check
};

/// The fastest motion from rest with A + c <= bound, seeded by the robust P2 gait (computed
/// with options.seed_design: its margins and rho_max, on params). Throws std::invalid_argument
/// for bad params or options. Every evaluation asks options.search.attractor.interrupt, the
/// re-checks options.check.attractor.interrupt, the seed's P2 options.seed_design.interrupt
/// (interrupt.hpp): set all three to abandon the run from outside.
ReachResult OptimizeReach(const Params& params, const ReachOptions& options = {});

/// The same, seeded by a given P2 result (e.g. one already computed by the caller; its force
/// must be of the paper's family). Without a valid seed the search still runs, from the box.
/// It asks the interrupts of options.search and options.check.
ReachResult OptimizeReach(const Params& params, const OptimizeResult& seed,
                          const ReachOptions& options = {});

}  // namespace capsubot
