#pragma once
// `capsubot simulate` as one call (docs/model.md sections 3 and 10): the exact event-driven
// simulation from a given state or from right after the impact of the analytic orbit, its
// events and samples told to an observer (the command line streams them to CSV files, the
// Python module keeps them as arrays).

#include <cstdint>
#include <optional>
#include <variant>

#include "capsubot/job/stage_callback.hpp"
#include "capsubot/model/forcing.hpp"
#include "capsubot/model/params.hpp"
#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/orbit/validity.hpp"
#include "capsubot/simulate/simulator.hpp"

namespace capsubot {

/// From a given state of a robot of mass ratio alpha (the simulator's rules: SimOptions).
struct SimulateFromState {
  double alpha = kNaN;  ///< mass ratio m2/(m1+m2); 0 < alpha < 1
  double x0 = kNaN;     ///< position of the inner body [L]; 0 <= x0 <= 1
  double u0 = kNaN;     ///< relative velocity dx/dphi [omega L]
  double v0 = kNaN;     ///< capsule velocity [omega L]
};

/// From right after the impact of the analytic one-impact orbit of the force, T0 and e, with
/// its mass ratio (StartFromOrbit: x = 1, u = -e u, v = v_plus).
struct SimulateFromOrbit {};

/// Where the simulation starts.
using SimulateStart = std::variant<SimulateFromState, SimulateFromOrbit>;

struct SimulateJobOptions {
  Forcing forcing;      ///< the force F(phi) = G(phi + phi0), phi = 0 at the start
  Params params;        ///< T0 and e
  SimulateStart start;  ///< a state, or the analytic orbit
  /// The run: y0, periods, transient, chatter_velocity, max_events_per_period (at most
  /// kMaxEventsPerPeriod) and the simulator's other settings. The job sets its start (alpha,
  /// x0, u0, v0: the start's), its energy budget (on) and its sample_step.
  SimOptions sim;
  /// Sample the state samples_per_period times a period over the whole run, the transient too
  /// (observer->OnSample).
  bool trajectory = false;
  /// 1 <= samples_per_period <= kMaxSamplesPerPeriod, with trajectory at most
  /// kMaxTrajectoryRows samples over transient + periods.
  std::int64_t samples_per_period = 100;
  SimObserver* observer = nullptr;  ///< told every event, sample and period; null: nobody
  StageCallback on_stage;           ///< told the stage ("simulate: 10 periods"), "" when done

  /// Throws std::invalid_argument naming the first bad field, its value and the rule (params,
  /// samples_per_period, max_events_per_period, the trajectory's rows; the simulator's options
  /// with a given state).
  void Validate() const;
};

struct SimulateJobResult {
  SimulateJobOptions options;     ///< the options it ran with (its observer, callback cleared)
  SimOptions sim;                 ///< the simulator's options as run (the start filled in)
  std::optional<Solution> orbit;  ///< from the orbit: the orbit started from (its validity too)
  SimResult run;                  ///< the simulation (status ok, impact_limit or event_limit)
};

/// Simulates from options.start. Throws std::invalid_argument for bad options and when no
/// orbit exists to start from, std::runtime_error when the state stops being finite (status
/// non_finite; the observer has seen the run up to there), and what the observer throws.
SimulateJobResult RunSimulateJob(const SimulateJobOptions& options);

}  // namespace capsubot
