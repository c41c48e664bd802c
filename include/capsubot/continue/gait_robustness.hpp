#pragma once
// How far the model parameters T0, e and alpha can move before a gait's periodic motion is lost
// (docs/continuation.md, docs/optimize.md): the gait's one-impact orbit continued in each of
// them, both ways, up to the nearest special point (ContinueParameter).

#include <functional>
#include <string>
#include <vector>

#include "capsubot/continue/continuation.hpp"
#include "capsubot/continue/speed_band.hpp"
#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/orbit/orbit.hpp"

namespace capsubot {

/// Where the gait's motion ends or loses stability along one direction of a parameter: the
/// nearest fold, period doubling or Neimark-Sacker point, or else the end of the branch (range
/// end, lost: the continuation cannot go on, max points). Grazings and segment changes are no
/// limits: the motion goes on through them with other impacts or another stick/slide pattern
/// (ParameterRobustness::special_points lists them).
struct MotionLimit {
  bool special = false;                             ///< a special point (else the branch's end)
  SpecialPointType type = SpecialPointType::kFold;  ///< its type, when special
  BranchEnd end = BranchEnd::kNotRun;               ///< how the branch ended, when not special
  double parameter = kNaN;                          ///< the parameter's value there
  bool located = false;    ///< the special point was located to the location tolerance
  double accuracy = kNaN;  ///< width of its final bracket in the parameter (special points)
  PeriodicMotion motion;   ///< the motion there (special points only)

  /// The special point's type name ("fold", ...) or the end's ("range_end", "lost", ...).
  const char* Name() const;
  /// Plain words: what happens there and where, the parameter written as `name` = `value`
  /// (`value` the text of `parameter`, with its unit or more): "a grazing: an impact appears or
  /// disappears at e = 0.25", "no limit up to the end of the range, T0 = 0.02".
  std::string Text(const std::string& name, const std::string& value) const;
};

/// Writes a parameter's value (with its unit, a change in percent, ...).
using ValueText = std::function<std::string(double)>;

/// One parameter's continuation.
struct ParameterRobustness {
  std::string name;     ///< "T0", "e" or "alpha"
  double value = kNaN;  ///< the gait's value
  double from = kNaN;   ///< the range searched
  double to = kNaN;
  ContinuationStatus status = ContinuationStatus::kNotRun;  ///< the branch's status
  std::string message;                                      ///< why there is no branch, else empty
  MotionLimit down;  ///< the nearest limit below the gait's value (the branch's backward part)
  MotionLimit up;    ///< the nearest limit above it (the forward part)
  /// The branch's special points other than speed extrema and changes of a chattering count,
  /// in the order of the branch.
  std::vector<SpecialPoint> special_points;
  /// Grazings left out of `special_points`: only the number of impacts of a chattering sequence
  /// changed (a sequence on one wall that ends with the inner body resting on it, whose
  /// infinitely many impacts the simulator sums at their accumulation point after a number of
  /// its own choosing); per wall the sequences and the impacts outside them are the same on
  /// both sides. Not a bifurcation of the motion.
  int chatter_changes = 0;
  /// The speed band (RobustnessOptions::speed_bands; status kNotRun otherwise).
  SpeedBand band;

  /// The special points inside the band of its first level (none without a band), each once:
  /// the motion changes there, the speed from rest goes on.
  std::vector<SpecialPoint> InBand() const;
  /// Plain words for the band, one line per level, the special points inside it and the
  /// chattering counts left out, each line indented by `indent`; values written by `value`, the
  /// nominal speed as `speed`. Empty without a band.
  std::string BandText(const ValueText& value, const std::string& speed,
                       const std::string& indent) const;
};

struct RobustnessOptions {
  /// T0 is searched in [T0 / t0_factor, T0 t0_factor]; > 1. A friction coefficient is seldom
  /// known better than to a factor 2. (e is searched in [0, 1]; alpha halfway to each end of
  /// (0, 1), [alpha / 2, (1 + alpha) / 2].)
  double t0_factor = 2.0;
  /// The continuation of each parameter: from, to and start are set per parameter, the rest
  /// (steps, points, tolerances, shooting) is taken from here.
  ContinuationOptions continuation;
  /// Also find each parameter's speed band (speed_band.hpp) over the same range.
  bool speed_bands = false;
  /// The bands' levels, accuracy and starts from rest.
  SpeedBandOptions band;

