#pragma once
// `capsubot periodic` as one call (docs/model.md section 13): a periodic motion of any kind found
// exactly by Newton's method on the p-th iterate of the stroboscopic map, with its multipliers.

#include <variant>

#include "capsubot/attract/periodic.hpp"
#include "capsubot/job/stage_callback.hpp"
#include "capsubot/model/forcing.hpp"
#include "capsubot/model/params.hpp"
#include "capsubot/model/robot_model.hpp"
#include "capsubot/numerics/not_computed.hpp"

namespace capsubot {

/// From a given state, taken to be near the motion: no transient unless one is given.
struct PeriodicFromState {
  PhaseState state;   ///< x, u, v at forcing phase psi (a finite phase, RequirePhase)
  int transient = 0;  ///< periods simulated before the period is sought; >= 0
};

/// From rest at x0 and forcing phase psi, after a transient that brings the start near its
/// long-run motion.
struct PeriodicFromRest {
  double x0 = kNaN;     ///< position of the inner body; 0 <= x0 <= 1
  double psi = kNaN;    ///< forcing phase [rad] (RequirePhase)
  int transient = 200;  ///< periods simulated before the period is sought; >= 0
};

/// The period known: Newton's method from the state itself, whose phase is the section (no
/// transient, no search of the period: ShootPeriodicMotion).
struct PeriodicOfPeriod {
  PhaseState state;  ///< x, u, v at forcing phase psi
  int period = 1;    ///< p in forcing periods; 1 <= p <= 64
};

/// Where Newton's method starts.
using PeriodicStart = std::variant<PeriodicFromState, PeriodicFromRest, PeriodicOfPeriod>;

struct PeriodicJobOptions {
  /// The force F = G(psi + phi0) at the start's phase psi, T0, e and the mass ratio
  /// m2/(m1+m2), 0 < alpha < 1.
  RobotModel robot;
  PeriodicStart start;  ///< a state, from rest, or a state with its period
  /// Newton's method and the simulator (max_period, step, chatter_velocity, ..., interrupt);
  /// its transient is the start's (set by the job).
  ShootingOptions shooting;
  StageCallback on_stage;  ///< told the stage ("periodic: Newton shooting"), "" when done

  /// Throws std::invalid_argument for a start phase that is no phase (RequirePhase, naming psi);
  /// the other fields are checked by the shooting itself.
  void Validate() const;
};

struct PeriodicJobResult {
  PeriodicJobOptions options;  ///< the options it ran with (its callbacks cleared)
  PeriodicMotion motion;       ///< the motion found (its status says whether Newton converged)
};

/// The periodic motion near options.start (FindPeriodicMotion, or ShootPeriodicMotion with the
/// period known). Throws std::invalid_argument for bad options; outcomes are statuses.
PeriodicJobResult RunPeriodicJob(const PeriodicJobOptions& options);

}  // namespace capsubot
