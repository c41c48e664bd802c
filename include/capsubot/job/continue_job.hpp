#pragma once
// `capsubot continue` as one call (docs/continuation.md): a periodic motion followed through a
// range of one model parameter with its special points, and on request the branch switched to
// at its first period doubling (period 2p) or grazing (other impacts per period) and the
// two-parameter curve of its first special point of a given type. The command line and the
// Python module's continue_branch make this call.

#include <optional>
#include <string>
#include <variant>

#include "capsubot/continue/continuation.hpp"
#include "capsubot/continue/special_curve.hpp"
#include "capsubot/job/stage_callback.hpp"
#include "capsubot/model/forcing.hpp"
#include "capsubot/model/params.hpp"
#include "capsubot/model/robot_model.hpp"
#include "capsubot/numerics/not_computed.hpp"

namespace capsubot {

/// Start on the robot's valid one-impact orbit with the smallest spectral radius, right after
/// its impact (OneImpactOrbitStart, parameter_branch.hpp).
struct FromOneImpactOrbit {};

/// Where the branch starts: the robot's one-impact orbit, or a state (x in [0, 1], u, v at the
/// forcing phase psi [rad], |psi| <= 1e6) near the periodic motion.
using ContinueStart = std::variant<FromOneImpactOrbit, PhaseState>;

/// The two-parameter curve of the branch's first located special point of a type.
struct FollowOptions {
  std::string param2;   ///< the second parameter: a robot parameter other than the branch's
  double from2 = kNaN;  ///< lower end of its range (finite); the robot's value lies in the range
  double to2 = kNaN;    ///< upper end (finite, > from2)
  /// fold, period_doubling, grazing or speed_extremum (ParseFollowType reads the names).
  SpecialPointType type = SpecialPointType::kPeriodDoubling;
};

/// Where the branch is left for another (`--switch-at`, SwitchAtPeriodDoubling and
/// SwitchAtGrazing of branch_switch.hpp).
enum class SwitchPoint {
  kPeriodDoubling,  ///< the first located period doubling: the period-2p branch born there
  kGrazing,         ///< the first grazing: the motion with other impacts per period just beyond it
};

/// "period_doubling", "grazing".
const char* SwitchPointName(SwitchPoint point);

/// The SwitchPoint of that name; std::invalid_argument "switch = <name> is invalid: expected
/// period_doubling or grazing" otherwise.
SwitchPoint ParseSwitchPoint(const std::string& name);

struct ContinueJobOptions {
  RobotModel robot;  ///< the force, T0 > 0, 0 <= e <= 1, the mass ratio 0 < alpha < 1
  /// The parameter followed: A, c, alpha, T0, e, phi0, a1..a16, b1..b16 (a robot parameter of
  /// ModelParameter that the force has).
  std::string param;
  ContinueStart start;  ///< where the branch starts
  /// The range [from, to] (the robot's value of `param` lies in it: the branch starts there;
  /// `start` is set to it), steps, points, tolerances, the shooting and the interrupt; the
  /// switched branch and the curve take the same settings.
  ContinuationOptions continuation;
  /// Also follow the branch switched to at the branch's first point of this kind (none: no
  /// switch).
  std::optional<SwitchPoint> switch_at;
  /// Also follow the branch's first located special point of follow->type in (param, param2).
  std::optional<FollowOptions> follow;
  /// Told "continue: k/n <stage>" as the job enters each stage, and "" when it is done.
  StageCallback on_stage;

  /// Throws std::invalid_argument naming the first bad field, its value and the rule: the
  /// robot, the start's phase, the parameters' names, the ranges and the robot's values in
  /// them, the followed type.
  void Validate() const;
};

/// The branch of `switch_at`.
struct SwitchResult {
  SwitchPoint point = SwitchPoint::kPeriodDoubling;  ///< the kind of point switched at
  /// The point switched at: the first located period doubling, the first grazing (none: empty).
  std::optional<SpecialPoint> at;
  /// The branch switched to (status not_run without `at`; no_motion, with a message, when the
  /// motion ends at the grazing).
  Branch branch;
};

/// The curve of `follow`.
struct FollowResult {
  std::string param2;                                         ///< the second parameter's name
  double value2 = kNaN;                                       ///< the robot's value of it
  SpecialPointType type = SpecialPointType::kPeriodDoubling;  ///< the type followed
  std::optional<SpecialPoint> at;  ///< the branch's special point it starts from (none: empty)
  Curve curve;                     ///< the curve (status not_run, with a message, without `at`)
};

struct ContinueJobResult {
  std::string param;                     ///< the branch's parameter
  Branch branch;                         ///< the branch
  std::optional<SwitchResult> switched;  ///< when switch_at was asked
  std::optional<FollowResult> follow;    ///< when follow was asked
};

/// Validates `options`, follows the branch (ContinueParameter), then the switched branch
/// (SwitchAtPeriodDoubling or SwitchAtGrazing) and the curve (FollowSpecialPoint) when asked
/// and the branch has such a point. Throws std::invalid_argument for bad options, a robot without a
/// one-impact orbit (FromOneImpactOrbit) or a range whose ends are no robots; outcomes are
/// statuses.
ContinueJobResult RunContinueJob(const ContinueJobOptions& options);

}  // namespace capsubot
