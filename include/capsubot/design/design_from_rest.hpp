#pragma once
// Designing a real robot, part two (docs/model.md sections 9, 11, 12 and 13): the inner mass m2
// (and the motor frequency, when a range is given) whose motion reached from rest is fastest in
// each direction, forward and backward. A robot can be mounted either way round, and a light
// inner body often drives the shell backward faster than any forward one-impact gait.
//
// Not an orbit formula: every candidate robot (m2, f) is simulated from the grid of starts from
// rest of FindAttractors with the user's motor, whatever motion it reaches (one or many impacts,
// one or both walls, a motor that slides the shell by itself). The objective is the mean
// velocity over the starts, in m/s so that frequencies compare: forward maximises it, backward
// maximises its negative. The search is the one of OptimizeReach: a global NLopt stage
// (DIRECT-L) over log m2 (and log f) with cheap from-rest settings, a local polish (Sbplx) from
// its best point, then the best distinct points re-checked with the full settings; the best of
// them wins. A point where a start ends in event_limit (a Zeno sequence) is infeasible.

#include <cstdint>
#include <functional>
#include <string>

#include "capsubot/attract/attractors.hpp"
#include "capsubot/design/design.hpp"
#include "capsubot/model/energy.hpp"
#include "capsubot/numerics/not_computed.hpp"

namespace capsubot {

/// Periods recorded by the re-check of the from-rest design: a motion without a period (the
/// fastest motions from rest often have none) is a time average over the record, whose
/// statistical error falls like one over its square root.
inline constexpr int kCheckRecord = 1000;

/// Most from-rest evaluations of a stage (global or local) of the from-rest design, per
/// direction.
inline constexpr int kMaxDesignFromRestEvaluations = 100000;

/// How the from-rest design searches and checks; defaults sized so that the example robot
/// takes a few seconds on one core.
struct DesignFromRestOptions {
  /// From-rest settings inside the search: 4 x 4 starts, 100 + 32 periods (CheapFromRestOptions).
  FromRestOptions search;
  /// From-rest settings of the re-check and of the reported attractors: 8 x 8 starts,
  /// 200 + kCheckRecord periods (a motion without a period is averaged over the whole record).
  FromRestOptions check;
  /// Global stage, by NLopt name (ReachGlobalAlgorithmNames()).
  std::string global_algorithm = "GN_DIRECT_L";
  /// Local polish from the best point of the global stage (ReachLocalAlgorithmNames()).
  std::string local_algorithm = "LN_SBPLX";
  /// From-rest evaluations of the global stage per direction (the two directions share the
  /// robots they both visit); >= 1.
  int global_evaluations = 100;
  int local_evaluations = 30;  ///< evaluations of the local polish per direction; >= 0
  /// Wall-clock limit of the search stages of both directions together, seconds; > 0. The
  /// re-checks come on top (at most 2 candidates robots per direction).
  double max_seconds = 20.0;
  double rel_tol = 1e-4;  ///< relative tolerance of the local polish on log m2 and log f; > 0
  int candidates = 3;     ///< best distinct search points re-checked per direction; >= 1

