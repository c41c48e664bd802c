#pragma once
// Exact event-driven simulation of the full non-smooth dynamics (docs/model.md sections 3 and 10):
// the independent ground truth for the analytic orbit. It uses only the force (F, Pi, Phi,
// Crossings, Bounds) and the parameters, never the analytic orbit code.
//
// Inside each mode the motion is in closed form; events are located by exact bracketing on
// pieces where the event function is monotone, convex or concave (cut at the crossings of F
// with known levels), then Halley's iteration kept in the bracket, to a few ulp in phase.
// See docs/simulate.md for why no event is missed, and for the energy budget (docs/model.md
// section 11).

#include <cstdint>
#include <string>

#include "capsubot/model/energy.hpp"
#include "capsubot/model/forcing.hpp"
#include "capsubot/model/params.hpp"
#include "capsubot/numerics/not_computed.hpp"

namespace capsubot {

/// The modes of docs/model.md section 3, plus the inner body resting on a wall (after chattering,
/// or an e = 0 impact while pressed against the wall): then u = 0 and it moves with the capsule.
enum class SimMode {
  kRest,           ///< capsule at rest (v = 0), inner body free
  kSlideForward,   ///< v > 0, inner body free
  kSlideBackward,  ///< v < 0, inner body free
  kOnRightWall,    ///< inner body resting on the right wall (x = 1, u = 0); capsule rests or slides
  kOnLeftWall,     ///< inner body resting on the left wall (x = 0, u = 0); capsule rests or slides
};

enum class EventKind {
  kImpactRight,  ///< x = 1 with u > 0: u -> -e u, v -> v + alpha (1+e) u
  kImpactLeft,   ///< x = 0 with u < 0: same law
  kStop,         ///< v reaches 0 while sliding (then rest, or reversal if |F| > T0)
  kBreakaway,    ///< at rest, |F| reaches T0: the capsule starts to slide
  kStick,        ///< the inner body comes to rest on a wall (end of a chattering sequence)
  kRelease,      ///< the inner body leaves the wall it rested on (contact force changes sign)
};

/// Stable identifiers used in CSV and JSON ("impact_right", "stop", ...).
const char* EventKindName(EventKind kind);
const char* SimModeName(SimMode mode);

/// The full state at a phase. y is the capsule position (units of L).
struct SimState {
  double phi = kNaN;  ///< phase since the start of the simulation
  double x = kNaN;    ///< relative position of the inner body (walls at 0 and 1)
  double u = kNaN;    ///< relative velocity x'
  double v = kNaN;    ///< capsule velocity
  double y = kNaN;    ///< capsule position
  SimMode mode = SimMode::kRest;
};

/// One event: the state right after it, and u, v right before it (they differ at impacts).
struct SimEvent {
  EventKind kind = EventKind::kStop;
  SimState after;          ///< state right after the event (its phase is the event's phase)
  double u_before = kNaN;  ///< relative velocity right before (the impact velocity)
  double v_before = kNaN;  ///< capsule velocity right before
};

/// Receives events and trajectory samples (optional; the hot path passes none).
class SimObserver {
 public:
  virtual ~SimObserver() = default;
  virtual void OnEvent(const SimEvent& event) { (void)event; }
  /// Called at phases k * sample_step (k = 0, 1, ...) up to the end, in order.
  virtual void OnSample(const SimState& state) { (void)state; }
  /// Called when the run passes into a new forcing period (for progress reports): `periods`
  /// whole periods are done. At most once per period; several periods without an event
  /// may be reported at once.
  virtual void OnPeriods(std::int64_t periods) { (void)periods; }
  /// Asked right after each OnSample: true ends the run there, as if its end phase were that
  /// sample's (the final state is the sample's state; the figures are those up to it). Lets an
  /// observer stop a long run once it has seen enough without restarting the simulation, so
  /// the trajectory up to that point is the same, bit for bit, as that of a run to the end.
  virtual bool Done() { return false; }
};

struct SimOptions {
  double alpha = kNaN;  ///< mass ratio m2/(m1+m2); 0 < alpha < 1
  double x0 = kNaN;     ///< initial relative position; 0 <= x0 <= 1
  double u0 = kNaN;     ///< initial relative velocity (finite)
  double v0 = kNaN;     ///< initial capsule velocity (finite)
  double y0 = 0.0;      ///< initial capsule position (finite)
  /// Periods run first and tallied apart (SimResult::transient); 0 <= transient <= 1e8.
  double transient = 0.0;
  /// Periods recorded after the transient: phi runs over [0, (transient + periods) tau];
  /// 0 < periods <= 1e8.
  double periods = 1.0;
  /// Stop right after this many right-wall impacts over the whole run, transient included
  /// (0: no limit). An impact at phi = 0 counts.
  std::int64_t max_impacts_right = 0;
  /// A chattering sequence (impacts on one wall with shrinking speeds, docs/model.md section 14)
  /// is ended at its accumulation point, extrapolated from its last impacts, once the error of
  /// the accumulation phase (estimated from the change of the extrapolation over one impact)
  /// is below this, and the ratio of successive speeds is steady and below 1 (docs/simulate.md
  /// "Chattering"); the body then rests on the wall. Finite, > 0.
  double chatter_tolerance = 1e-10;
  /// Fallback of the rule above: an impact slower than this (|u| before it), with at least
  /// five impacts in its sequence, ends the sequence at the extrapolated accumulation point if
  /// the speeds shrink steadily; if they do not shrink (e = 1 without loss) and the relative
  /// acceleration pushes the body into the wall, as a plastic impact (u+ = 0), the body then
  /// resting on the wall; a sequence that shrinks but not yet steadily goes on. Finite, > 0.
  double chatter_velocity = 1e-6;
  /// Work bound: at most this many events per simulated period (then status kEventLimit). >= 10.
  /// The total, this times ceil(periods), saturates at the largest std::int64_t (no overflow).
  std::int64_t max_events_per_period = 100000;
  /// Phase step of OnSample calls (0: no samples); >= 0.
  double sample_step = 0.0;
  /// Accumulate the energy budget (SimTally::energy; docs/model.md section 11). It costs about
  /// half again the time per period (the positive part needs the sign changes of F u), so the
  /// hot path leaves it off; the budget is NaN then.
  bool energy = false;
  /// Reuse located events along a repeated cycle: once the state at the first event search of
  /// a period (mode, slide, phase within the period, x, u, v) equals, bit for bit, that of one
  /// of the last 64 periods, the events of the next cycle are recorded and, when the cycle
  /// closes, taken again instead of searched (the search is a function of that state alone;
  /// docs/simulate.md "Repeated cycles"). Every event is still applied and reported, so the
  /// run is the same bit for bit; false searches every event (to time the search itself).
  bool reuse_cycles = true;

