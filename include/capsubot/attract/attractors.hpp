#pragma once
// The long-run motion of the robot and the attractors it reaches from rest (docs/model.md
// sections 12 and 13), found with the exact simulator (simulator.hpp).
//
// The stroboscopic map takes the state (x, u, v) at a forcing phase psi to the state one forcing
// period later; the capsule position drifts and is not part of the state. A start is simulated
// for a transient, then recorded; the period p of its long-run motion is the smallest p whose
// p-th iterate returns to the same state (x, u, v and mode) within a tolerance. The section is
// placed in the middle of the largest gap between the events (impacts, stops, ...) of the last
// periods of the transient, so no sample falls on an impact or a stick-slip switch.
//
// Starts whose motions agree (same status, period and impact counts, mean velocities within a
// relative tolerance) form one attractor. Every function here is deterministic (the same
// numbers for any thread count), prints nothing and may be called many times.

#include <cstdint>
#include <functional>
#include <vector>

#include "capsubot/attract/start_grid.hpp"
#include "capsubot/model/forcing.hpp"
#include "capsubot/model/interrupt.hpp"
#include "capsubot/model/params.hpp"
#include "capsubot/model/robot_model.hpp"
#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/orbit/orbit.hpp"
#include "capsubot/parallel/blocks.hpp"
#include "capsubot/simulate/simulator.hpp"

namespace capsubot {

/// A state of the robot at a forcing phase: a start, or a point of the stroboscopic map.
/// psi is the forcing phase: there F = G(psi + phi0), A sin(psi + phi0) + c for the paper's
/// family (phi0 the forcing's own phase).
struct PhaseState {
  double x = kNaN;    ///< relative position of the inner body (walls at 0 and 1)
  double u = kNaN;    ///< relative velocity x'
  double v = kNaN;    ///< capsule velocity
  double psi = kNaN;  ///< forcing phase, in [0, tau)
};

/// Checks a mass ratio and a start state before a run: throws std::invalid_argument naming the
/// bad value (the simulator's rules for alpha, x, u and v; a finite psi).
void ValidateStart(double alpha, const PhaseState& start);

/// The most periods a long run records (MotionOptions::record): the record holds about 50
/// bytes a period per thread (its section states and impacts), 0.5 GB at this bound.
inline constexpr int kMaxRecord = 10000000;

/// How a long-run motion is simulated and classified.
struct MotionOptions {
  int transient = 200;  ///< periods simulated before the record; >= 0
  int record = 100;     ///< periods recorded; 2 * max_period <= record <= kMaxRecord
  int max_period = 8;   ///< largest period searched, in forcing periods; 1 <= p <= 64
  /// Two section states are the same when their modes agree and x, u and v differ by at most
  /// this (units of L and omega L); > 0.
  double state_tolerance = 1e-6;
  /// Early stop: the transient runs in chunks of 2 max_period periods, and a motion whose
  /// section states already repeat with period p to this tolerance (at a section clear of every
  /// event) is taken as periodic at once: the rest of the run would only repeat it. Its mean
  /// velocity is then taken over the whole periods p of the last chunk. >= 0; 0 always runs the
  /// full transient and record.
  double converged_tolerance = 1e-11;
  /// The simulator's chatter cut-off (SimOptions::chatter_velocity); > 0.
  double chatter_velocity = 1e-6;
  /// Work bound per simulated period (SimOptions::max_events_per_period): a start that needs
  /// more ends with status kEventLimit (a Zeno sequence of impacts); >= 10.
  std::int64_t max_events_per_period = 1000;
  /// The simulator's reuse of located events along repeated cycles
  /// (SimOptions::reuse_cycles): the same results bit for bit; false only to time the search.
  bool reuse_cycles = true;