  DesignFromRestOptions();
  /// Throws std::invalid_argument naming the first bad field, its value and the rule.
  void Validate() const;
};

/// Direction of a from-rest design.
enum class Direction { kForward, kBackward };

/// Stable identifier ("forward", "backward").
const char* DirectionName(Direction direction);

enum class FromRestStatus {
  kNotRun,      ///< not computed
  kOk,          ///< found: the mean velocity over the starts is in the direction asked
  kNoMotion,    ///< no robot searched moves in this direction on average over the starts
  kEventLimit,  ///< every candidate had a start ending in event_limit (a Zeno sequence)
};

/// Stable identifier ("ok", "no_motion", "event_limit", "not_run").
const char* FromRestStatusName(FromRestStatus status);

/// The fastest motion from rest in one direction, in the user's units. Speeds and
/// displacements are signed (negative backward); the energy figures are the starts' average of
/// each attractor's budget per forcing period (Simulate with SimOptions::energy over whole
/// periods of the attractor), weighted by the fraction of starts that reach it.
struct FromRestBest {
  Direction direction = Direction::kForward;
  FromRestStatus status = FromRestStatus::kNotRun;
  double m2_kg = kNaN;         ///< inner mass [kg]
  double frequency_hz = kNaN;  ///< motor frequency [Hz]
  // Below: NaN unless status == kOk.
  double speed_mm_s = kNaN;       ///< mean shell velocity over the starts [mm/s], signed
  double displacement_mm = kNaN;  ///< mean displacement per forcing period [mm], signed
  /// Relative velocity of the inner body at the impact [m/s] when the most common attractor
  /// has exactly one impact per its period; NaN otherwise (ill-defined for several impacts).
  double impact_velocity_m_s = kNaN;
  double energy_mj = kNaN;          ///< motor work per forcing period [mJ]
  double power_mw = kNaN;           ///< mean motor power [mW]
  double power_positive_mw = kNaN;  ///< mean power of a drive that cannot recover energy [mW]
  double friction_loss_mj = kNaN;   ///< friction loss per period [mJ]
  double impact_loss_mj = kNaN;     ///< impact loss per period [mJ]
  double cot = kNaN;                ///< motor work / ((m1+m2) g |displacement|)
  double efficiency = kNaN;         ///< mu / COT = friction loss / motor work
  /// Fractions of the starts whose long-run motion goes forward (mean velocity > 0) and
  /// backward (< 0); both > 0 means the direction depends on the start.
  double forward_fraction = kNaN;
  double backward_fraction = kNaN;  ///< see forward_fraction

  DesignModel model;            ///< the dimensionless robot (T0, force, alpha, omega)
  double mean_velocity = kNaN;  ///< mean over the starts, units of omega L
  Attractors attractors;        ///< reached from the full grid of starts (options.check)
  Energy energy;                ///< the weighted budget per period, dimensionless
  std::string message;          ///< one readable sentence

  bool ok() const { return status == FromRestStatus::kOk; }
};

/// Both directions and the cost of the search.
struct DesignFromRestResult {
  FromRestBest forward;   ///< the fastest forward motion from rest
  FromRestBest backward;  ///< the fastest backward motion from rest
  int evaluations = 0;    ///< from-rest evaluations (search, both directions, and re-checks)
  /// Search evaluations rejected because a start ended in event_limit.
  int rejected_evaluations = 0;
  double search_seconds = kNaN;  ///< wall clock of the search
  bool max_time = false;         ///< the wall-clock limit stopped a search stage (best points kept)
};

/// Reports the stage of the from-rest design ("forward: global search"), `done` of `total`
/// evaluations of the whole run (total an upper bound; the last report, at the end of the run,
/// has total = done); must be cheap.
using DesignFromRestProgress =
    std::function<void(const std::string& stage, std::int64_t done, std::int64_t total)>;

/// The fastest motion reached from rest in each direction over m2 in [M2Min, M2Max] (and f in
/// the frequency range). The margins and rho_max of the input do not apply (they are those of
/// the one-impact gait). Throws std::invalid_argument for invalid input or options. Every
/// evaluation asks options.search.attractor.interrupt, the re-checks
/// options.check.attractor.interrupt (interrupt.hpp): set both to abandon the run from outside.
DesignFromRestResult DesignFromRest(const DesignInput& input,
                                    const DesignFromRestOptions& options = {},
                                    const DesignFromRestProgress& progress = {});

/// The from-rest motion of the robot (m2, f) checked with `from_rest` in the given direction,
/// in the user's units: attractors, mean velocity, weighted energy budget (status kNoMotion
/// when its mean velocity is not in the direction). Deterministic.
FromRestBest EvaluateFromRest(const DesignInput& input, double m2, double frequency,
                              Direction direction, const FromRestOptions& from_rest);

/// The same for the robot `model` (any force, phase included) with inner mass m2 [kg] at
/// frequency f [Hz] (model.omega = 2 pi f): the drive design's robots, whose force is not the
/// input's motor force. Validates nothing.
FromRestBest EvaluateModelFromRest(const DesignInput& input, const DesignModel& model, double m2,
                                   double frequency, Direction direction,
                                   const FromRestOptions& from_rest);

}  // namespace capsubot
