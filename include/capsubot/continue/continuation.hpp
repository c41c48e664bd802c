#pragma once
// Pseudo-arclength continuation of periodic motions in one model parameter (docs/model.md
// section 13, docs/continuation.md).
//
// A periodic motion of period p is a fixed point z of the p-th iterate of the stroboscopic map,
// P^p(z; lambda) = z, in the free coordinates of its section (periodic.hpp). Its branch is the
// curve y(s) = (z(s), lambda(s)) in arclength s. From a point y_i with unit tangent t_i (the
// null vector of [P_z - I, P_lambda]), the predictor steps to y_i + h t_i and the corrector
// solves, by Newton's method, P^p(z; lambda) - z = 0 together with t_i . (y - y_i) = h. The
// Jacobians are central differences of the exact simulated map, as in the Newton shooting. The
// step h grows after a fast correction and is halved after a failed one.
//
// Between two points of the branch, test functions that change sign mark special points, each
// located by a secant (or bisection) search along the arclength: a fold (lambda turns back: the
// tangent's parameter component changes sign), a period doubling (det(P_z + I) changes sign), a
// Neimark-Sacker point (a complex pair of multipliers crosses the unit circle), a grazing
// (the impacts per period change) or a segment change (the order of the stick/slide events
// changes), and a speed extremum (d mean velocity / ds changes sign).

#include <complex>
#include <cstdint>
#include <functional>
#include <string>
#include <vector>

#include "capsubot/attract/attractors.hpp"
#include "capsubot/attract/periodic.hpp"
#include "capsubot/model/forcing.hpp"
#include "capsubot/model/interrupt.hpp"
#include "capsubot/model/model_parameter.hpp"
#include "capsubot/model/params.hpp"
#include "capsubot/numerics/not_computed.hpp"

namespace capsubot {

/// A one-parameter family of robots (RobotModel, model_parameter.hpp): the robot at parameter
/// value lambda. The continuation does
/// not know which parameter it is; a family must be smooth in lambda where the motion is.
using RobotFamily = std::function<RobotModel(double lambda)>;

struct ContinuationOptions {
  double from = kNaN;   ///< lower end of the parameter range (finite)
  double to = kNaN;     ///< upper end (finite, > from)
  double start = kNaN;  ///< the parameter's value at the start state; from <= start <= to
  /// Points of the branch in all (the start included); 2 <= max_points <= 100,000 (about 1 KB
  /// of memory each, 4 KB more as JSON).
  int max_points = 200;
  double initial_step = 0.01;  ///< first arclength step; min_step <= initial_step <= max_step
  double min_step = 1e-7;      ///< smallest step: a correction failing there ends the branch; > 0
  double max_step = 0.05;      ///< largest step; >= min_step
  /// The corrector stops when max |P^p(z) - z| is at most this; > 0.
  double residual_tolerance = 1e-12;
  int max_corrector_iterations = 8;  ///< Newton iterations per correction; >= 1
  /// Special points are located until the bracket along the arclength (hence the parameter) is
  /// at most this wide; > 0.
  double location_tolerance = 1e-10;
  bool both_directions = true;  ///< continue both ways from the start (else towards `to` only)
  /// The start's Newton shooting (max_period: the period is found there) and the simulator's
  /// settings along the branch (step: the finite-difference step of every Jacobian).
  ShootingOptions shooting;
  /// Asked once per attempted step (a few simulated periods apart, about a millisecond); what
  /// it throws stops the continuation and is rethrown (capsubot/model/interrupt.hpp). Optional.
  Interrupt interrupt;