  /// Throws std::invalid_argument naming the first bad field, its value and the rule.
  void Validate() const;
};

enum class SimStatus {
  kNotRun,       ///< not computed
  kOk,           ///< reached the end phase
  kImpactLimit,  ///< stopped right after max_impacts_right right-wall impacts
  kEventLimit,   ///< the work bound was hit (message says where); the state is where it stopped
  /// The state stopped being finite numbers (a velocity or position beyond double precision,
  /// e.g. a huge v0): the run stops there, message says where; the final state is that state.
  kNonFinite,
};

/// Stable identifier of a status ("ok", "impact_limit", "event_limit", "non_finite").
const char* SimStatusName(SimStatus status);

/// What happened over a span of the run (the record after the transient, or the transient).
struct SimTally {
  std::int64_t impacts_right = 0;
  std::int64_t impacts_left = 0;
  std::int64_t stops = 0;
  std::int64_t breakaways = 0;
  std::int64_t sticks = 0;     ///< chattering sequences ended with the body resting on a wall
  std::int64_t releases = 0;   ///< departures from a wall after resting on it
  std::int64_t events = 0;     ///< all events
  double span = kNaN;          ///< length of the span in phase
  double displacement = kNaN;  ///< y at its end minus y at its start
  double v_mean = kNaN;        ///< displacement / span
  /// Exact energy budget of the span (SimOptions::energy; NaN otherwise). Over any span,
  /// motor_work = friction_loss + impact_loss + change of the kinetic energy
  /// ((1-alpha) v^2 + alpha (v+u)^2)/2. A sequence ended at its accumulation point adds the
  /// extrapolated tallies of its remaining impacts and flights; one ended by the plastic
  /// fallback counts it as a plastic impact (it removes alpha (1-alpha) u^2/2).
  Energy energy;
};

/// The figures of the record (after the transient) are the SimTally base; the transient's are
/// apart.
struct SimResult : SimTally {
  SimStatus status = SimStatus::kNotRun;
  std::string message;   ///< why the run stopped early (kEventLimit, kNonFinite), else empty
  SimState final_state;  ///< state at the end (after any event at the end phase)
  /// The first SimOptions::transient periods (all zero/NaN when there is none). A run stopped
  /// inside the transient (impact or event limit) has all its figures here and an empty record.
  SimTally transient;
  /// Events of the whole run whose location was taken from an earlier, identical state
  /// (SimOptions::reuse_cycles) instead of searched.
  std::int64_t reused_events = 0;
};

/// Simulates the model of docs/model.md section 3 from the initial state of `options`, with the
/// force F(phi) = forcing.F(phi), phi = 0 at the start. Validates params and options
/// (std::invalid_argument); expected outcomes are statuses, never exceptions. An event within
/// kEndSlack of the end phase is processed before stopping, so a run of whole periods from a
/// post-impact state of a periodic orbit ends right after the closing impact.
SimResult Simulate(const Forcing& forcing, const Params& params, const SimOptions& options,
                   SimObserver* observer = nullptr);

inline constexpr double kEndSlack = 1e-10;  ///< phase tolerance of the end (see Simulate)

}  // namespace capsubot
