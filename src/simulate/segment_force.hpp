#pragma once
// The motor force seen from the origin of one simulated segment (docs/model.md sections 2, 3
// and 10), for the simulator's hot path: the harmonics rotated to the segment's origin and
// the factors 1/k and 1/k^2 of the integrals taken once per segment, so each point costs one
// sincos and no division.

#include <array>
#include <cmath>

#include "capsubot/forcing.hpp"
#include "simulate/local_sincos.hpp"

namespace capsubot::detail {

/// Phases in increasing order, phi[0..n) (PhaseList without zeroing the unused entries: the
/// hot path fills a few of them per segment).
struct CrossingList {
  std::array<double, 2 * kMaxHarmonics + 2> phi;
  int n = 0;
};

class SegmentForce {
 public:
  /// Levels whose crossings a run looks up instead of solving them per segment.
  static constexpr int kMaxLevels = 5;

  /// Once per run: the crossings over one period of `motor` (shift 0) with each of `levels`
  /// (at most kMaxLevels); Crossings of these levels then only shift them to the segment.
  void Prepare(const Forcing& motor, const double* levels, int n_levels);
  /// F(s) = G(origin + s) with G the motor force and origin = motor.phi0() + shift: the same
  /// series as motor.WithPhase(motor.phi0() + shift) to rounding (LocalCosSin of k origin).
  /// shift in [0, tau).
  void Set(const Forcing& motor, double shift);

  /// F(s).
  double F(double s) const {
    if (s == 0.0) return f0_;
    const auto [c1, s1] = LocalCosSin(s);
    if (K_ == 1) return c_ + (a_[0] * c1 + b_[0] * s1);  // SumF for K = 1
    return c_ + SumF(c1, s1);
  }
  /// F(s), Pi(s), Phi(s) from one sincos (harmonic k by angle addition). At s = 0 exactly:
  /// F(0) = c + sum a_k and Pi = Phi = 0, without a sincos. Inline: the event searches of the
  /// simulator call it a dozen times per event, mostly for one harmonic.
  ForceValues Values(double s) const {
    if (s == 0.0) return {f0_, 0.0, 0.0};
    // Pi = c s + sum_k (a_k sin ks + b_k (1 - cos ks)) / k,
    // Phi = c s^2/2 + sum_k (a_k (1 - cos ks) + b_k (k s - sin ks)) / k^2.
    const auto [c1, s1] = LocalCosSin(s);
    if (K_ == 1) {  // SumValues for K = 1, without the recurrence
      const double one_minus_c = 1.0 - c1;
      return {c_ + (a_[0] * c1 + b_[0] * s1), c_ * s + (a1_[0] * s1 + b1_[0] * one_minus_c),
              0.5 * c_ * s * s + (a2_[0] * one_minus_c + b2_[0] * (s - s1))};
    }
    return SumValues(s, c1, s1);
  }
  /// Every s in [lo, hi] (0 <= lo, hi - lo <= tau) where F crosses or touches `level`,
  /// sorted: Forcing::Crossings of the same series; for a prepared level, the motor's
  /// crossings shifted to the segment (the same phases to rounding, without a root solve).
  CrossingList Crossings(double level, double lo, double hi) const;

 private:
  struct LevelCrossings {
    double level = 0.0;
    PhaseList t;  // crossings in [0, tau) of the series at shift 0
  };
  // The sums of F and of Values for K > 1 from cos s, sin s (harmonic k by angle addition).
  double SumF(double c1, double s1) const;
  ForceValues SumValues(double s, double c1, double s1) const;

  std::array<LevelCrossings, kMaxLevels> table_{};
  int n_levels_ = 0;
  double shift_ = 0.0;
  int K_ = 0;
  double c_ = 0.0;
  double f0_ = 0.0;                                // F(0)
  std::array<double, kMaxHarmonics> a_{}, b_{};    // F = c + sum a_k cos k s + b_k sin k s
  std::array<double, kMaxHarmonics> a1_{}, b1_{};  // a_k / k, b_k / k
  std::array<double, kMaxHarmonics> a2_{}, b2_{};  // a_k / k^2, b_k / k^2
};

}  // namespace capsubot::detail