  /// Throws std::invalid_argument naming the first bad field, its value and the rule.
  void Validate() const;
};

/// Throws std::invalid_argument "step = ... is invalid" unless the finite differences of a
/// parameter over [lo, hi] stay in that range: its step h = step max(1, |value|) is taken
/// central, or one-sided up to 2 h inwards at an end, so 3 step max(1, |lo|, |hi|) <= hi - lo
/// (beyond the range the robots may not exist). lo_name, hi_name: the ends' names.
void RequireDifferencesInRange(double step, const char* lo_name, double lo, const char* hi_name,
                               double hi);

/// One point of a branch.
struct BranchPoint {
  double parameter = kNaN;       ///< lambda
  double arclength = kNaN;       ///< s from the start, increasing along the branch's order
  double tangent = kNaN;         ///< d lambda / ds (changes sign at a fold)
  PeriodicMotion motion;         ///< period, impacts, mean velocity, state, multipliers, ...
  int corrector_iterations = 0;  ///< Newton iterations of the corrector that found it
  std::string label;             ///< the types of the special points just before this point, or ""
};

enum class SpecialPointType {
  kFold,            ///< a multiplier through +1: the parameter turns back
  kPeriodDoubling,  ///< a multiplier through -1
  kNeimarkSacker,   ///< a complex pair of multipliers through the unit circle
  kGrazing,         ///< the impacts per period change (an impact appears or disappears)
  kSegmentChange,   ///< the order of the stick/slide events per period changes
  kSpeedExtremum,   ///< the mean velocity is extremal along the branch
};

/// "fold", "period_doubling", "neimark_sacker", "grazing", "segment_change", "speed_extremum".
const char* SpecialPointTypeName(SpecialPointType type);

/// The wall a grazing's free flight touches.
enum class Wall {
  kNone,   ///< not a grazing
  kRight,  ///< x = 1 (a maximum of x)
  kLeft,   ///< x = 0 (a minimum of x)
};

/// "none", "right", "left".
const char* WallName(Wall wall);

struct SpecialPoint {
  SpecialPointType type = SpecialPointType::kFold;
  double parameter = kNaN;  ///< lambda at the special point
  double arclength = kNaN;  ///< s there (BranchPoint::arclength)
  /// Width of the final bracket in the parameter (<= location_tolerance when located).
  double accuracy = kNaN;
  bool located = false;  ///< the search reached location_tolerance
  /// The motion at the located point (for a grazing or segment change: the last point on the
  /// side of the branch's earlier points).
  PeriodicMotion motion;
  int after_point = -1;     ///< index into Branch::points of the point just before it
  Wall wall = Wall::kNone;  ///< a grazing's wall
};

enum class BranchEnd {
  kNotRun,     ///< not computed
  kRangeEnd,   ///< reached `from` or `to` (the last point lies on the end)
  kLost,       ///< the corrector failed at the smallest step: the motion is lost here
  kMaxPoints,  ///< max_points reached
  /// A two-parameter curve (special_curve.hpp) cannot go on at the smallest step without
  /// changing the motion's events (impacts, stick/slide pattern): its condition ends there.
  kEventChange,
  /// A free flight of the motion touches a wall there (its last special point is that grazing,
  /// located along the parameter) and the motion does not go on with its events beyond it.
  kGrazing,
  /// The branch (of an even period 2p) passes through the motion of period p there, the period
  /// doubling it is born at: beyond, it is the same motion shifted by p periods, retraced.
  kHalfPeriod,
};

/// "not_run", "range_end", "lost", "max_points", "event_change", "grazing", "half_period".
const char* BranchEndName(BranchEnd end);

enum class ContinuationStatus {
  kNotRun,     ///< not computed
  kOk,         ///< the start converged and the branch was followed
  kNoMotion,   ///< Newton's method found no periodic motion at the start
  kEventLimit  ///< the start's simulation hit the work bound
};

/// "not_run", "ok", "no_motion", "event_limit".
const char* ContinuationStatusName(ContinuationStatus status);

/// A branch of periodic motions.
struct Branch {
  ContinuationStatus status = ContinuationStatus::kNotRun;
  std::string message;  ///< why there is no branch (status not kOk), else empty
  /// The points in increasing arclength: the backward part (towards `from` at the start),
  /// the start, the forward part.
  std::vector<BranchPoint> points;
  std::vector<SpecialPoint> special_points;     ///< in the order of the points
  int start_index = -1;                         ///< index of the start in `points`
  BranchEnd backward_end = BranchEnd::kNotRun;  ///< how the backward part ended
  BranchEnd forward_end = BranchEnd::kNotRun;   ///< how the forward part ended
  double backward_parameter = kNaN;             ///< its last lambda
  double forward_parameter = kNaN;              ///< its last lambda

  /// A plain-words summary: the motion at the start, the range covered, how each end was met,
  /// the special points. `name` is the parameter's name.
  std::string Summary(const std::string& name) const;
};

/// Follows the periodic motion near `start` (at parameter options.start) through the range
/// [from, to]: Newton shooting at the start (FindPeriodicMotion with options.shooting), then
/// pseudo-arclength continuation both ways. Throws std::invalid_argument for bad options, a
/// bad start or a family whose robots at from, start or to are invalid; outcomes are statuses.
Branch ContinueBranch(const RobotFamily& family, const PhaseState& start,
                      const ContinuationOptions& options);

}  // namespace capsubot