  /// Throws std::invalid_argument naming the first bad field, its value and the rule.
  void Validate() const;
};

/// The three continuations, in the order T0, e, alpha.
struct GaitRobustness {
  std::vector<ParameterRobustness> parameters;

  /// Plain words, one line per parameter and direction, indented by `indent`.
  std::string Summary(const std::string& indent = "  ") const;
};

/// A periodic motion to continue: the robot (its force, T0 and e of its params, alpha) and a
/// state on the motion (a fixed point of its period map, as Newton shooting refines it).
struct MotionToContinue {
  RobotModel robot;
  PhaseState start;
};

/// One parameter of a robustness study: the robots along it and the range, in the family's own
/// parameter, and the factor from it to the parameter reported (a family in T0 over T0's value
/// has the range [1/2, 2] whatever T0, so its finite differences fit the range).
struct RobustnessParameter {
  std::string name;    ///< the name reported ("T0", "mu", "m2_kg")
  RobotFamily family;  ///< the robot at each value of the family's parameter
  double value = 1.0;  ///< the robot's value of it
  double from = 0.5;   ///< the range searched
  double to = 2.0;
  double scale = 1.0;  ///< reported value = the family's value times this; > 0
};

/// `family` (the robots at each value of a parameter) followed in the parameter over its value,
/// lambda = parameter / value, over [1/factor, factor] (factor > 1), reported as the parameter
/// times `unit` (1, or mu / T0 for a family in T0 reported in mu: T0 = mu g/(omega^2 L)).
RobustnessParameter RelativeParameter(const std::string& name, const RobotFamily& family,
                                      double value, double factor, double unit = 1.0);

/// The periodic motion through `start` followed along `p` over its range, both ways from its
/// value, the nearest limit each way and, with options.speed_bands, the speed band; every value
/// reported in the parameter's unit (p.scale). A part that cannot be computed (its
/// continuation's options or robots refused) says so in `status` (kNotRun) and `message`.
ParameterRobustness ContinueRobustness(const RobustnessParameter& p, const PhaseState& start,
                                       const RobustnessOptions& options);

/// Continues the periodic motion through `motion.start` in T0, e and alpha over the ranges of
/// `options` and reports the nearest limit each way. Throws std::invalid_argument for bad
/// options or invalid parameters.
GaitRobustness ComputeMotionRobustness(const MotionToContinue& motion,
                                       const RobustnessOptions& options);
/// The same with the default RobustnessOptions.
GaitRobustness ComputeMotionRobustness(const MotionToContinue& motion);

/// The speed bands alone (options.band) of `robot` in T0, e and alpha, over the ranges of
/// ComputeMotionRobustness, for a robot whose motion from rest is not one periodic motion to
/// continue: each parameter's status kNotRun with the message `why`.
GaitRobustness ComputeSpeedBands(const RobotModel& robot, const RobustnessOptions& options,
                                 const std::string& why);

/// Continues the one-impact orbit `orbit` (the gait: its force, alpha, T0 and e), started right
/// after its impact (OrbitImpactState), in T0, e and alpha over the ranges of `options`, and
/// reports the nearest limit each way. Throws std::invalid_argument for bad options or an
/// orbit whose parameters are invalid (ComputeMotionRobustness of that state).
GaitRobustness ComputeGaitRobustness(const Orbit& orbit, const RobustnessOptions& options);
/// The same with the default RobustnessOptions.
GaitRobustness ComputeGaitRobustness(const Orbit& orbit);

}  // namespace capsubot
