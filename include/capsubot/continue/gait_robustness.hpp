#pragma once
// How far the model parameters T0, e and alpha can move before a gait's periodic motion is lost
// (docs/continuation.md, docs/optimize.md): the gait's one-impact orbit continued in each of
// them, both ways, up to the nearest special point (ContinueParameter).

#include <limits>
#include <string>
#include <vector>

#include "capsubot/continue/continuation.hpp"
#include "capsubot/orbit/orbit.hpp"

namespace capsubot {

/// Where the gait's motion stops being itself along one direction of a parameter: the nearest
/// special point other than a speed extremum (a fold, period doubling, Neimark-Sacker point,
/// grazing or segment change: the motion ends, loses stability or changes its impacts or its
/// stick/slide pattern), or else the end of the branch (range end, lost, max points).
struct MotionLimit {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

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

/// One parameter's continuation.
struct ParameterRobustness {
  static constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

  std::string name;     ///< "T0", "e" or "alpha"
  double value = kNaN;  ///< the gait's value
  double from = kNaN;   ///< the range searched
  double to = kNaN;
  ContinuationStatus status = ContinuationStatus::kNotRun;  ///< the branch's status
  std::string message;                                      ///< why there is no branch, else empty
  MotionLimit down;  ///< the nearest limit below the gait's value (the branch's backward part)
  MotionLimit up;    ///< the nearest limit above it (the forward part)
};

struct RobustnessOptions {
  /// T0 is searched in [T0 / t0_factor, T0 t0_factor]; > 1. A friction coefficient is seldom
  /// known better than to a factor 2. (e is searched in [0, 1]; alpha halfway to each end of
  /// (0, 1), [alpha / 2, (1 + alpha) / 2].)
  double t0_factor = 2.0;
  /// The continuation of each parameter: from, to and start are set per parameter, the rest
  /// (steps, points, tolerances, shooting) is taken from here.
  ContinuationOptions continuation;

  /// Throws std::invalid_argument naming the first bad field, its value and the rule.
  void Validate() const;
};

/// The three continuations, in the order T0, e, alpha.
struct GaitRobustness {
  std::vector<ParameterRobustness> parameters;

  /// Plain words, one line per parameter and direction, indented by `indent`.
  std::string Summary(const std::string& indent = "  ") const;
};

/// A periodic motion to continue: the robot (force, T0 and e of `params`, alpha) and a state
/// on the motion (a fixed point of its period map, as Newton shooting refines it).
struct MotionToContinue {
  Forcing forcing;
  Params params;
  double alpha;
  PhaseState start;
};

/// The periodic motion through `start` followed along `family` (the robot at each value of the
/// parameter called `name`) over [from, to], both ways from the value `value` of `start`'s
/// robot, and the nearest limit each way. Throws std::invalid_argument as ContinueBranch does.
ParameterRobustness ContinueRobustness(const RobotFamily& family, const PhaseState& start,
                                       const std::string& name, double value, double from,
                                       double to, const ContinuationOptions& continuation);

/// Continues the periodic motion through `motion.start` in T0, e and alpha over the ranges of
/// `options` and reports the nearest limit each way. Throws std::invalid_argument for bad
/// options or invalid parameters.
GaitRobustness ComputeMotionRobustness(const MotionToContinue& motion,
                                       const RobustnessOptions& options = {});

/// Continues the one-impact orbit `orbit` (the gait: its force, alpha, T0 and e), started right
/// after its impact (OrbitImpactState), in T0, e and alpha over the ranges of `options`, and
/// reports the nearest limit each way. Throws std::invalid_argument for bad options or an
/// orbit whose parameters are invalid (ComputeMotionRobustness of that state).
GaitRobustness ComputeGaitRobustness(const Orbit& orbit, const RobustnessOptions& options = {});

}  // namespace capsubot