  /// Throws std::invalid_argument naming the first bad field, its value and the rule.
  void Validate() const;
};

enum class MotionStatus {
  kNotRun,      ///< not computed
  kPeriodic,    ///< a period p <= max_period was found
  kNoPeriod,    ///< no period up to max_period (not converged, quasi-periodic or chaotic)
  kEventLimit,  ///< the simulation hit the work bound (a Zeno sequence): no motion reported
};

/// Stable identifier ("periodic", "no_period", "event_limit", "not_run").
const char* MotionStatusName(MotionStatus status);

/// The long-run motion from one start.
struct Motion {
  MotionStatus status = MotionStatus::kNotRun;
  int period = 0;  ///< p in forcing periods; 0 unless kPeriodic
  /// Right-wall impacts per p periods (kPeriodic); over the whole record otherwise.
  std::int64_t impacts_right = 0;
  std::int64_t impacts_left = 0;  ///< left-wall impacts, counted the same way
  /// Mean capsule velocity (units of omega L): kPeriodic, that of the periodic motion Newton's
  /// method finds (displacement over one period p from its fixed point / (p tau)), or, when
  /// Newton fails, over the whole periods p at the end of the record; kNoPeriod, displacement
  /// over the whole record / (record tau), as a direct simulation of the start gives it; NaN
  /// for kEventLimit.
  double mean_velocity = kNaN;
  /// kNoPeriod: the mean velocity over the first and the second half of the record (they tell
  /// whether the record is long enough for the mean to settle); kPeriodic: mean_velocity.
  double first_half_velocity = kNaN;
  double second_half_velocity = kNaN;
  /// kPeriodic: the fixed point of the p-th iterate at a section clear of its events (refined)
  /// or the last state of the record; otherwise the state at the end of the record.
  PhaseState section;
  SimMode mode = SimMode::kRest;  ///< the mode there
  /// Newton's method found the periodic motion (kPeriodic): period, impacts, velocity and
  /// multipliers are exact; false when they come from the record alone.
  bool refined = false;
  double spectral_radius = kNaN;  ///< largest modulus of the multipliers (refined only)
  double multiplier_re = kNaN;    ///< the multiplier of largest modulus (refined only)
  double multiplier_im = kNaN;
};

/// The long-run motion from `start` (docs/model.md section 13): simulate options.transient
/// periods, place the section, record options.record periods and classify. Throws
/// std::invalid_argument for bad params, alpha, start or options; simulator outcomes (an event
/// limit) are statuses.
Motion LongRunMotion(const RobotModel& robot, const PhaseState& start,
                     const MotionOptions& options);

/// A start from rest (docs/model.md section 12): x = x0, u = v = 0 at forcing phase psi.
PhaseState RestStart(double x0, double psi);

/// Cell (i, j) of the n_x x n_psi grid of starts from rest: x0 = (i + 0.5)/n_x,
/// psi = tau j / n_psi.
PhaseState GridStart(int i, int j, int n_x, int n_psi);

/// Every cell of that grid, i = 0..n_x-1 (outer), j = 0..n_psi-1 (inner); none when a size is
/// below 1.
std::vector<PhaseState> GridStarts(int n_x, int n_psi);

/// Progress of a classification of many starts: starts done of total. Called from worker
/// threads under a lock, in increasing order of `done`; must be cheap.
using StartsProgress = std::function<void(std::int64_t done, std::int64_t total)>;

/// How starts are grouped into attractors.
struct AttractorOptions {
  MotionOptions motion;  ///< simulation and classification of each start
  /// Two periodic motions with the same period belong to one attractor when their mean
  /// velocities differ by at most this times the larger magnitude; >= 0. (Newton's method gives
  /// both exactly; impact counts are not compared: a chattering sequence may be cut after a
  /// different number of impacts.)
  double velocity_tolerance = 1e-6;
  /// Motions with no period form one irregular attractor per cluster of mean velocity: sorted
  /// by mean velocity, neighbours within this times the larger magnitude are in one cluster;
  /// >= 0.
  double irregular_tolerance = 0.1;
  /// A periodic motion is the analytic one-impact orbit when its section state is within this
  /// of the orbit's state (x, u, v, units of L and omega L); > 0.
  double orbit_tolerance = 1e-6;
  int threads = 0;  ///< worker threads; 0: all cores. The result does not depend on it.
  /// Asked on the calling thread after every block of starts (interrupt.hpp); throws to
  /// abandon the run (the worker threads finish their blocks first).
  Interrupt interrupt;

