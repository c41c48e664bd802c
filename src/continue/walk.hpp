#pragma once
// A walk along a branch (one parameter) or a curve of special points (two), the parts both
// share: the arclength step, which grows after a corrector that converged fast and halves
// after a failure, the walk bounded in attempts, not only in points; how an accepted point is
// kept; the corrector's tolerances.

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <utility>
#include <vector>

#include "capsubot/continue/continuation.hpp"

namespace capsubot::detail {

class StepControl {
 public:
  /// Steps of `options` (initial, min, max) for a walk of at most `budget` points.
  StepControl(const ContinuationOptions& options, int budget)
      : h_(options.initial_step), min_(options.min_step), max_(options.max_step) {
    // Every point costs at most one failed step per halving from max_step to min_step (the
    // logarithms apart: the ratio itself overflows for steps near the ends of the doubles).
    const int halvings = static_cast<int>(std::ceil(std::log2(max_) - std::log2(min_))) + 2;
    max_attempts_ = static_cast<std::int64_t>(budget + 1) * halvings;
  }

  /// The step to try.
  double h() const { return h_; }
  /// Whether another attempt is allowed (each call counts one).
  bool Attempt() { return attempts_++ < max_attempts_; }
  /// A failed step: halved; false when it already was the smallest (the walk is lost there).
  bool Failed() {
    if (h_ <= min_) return false;
    h_ = std::max(0.5 * h_, min_);
    return true;
  }
  /// An accepted point whose corrector took `iterations`: the step grows when it was fast.
  void Accepted(int iterations) {
    if (iterations <= kFastIterations) h_ = std::min(kGrowth * h_, max_);
  }

 private:
  // The step grows by kGrowth after a correction of at most kFastIterations chord iterations
  // (each cuts the residual by about the step times the branch's curvature, so a few reach the
  // tolerance from a good predictor).
  static constexpr double kGrowth = 1.5;
  static constexpr int kFastIterations = 4;

  double h_, min_, max_;
  std::int64_t attempts_ = 0, max_attempts_ = 0;
};

/// Keeps the accepted point `b` of a walk: appends it to `nodes`; the walk ends at the range's
/// end (`at_end`) or where the point's section cannot be placed clear of its events
/// (`system.Replace`), else the step grows as its corrector allows. Returns false when the walk
/// ends, with *end saying how.
template <class System, class Node>
bool KeepPoint(System& system, Node b, bool at_end, StepControl& step, std::vector<Node>* nodes,
               BranchEnd* end) {
  nodes->push_back(std::move(b));
  if (at_end) {
    *end = BranchEnd::kRangeEnd;
    return false;
  }
  if (!system.Replace(&nodes->back())) {
    *end = BranchEnd::kLost;
    return false;
  }
  step.Accepted(nodes->back().iterations);
  return true;
}

// The corrector's tolerances, for a branch and for a curve alike.
/// A chord iteration (the Jacobian of an earlier iterate) must cut the residual at least by
/// this factor; otherwise the Jacobian is recomputed at the current iterate.
inline constexpr double kChordRate = 0.25;
/// The residual of a converged point may stay up to this factor above the tolerance once
/// Newton's update is below kUpdateRounding: the map's own rounding, amplified by its
/// multipliers.
inline constexpr double kRoundingFactor = 100.0;
inline constexpr double kUpdateRounding = 1e-13;

}  // namespace capsubot::detail
