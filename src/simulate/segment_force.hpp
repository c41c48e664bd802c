#pragma once
// The motor force seen from the origin of one simulated segment (docs/model.md sections 2, 3
// and 10), for the simulator's hot path: the harmonics rotated to the segment's origin and
// the factors 1/k and 1/k^2 of the integrals taken once per segment, so each point costs one
// sincos (none along a root search: its iterates' angles come by angle addition) and no
// division; the signs of F against the levels the events look for, between their crossings,
// are tabulated once per run. A pulse force (Forcing::pulse) is held as its constant pieces
// from the origin instead (detail::PulsePieces): F, Pi and Phi are polynomials of degree 0, 1
// and 2 on each, and every switch is a cut of every level (Crossings), so each piece the event
// searches see has a constant force.

#include <array>
#include <cmath>

#include "capsubot/model/detail/pulse_pieces.hpp"
#include "capsubot/model/forcing.hpp"
#include "simulate/local_sincos.hpp"

namespace capsubot::detail {

/// Phases in increasing order, phi[0..n) (PhaseList without zeroing the unused entries: the
/// hot path fills a few of them per segment).
struct CrossingList {
  std::array<double, 2 * kMaxHarmonics + 2> phi;
  int n = 0;
};

/// 1 - cos x from cos x and sin x: sin^2 x/(1 + cos x) where cos x > 0, so it keeps its
/// relative accuracy for small x (the short flights of a chattering sequence, whose
/// displacement Phi would otherwise lose it to the rounding of cos x near 1); 1 - cos x
/// elsewhere (no cancellation there).
inline double Versine(double c, double s) { return c > 0.0 ? s * s / (1.0 + c) : 1.0 - c; }

class SegmentForce {
 public:
  /// Levels whose crossings a run looks up instead of solving them per segment.
  static constexpr int kMaxLevels = 5;

  /// A switch of a pulse force closer than this to the origin, on either side, is at the
  /// origin: an event located at a switch leaves the origin there to within a few ulp of 2 pi,
  /// and the force from it on is the new level. The event searches drop cuts this close after
  /// the start too (the simulator's minimal cut).
  static constexpr double kSwitchSnap = 1e-13;

  /// A part of a piece between crossings shorter than this takes its sign from its own middle
  /// (PieceSign): a longer one's middle lies far enough from the crossings for the sign of
  /// the whole piece to be its sign.
  static constexpr double kNearCut = 1e-3;

  /// Once per run: the crossings over one period of `motor` (shift 0) with each of `levels`
  /// (at most kMaxLevels), and the sign of F - level between them, from its largest size on
  /// each piece (exact bounds of F; 0 when F stays within `tol` of the level on the whole
  /// piece); Crossings and PieceSign of these levels then only shift them to the segment.
  void Prepare(const Forcing& motor, const double* levels, int n_levels, double tol);
  /// F(s) = G(origin + s) with G the motor force and origin = motor.phi0() + shift: the same
  /// series as motor.WithPhase(motor.phi0() + shift) to rounding (LocalCosSin of k origin).
  /// shift in [0, tau).
  void Set(const Forcing& motor, double shift);

  /// The local phase s with its cosine and sine (LocalCosSin; none at s = 0).
  static Angle At(double s) {
    if (s == 0.0) return {0.0, 1.0, 0.0};
    const auto [c, sn] = LocalCosSin(s);
    return {s, c, sn};
  }

  /// F(s).
  double F(double s) const {
    if (s == 0.0) return f0_;
    if (K_ != 1) return ManyF(s);
    const auto [c1, s1] = LocalCosSin(s);
    return c_ + (a_[0] * c1 + b_[0] * s1);  // SumF for K = 1
  }
  /// F(s), Pi(s), Phi(s) from one sincos (harmonic k by angle addition). At s = 0 exactly:
  /// F(0) = c + sum a_k and Pi = Phi = 0, without a sincos. Inline: the event searches of the
  /// simulator call it several times per event, mostly for one harmonic.
  ForceValues Values(double s) const {
    if (s == 0.0) return {f0_, 0.0, 0.0};
    return Values(At(s));
  }
  /// Values at a local phase whose cosine and sine are known (no sincos).
  ForceValues Values(const Angle& at) const {
    const ForceJet j = Sums<false>(at);
    return {j.F, j.Pi, j.Phi};
  }
  /// Values with F' and F'' (what PhaseRoot needs), no sincos.
  ForceJet Jet(const Angle& at) const { return Sums<true>(at); }
  /// Sign of F - level on (l, r), a part of one piece between consecutive crossings of the
  /// level (0 <= l < r <= l + tau): +1 or -1, or 0 when |F - level| <= tol in its middle (a
  /// touch, or a piece too short to matter: F stays on the level within rounding). For a
  /// prepared level and a part longer than kNearCut, the tabulated sign of the piece that
  /// holds its middle (no evaluation of F; decided where F - level is largest, so a point
  /// where F nearly touches the level inside a piece changes nothing).
  double PieceSign(double level, double l, double r) const;
  /// Every s in [lo, hi] (0 <= lo, hi - lo <= tau) where F crosses or touches `level`,
  /// sorted: Forcing::Crossings of the same series; for a prepared level, the motor's
  /// crossings shifted to the segment (the same phases to rounding, without a root solve). For a
  /// pulse force every switch in [lo, hi], whatever the level.
  CrossingList Crossings(double level, double lo, double hi) const;

