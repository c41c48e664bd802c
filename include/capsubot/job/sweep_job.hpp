#pragma once
// `capsubot sweep` as one call: a grid of parameters and what to compute at every point (the
// orbit of a given force, or the best gait of P1, P2, P3 or the reach search: docs/model.md
// sections 4-5, 7 and 13) in, the CSV file written by the sweep (capsubot/sweep/sweep.hpp) and
// what it did out. The job turns what a user gives (a force in parts, the mode's own defaults:
// the robust gait for the reach search) into the sweep's options.

#include <optional>
#include <string>
#include <variant>
#include <vector>

#include "capsubot/optimize/optimize_phase.hpp"
#include "capsubot/optimize/optimize_request.hpp"
#include "capsubot/reach/optimize_reach.hpp"
#include "capsubot/sweep/grid.hpp"
#include "capsubot/sweep/grid_file.hpp"
#include "capsubot/sweep/sweep.hpp"

namespace capsubot {

/// The force of a sweep that is given one (the orbit of a force, P1), in the parts a user gives:
/// a part the grid varies need not be given (the grid's value replaces it at every point).
/// Either the harmonic force A sin(phi + phi0) + c (A) or the Fourier force
/// c + sum_k (a_k cos k(phi+phi0) + b_k sin k(phi+phi0)) (sin, cos).
struct SweepForce {
  std::optional<double> A;  ///< amplitude A >= 0 [force]; none: 0 when A or b1 is gridded
  std::optional<double> c;  ///< mean force c [force]; none: 0 when c is gridded
  std::vector<double> sin;  ///< b_1..b_K of the Fourier force instead of A; empty: harmonic
  std::vector<double> cos;  ///< a_1..a_K (as many as sin); empty: all 0
};

/// No optimisation: the orbit of the given force and its validity at every point (Solve); with
/// a grid over alpha, every orbit of the robot with that mass ratio.
struct SweepOrbitMode {
  Params params;     ///< T0 and e, except the gridded ones
  Margins margins;   ///< the margins of the orbits' validity, except the gridded ones
  SweepForce force;  ///< the force, except the gridded parts
  /// Motor phase at the impact phi0 [rad]; none: the grid gives it (phi0), or the robot's
  /// orbits do (alpha: then it must be none).
  std::optional<double> phi0;
  bool stability = false;  ///< add the stability columns (docs/model.md section 8)
};

/// P1: the best impact phase phi0 for the force shape at every point (OptimizePhase).
struct SweepPhaseMode {
  Params params;           ///< T0 and e, except the gridded ones
  SweepForce force;        ///< the shape of the force (phi0 is what P1 finds)
  bool stability = false;  ///< add the stability columns
  /// P1's options: gait.margins and gait.rho_max (grids over them replace them), scan_points,
  /// tolerances.
  PhaseOptions phase;
};

/// P2: the best A, c, phi0 with max |F| <= the bound at every point (OptimizeForcing).
struct SweepForcingMode {
  Params params;           ///< T0 and e, except the gridded ones
  bool stability = false;  ///< add the stability columns
  /// The margins, the bound and rho_max (grids over them replace them) and the search effort;
  /// its harmonics are not used.
  SearchRequest search;
};

/// P3: the best force of `search.harmonics` harmonics with max |F| <= the bound
/// (OptimizeFourier).
struct SweepFourierMode {
  Params params;           ///< T0 and e, except the gridded ones
  bool stability = false;  ///< add the stability columns
  /// The margins, the bound, rho_max, harmonics and the search effort; its hops are not used.
  SearchRequest search;
};

/// The fastest motion from rest at every point (OptimizeReach), seeded by the robust gait of
/// P2 (docs/model.md section 12), as `capsubot optimize --problem reach`: the defaults are the
/// robust gait's margins and rho_max.
struct SweepReachMode {
  SweepReachMode();
  /// T0 and e, except the gridded ones.
  Params params;
  /// The seed's P2: the margins (default RobustMargins()), the bound (also the reach search's),
  /// rho_max (default kRobustRhoMax) and the search effort; its harmonics are not used.
  SearchRequest search;
  /// The search from rest: a fixed alpha (NaN: optimised), its grids of starts and evaluation
  /// budgets. Its force_bound is search.gait.force_bound's (must be NaN here) and max_seconds
  /// must stay infinite: the budgets bound each point, so the rows do not depend on the
  /// machine's speed.
  ReachOptions reach = SweepReachOptions();
};

/// What a sweep computes at each point; the alternatives follow SweepOptimize's order.
using SweepMode = std::variant<SweepOrbitMode, SweepPhaseMode, SweepForcingMode, SweepFourierMode,
                               SweepReachMode>;

/// The mode called `name` ("" or "none": the orbit; "phi0", "forcing", "fourier", "reach"),
/// with its defaults; throws ParseSweepOptimize's std::invalid_argument for another name.
SweepMode SweepModeNamed(const std::string& name);
/// The SweepOptimize of a mode.
SweepOptimize SweepModeOptimize(const SweepMode& mode);

struct SweepJobOptions {
  /// The grid (any number of axes, the first slowest): its parameters replace the values the
  /// mode gives at every point (docs/sweep.md).
  Grid grid;
  /// What to compute at each point, with the mode's own options.
  SweepMode mode;
  /// The CSV file: provenance comment lines, output path, shard, resume, threads, checkpoints.
  GridFileOptions file;
  /// Told after each block of rows (sweep.hpp); empty: nobody.
  SweepProgressCallback progress;

  /// Throws std::invalid_argument naming the first bad option, its value and the rule (a
  /// part of the force missing or given twice, a budget out of range, and every rule of
  /// SweepOptions::Validate).
  void Validate() const;
};

/// What a sweep job did.
struct SweepJobResult {
  SweepSummary summary;  ///< points, rows written, points resumed, threads, seconds
  std::string output;    ///< the file written ("-": standard output)
};

/// The sweep a job runs: its options checked and turned into the sweep's (the force built
/// from its parts, each mode's options). Throws what SweepJobOptions::Validate throws. The
/// blocks a distributed run's workers compute are SweepBlocks of it.
SweepOptions PlanSweepJob(const SweepJobOptions& options);

/// Runs the sweep of PlanSweepJob(options) (RunSweep: written to options.file.output, its
/// blocks computed by `backend`) and says what it did. Throws what RunSweep throws.
SweepJobResult RunSweepJob(const SweepJobOptions& options,
                           const BlockBackend& backend = LocalBlocks());

}  // namespace capsubot