  /// Throws std::invalid_argument naming the first bad field, its value and the rule.
  void Validate() const;
};

/// One attractor: a class of starts with the same long-run motion.
struct Attractor {
  Motion motion;            ///< the motion of its example start
  PhaseState example;       ///< the first start (in the order given) that reaches it
  std::int64_t starts = 0;  ///< how many starts reach it
  double fraction = 0.0;    ///< starts / all starts
  /// The analytic one-impact orbit of this robot (docs/model.md sections 4 and 8): period 1,
  /// one right impact, no left impact, and the section state on the orbit.
  bool one_impact_orbit = false;
  /// Mean, smallest and largest mean velocity over its starts (they differ only for an
  /// irregular motion).
  double mean_velocity = kNaN;
  double velocity_min = kNaN;
  double velocity_max = kNaN;
  /// Largest difference between the mean velocities of the two halves of a start's record,
  /// relative to the attractor's mean velocity (0 for a periodic motion): below 1 % the
  /// record is long enough for the mean to settle.
  double halves_difference = 0.0;
};

/// An irregular attractor's record is long enough when the halves of every start's record
/// agree to this (relative).
inline constexpr double kSettledHalves = 0.01;

/// The attractors reached from a set of starts.
struct Attractors {
  std::int64_t starts = 0;              ///< number of starts
  std::vector<Attractor> attractors;    ///< by starts, most first (ties: first reached first)
  std::vector<Motion> motions;          ///< the motion of every start, in the order given
  std::vector<int> labels;              ///< index into `attractors` of every start
  double mean_velocity = kNaN;          ///< mean over the starts that did not hit the work bound
  std::int64_t event_limit_starts = 0;  ///< starts that ended in kEventLimit
};

/// The long-run motion of every start, in the order given, computed in blocks of starts by
/// `backend` (this process's threads by default). Throws std::invalid_argument for bad inputs
/// (naming the field).
std::vector<Motion> LongRunMotions(const RobotModel& robot, const std::vector<PhaseState>& starts,
                                   const AttractorOptions& options,
                                   const StartsProgress& progress = {},
                                   const BlockBackend& backend = LocalBlocks());

/// Receives the motions of starts [begin, end) (end - begin of them), block after block in
/// the order of the starts, on the calling thread.
using MotionSink = std::function<void(std::int64_t begin, std::int64_t end, const Motion* motions)>;

/// LongRunMotions of starts [first, starts.size()) handed to `sink` block by block as they are
/// done (a writer streams them to a file; what `sink` throws stops the run and is rethrown),
/// options.interrupt asked after each. The motions do not depend on `first`, the backend or
/// the threads. Throws
/// std::invalid_argument for bad inputs (naming the field) before any call of `sink`.
void StreamLongRunMotions(const RobotModel& robot, const std::vector<PhaseState>& starts,
                          const AttractorOptions& options, std::int64_t first,
                          const MotionSink& sink, const BlockBackend& backend = LocalBlocks());

/// How motions are grouped into attractors (AttractorOptions' two tolerances).
struct Grouping {
  double velocity_tolerance = 1e-6;  ///< periodic motions (AttractorOptions)
  double irregular_tolerance = 0.1;  ///< motions with no period (AttractorOptions)
};

/// The motions of `starts` (one each, in the same order) grouped into attractors, as
/// ClassifyStarts groups them: periodic motions by period and mean velocity (within
/// `velocity_tolerance`, relative), motions with no period by clusters of mean velocity
/// (`irregular_tolerance`), starts that hit the work bound in one class; classes numbered in
/// the order of their first start, then sorted by starts, most first. The attractors'
/// one_impact_orbit is left false. Throws std::invalid_argument when the sizes differ.
Attractors GroupMotions(const std::vector<PhaseState>& starts, std::vector<Motion> motions,
                        const Grouping& grouping);

/// The long-run motion of every start (LongRunMotions) grouped into attractors (GroupMotions),
/// the one-impact orbits recognised. Throws
/// std::invalid_argument for bad inputs (naming the field).
Attractors ClassifyStarts(const RobotModel& robot, const std::vector<PhaseState>& starts,
                          const AttractorOptions& options, const StartsProgress& progress = {},
                          const BlockBackend& backend = LocalBlocks());

/// The computers of ClassifyStarts' blocks (blocks.hpp): unit i is starts[i], its bytes the
/// bytes of its Motion (processes of one machine type exchange them). The arguments must
/// outlive the computers. A distributed backend's workers compute with these.
BlockComputeFactory MotionBlocks(const RobotModel& robot, const std::vector<PhaseState>& starts,
                                 const AttractorOptions& options);

/// Starts from rest on the grid of GridStart.
struct FromRestOptions {
  int n_x = 8;                 ///< starting positions x0 = (i + 0.5)/n_x (StartGrid's rules)
  int n_psi = 8;               ///< starting forcing phases psi = tau j/n_psi (StartGrid's rules)
  AttractorOptions attractor;  ///< classification and grouping

  /// Throws std::invalid_argument naming the first bad field, its value and the rule (the
  /// sizes: StartGrid::Validate).
  void Validate() const;
};

/// The attractors reached from rest (docs/model.md section 12): starts in the order
/// i = 0..n_x-1 (outer), j = 0..n_psi-1 (inner).
Attractors FindAttractors(const RobotModel& robot, const FromRestOptions& options,
                          const StartsProgress& progress = {});

/// True when `motion` is the one-impact orbit `orbit` (docs/model.md section 4) of the robot
/// driven by `forcing`: period 1, one right and no left impact per period, and the section
/// state within `tolerance` of the orbit's state at that forcing phase. orbit.forcing must be
/// the same motor as `forcing` (its phi0 the motor phase at the impact, as FindRobotOrbits
/// returns it).
bool MatchesOrbit(const Motion& motion, const Forcing& forcing, const Orbit& orbit,
                  double tolerance);

/// How many starts of `attractors` end on the given one-impact orbit (MatchesOrbit).
std::int64_t CountReached(const Attractors& attractors, const Forcing& forcing, const Orbit& orbit,
                          double tolerance = 1e-6);

}  // namespace capsubot
