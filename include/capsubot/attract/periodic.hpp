#pragma once
// Periodic motions of any kind (multi-impact, two-wall, period-p) found exactly by Newton's
// method on the p-th iterate of the stroboscopic map, with their multipliers (docs/model.md
// section 13). The map is evaluated by the exact simulator; its Jacobian by central finite
// differences.
//
// The state at the section is (x, u, v) at a fixed forcing phase psi, but the mode there
// removes coordinates: with the capsule at rest only (x, u) are free (v = 0; a perturbation of
// v dies out within the period: multiplier 0), while sliding all three are; with the inner body
// resting on a wall only v is (x and u are fixed). The multipliers reported are those of the
// free coordinates. The section is placed in the middle of the largest gap between events, so
// the map is smooth there.

#include <complex>
#include <cstdint>
#include <vector>

#include "capsubot/attract/attractors.hpp"
#include "capsubot/model/interrupt.hpp"
#include "capsubot/numerics/not_computed.hpp"

namespace capsubot {

struct ShootingOptions {
  int transient = 0;   ///< periods simulated from the start before shooting; >= 0
  int max_period = 8;  ///< largest period searched, in forcing periods; 1 <= p <= 64
  /// Newton stops when max |P^p(z) - z| over x, u, v is at most this; > 0.
  double residual_tolerance = 1e-12;
  int max_iterations = 40;  ///< Newton iterations; >= 1
  /// Step of the central finite differences of the Jacobian (units of L and omega L); > 0.
  double step = 1e-6;
  double chatter_velocity = 1e-6;  ///< the simulator's chatter cut-off; > 0
  /// Work bound per simulated period (SimOptions::max_events_per_period); >= 10.
  std::int64_t max_events_per_period = 100000;
  /// The simulator's reuse of located events along repeated cycles
  /// (SimOptions::reuse_cycles): the same results bit for bit; false only to time the search.
  bool reuse_cycles = true;
  /// Asked before every evaluation of the map and at every period of the transient
  /// (interrupt.hpp); throws to abandon the run.
  Interrupt interrupt;

  /// Throws std::invalid_argument naming the first bad field, its value and the rule.
  void Validate() const;
};

enum class ShootingStatus {
  kNotRun,         ///< not computed
  kConverged,      ///< residual <= residual_tolerance
  kNoConvergence,  ///< Newton did not reach the tolerance in max_iterations (state: the best)
  kEventLimit,     ///< the simulation hit the work bound
};

/// Stable identifier ("converged", "no_convergence", "event_limit", "not_run").
const char* ShootingStatusName(ShootingStatus status);

struct PeriodicMotion {
  ShootingStatus status = ShootingStatus::kNotRun;
  int period = 0;                  ///< p in forcing periods
  std::int64_t impacts_right = 0;  ///< right-wall impacts per p periods
  std::int64_t impacts_left = 0;   ///< left-wall impacts per p periods
  double mean_velocity = kNaN;     ///< displacement over p periods / (p tau), units of omega L
  PhaseState state;                ///< the fixed point of the p-th iterate at its section
  SimMode mode = SimMode::kRest;   ///< mode at the section
  int dimension = 0;               ///< free coordinates at the section (see the file comment)
  /// Eigenvalues of the Jacobian of the p-th iterate in the free coordinates, largest modulus
  /// first.
  std::vector<std::complex<double>> multipliers;
  double spectral_radius = kNaN;          ///< largest modulus (0 when dimension is 0)
  bool stable = false;                    ///< spectral_radius < 1
  double distance_to_plus_one = kNaN;     ///< |lambda_max - 1| (fold)
  double distance_to_minus_one = kNaN;    ///< |lambda_max + 1| (period doubling)
  double distance_to_unit_circle = kNaN;  ///< | |lambda_max| - 1 |
  double residual = kNaN;                 ///< max |P^p(z) - z| at the reported state
  int iterations = 0;                     ///< Newton iterations used
  /// The state lies beyond the robot's scale (1e6 times its velocity scale 2 pi (max |F| + T0)
  /// / (alpha (1 - alpha))), where the map's rounding exceeds its change: never converged.
  bool out_of_scale = false;
};

/// The periodic motion near `start` (docs/model.md section 13): after options.transient periods,
/// the period p <= max_period is the one whose p-th iterate comes back closest (the smallest
/// such p within rounding), then Newton's method on P^p(z) - z. Throws std::invalid_argument
/// for bad params, alpha, start or options; outcomes are statuses.
PeriodicMotion FindPeriodicMotion(const RobotModel& robot, const PhaseState& start,
                                  const ShootingOptions& options);

/// The same with the period given (1 <= period <= 64) and no transient: Newton from `start`,
/// whose phase is taken as the section.
PeriodicMotion ShootPeriodicMotion(const RobotModel& robot, const PhaseState& start, int period,
                                   const ShootingOptions& options);

}  // namespace capsubot
