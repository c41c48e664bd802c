#pragma once
// The arclength step of a walk along a branch (one parameter) or a curve of special points
// (two): it grows after a corrector that converged fast, halves after a failure, and the walk
// is bounded in attempts, not only in points.

#include <algorithm>
#include <cmath>
#include <cstdint>

#include "capsubot/continue/continuation.hpp"

namespace capsubot::detail {

class StepControl {
 public:
  /// Steps of `options` (initial, min, max) for a walk of at most `budget` points.
  StepControl(const ContinuationOptions& options, int budget)
      : h_(options.initial_step), min_(options.min_step), max_(options.max_step) {
    // Every point costs at most one failed step per halving from max_step to min_step.
    const int halvings = static_cast<int>(std::ceil(std::log2(max_ / min_))) + 2;
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

}  // namespace capsubot::detail
