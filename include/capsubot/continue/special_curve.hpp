#pragma once
// Two-parameter curves of special points (docs/continuation.md, "Two-parameter curves"): a
// fold, period doubling, grazing or speed extremum of a branch in lambda, followed in the plane
// (lambda, mu) of two model parameters by pseudo-arclength continuation of an extended system.
//
// The unknowns are y = (z, lambda, mu): the free coordinates z of the motion's section and the
// two parameters. The equations are the periodic-orbit condition P^p(z; lambda, mu) - z = 0
// (d equations) and the defining condition g(y) = 0 of the special point:
//   fold             det(P_z - I)       (a multiplier +1)
//   period doubling  det(P_z + I)       (a multiplier -1)
//   grazing          x_max - 1 at the right wall, -x_min at the left (an extremum of x of a free
//                    flight touches the wall; the flight continued past the wall in closed form)
//   speed extremum   d(mean velocity)/d lambda = (grad_z . w + grad_lambda) / (p tau), where
//                    (P_z - I) w = -P_lambda
// d + 1 equations in d + 2 unknowns: a curve, followed as a branch is (continuation.hpp), with
// the arclength condition closing the system.

#include <functional>
#include <string>
#include <vector>

#include "capsubot/continue/continuation.hpp"
#include "capsubot/numerics/not_computed.hpp"

namespace capsubot {

/// A two-parameter family of robots: the robot at (lambda, mu).
using RobotSurface = std::function<RobotModel(double lambda, double mu)>;

/// Whether a special point of this type can be followed in two parameters: fold, period
/// doubling, grazing, speed extremum.
bool IsFollowable(SpecialPointType type);

/// The followable type named `name` ("fold", "period_doubling", "grazing", "speed_extremum").
/// Throws std::invalid_argument "follow = <name> is invalid: expected one of fold,
/// period_doubling, grazing, speed_extremum".
SpecialPointType ParseFollowType(const std::string& name);

struct CurveOptions {
  double from2 = kNaN;   ///< lower end of mu's range (finite)
  double to2 = kNaN;     ///< upper end (finite, > from2)
  double start2 = kNaN;  ///< mu at the special point; from2 <= start2 <= to2
  /// lambda's range (from, to), the steps (arclength in (z, lambda, mu)), the points (both
  /// directions together), the tolerances and the simulator's settings, as for a branch; its
  /// `start` is set to the special point's lambda.
  ContinuationOptions continuation;

  /// Throws std::invalid_argument naming the first bad field, its value and the rule.
  void Validate() const;
};

/// One point of a curve.
struct CurvePoint {
  double parameter = kNaN;   ///< lambda
  double parameter2 = kNaN;  ///< mu
  double arclength = kNaN;   ///< s from the start, increasing along the curve's order
  /// The defining condition there (0 to its tolerance; a grazing sits 1e-9 inside the wall).
  double condition = kNaN;
  PeriodicMotion motion;  ///< state, multipliers, mean velocity, impacts, ...
};

/// A curve of special points in (lambda, mu).
struct Curve {
  ContinuationStatus status = ContinuationStatus::kNotRun;
  std::string message;  ///< why there is no curve (status not kOk), else empty
  SpecialPointType type = SpecialPointType::kFold;
  /// The points in increasing arclength: the backward part (mu decreasing at the start)
  /// reversed, the start, the forward part.
  std::vector<CurvePoint> points;
  int start_index = -1;                         ///< index of the start in `points`
  BranchEnd backward_end = BranchEnd::kNotRun;  ///< how the backward part ended
  BranchEnd forward_end = BranchEnd::kNotRun;   ///< how the forward part ended
};

/// Follows the located special point `sp` (of a followable type) of a branch in lambda of the
/// robots surface(lambda, options.start2) through the box [from, to] x [from2, to2]: the
/// extended system solved at mu = start2 from sp's motion, then continued both ways. The curve
/// keeps the motion's events (impacts, stick/slide pattern): a step onto other events is
/// refused, and a direction ends `event_change` where it cannot go on at the smallest step for
/// that reason. A grazing is followed from the side where the flight turns back before the
/// wall. Throws std::invalid_argument for bad options or a special point that is not located
/// or not followable; outcomes are statuses.
Curve FollowSpecialPoint(const RobotSurface& surface, const SpecialPoint& sp,
                         const CurveOptions& options);

}  // namespace capsubot