 private:
  struct LevelCrossings {
    double level = 0.0;
    PhaseList t;  // crossings in [0, tau) of the series at shift 0
    // sign[i]: the sign of F - level on (t[i], t[i+1]) (t[n] = t[0] + tau); with no
    // crossing, sign[0] on the whole period (see Prepare).
    std::array<double, 2 * kMaxHarmonics + 2> sign{};
  };
  const LevelCrossings* Find(double level) const {
    for (int i = 0; i < n_levels_; ++i) {
      if (table_[i].level == level) return &table_[i];
    }
    return nullptr;
  }
  // F, its derivatives (kWithDerivatives) and integrals at s from cos s and sin s:
  // Pi = c s + sum_k (a_k sin ks + b_k (1 - cos ks)) / k,
  // Phi = c s^2/2 + sum_k (a_k (1 - cos ks) + b_k (k s - sin ks)) / k^2; one harmonic inline,
  // more by angle addition (SumJet).
  template <bool kWithDerivatives>
  ForceJet Sums(const Angle& at) const {
    if (K_ != 1) return SumJet(at, kWithDerivatives);
    const double s = at.phi, c1 = at.cos, s1 = at.sin, one_minus_c = Versine(c1, s1);
    const double f = a_[0] * c1 + b_[0] * s1;
    ForceJet j;
    j.F = c_ + f;
    if (kWithDerivatives) {
      j.dF = b_[0] * c1 - a_[0] * s1;
      j.ddF = -f;
    }
    j.Pi = c_ * s + (a1_[0] * s1 + b1_[0] * one_minus_c);
    j.Phi = 0.5 * c_ * s * s + (a2_[0] * one_minus_c + b2_[0] * (s - s1));
    return j;
  }
  double SumF(double c1, double s1) const;
  double ManyF(double s) const;  // F(s) for K != 1 harmonics or a pulse force
  ForceJet SumJet(const Angle& at, bool derivatives) const;

  std::array<LevelCrossings, kMaxLevels> table_{};
  int n_levels_ = 0;
  double tol_ = 0.0;
  double shift_ = 0.0;
  int K_ = 0;  // harmonics, or kPulse
  static constexpr int kPulse = -1;
  detail::PulsePieces pieces_;  // the pulse force from the origin (K_ = kPulse)
  double c_ = 0.0;
  double f0_ = 0.0;                                // F(0)
  std::array<double, kMaxHarmonics> a_{}, b_{};    // F = c + sum a_k cos k s + b_k sin k s
  std::array<double, kMaxHarmonics> a1_{}, b1_{};  // a_k / k, b_k / k
  std::array<double, kMaxHarmonics> a2_{}, b2_{};  // a_k / k^2, b_k / k^2
};

/// How PhaseRoot moves from one iterate's angle to the next in a segment: angle addition for
/// steps that are short (Angle::Toward's short series) and, unless they start from the
/// origin itself, at most half the target phase; LocalCosSin otherwise. Angle addition from
/// an angle other than 0 errs by about an ulp of 1 in sin s; the second bound keeps that a
/// few ulp of sin s itself where s is small (the short flights of a chattering sequence), as
/// LocalCosSin is.
inline Angle StepAngle(const SegmentForce& force, const Angle& from, double to) {
  (void)force;
  constexpr double kShortStep = 0.125;  // Angle::Toward's short series
  const double step = std::abs(to - from.phi);
  return step <= kShortStep && (from.phi == 0.0 || step <= 0.5 * std::abs(to))
             ? from.Toward(to)
             : SegmentForce::At(to);
}

}  // namespace capsubot::detail
