#pragma once
// Designing a real robot, part (c): the fastest drive (docs/design.md, "Part (c)").
// Given the shell, the gap, the floor, the restitution and the motor's peak force F_max [N],
// the force's waveform (a sine with a bias, a Fourier series of K harmonics, or N constant
// levels), the motor frequency and the inner mass whose motion reached from rest is fastest.
//
// In the model this is the reach search (optimize_reach.hpp) with T0 and alpha free over the
// ranges of the frequency and the inner mass, and a bound that follows both: in units of
// (m1+m2) omega^2 L the peak is F_max T0 (1 - alpha)/(m1 mu g), with T0 = mu g/(omega^2 L) and
// alpha = m2/(m1+m2). Its objective v_mean/sqrt(T0) is the speed in units of sqrt(mu g L), so
// that robots at different frequencies compare. Backward is the mirror image: walls, friction
// and the grid of starts (x0 -> 1 - x0, psi -> psi + pi) are symmetric, so the force -F drives
// the same robot backward at the same speed; both are checked from rest.

#include <string>
#include <vector>

#include "capsubot/design/design.hpp"
#include "capsubot/design/design_from_rest.hpp"
#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/reach/drive_family.hpp"
#include "capsubot/reach/optimize_reach.hpp"
#include "capsubot/reach/reach_effort.hpp"

namespace capsubot {

/// How the fastest drive is searched.
struct DriveDesignOptions {
  DriveFamily drive = DriveFamily::Fourier(2);  ///< the waveforms searched
  double force_max = kNaN;  ///< the motor's peak force max |F_N| [N], finite > 0
  /// The search's starts and budgets (the drive budgets for K >= 2 and pulses); its
  /// max_seconds bounds each step of the search.
  ReachEffort effort;
  /// The re-check of the candidates and of both directions: 8 x 8 starts, 200 + 100 periods.
  FromRestOptions check;

  /// Throws std::invalid_argument naming the bad parameter (force_max, the drive's and the
  /// effort's names), its value and the rule.
  void Validate() const;
};

/// A drive in newtons over the motor phase s (the phase of the grid of starts from rest):
/// F_N(s) = mean + sum_k (cos[k-1] cos ks + sin[k-1] sin ks), or levels[j] for s in
/// [switches[j], switches[j+1]) (a pulse drive: cos and sin empty).
struct DriveForce {
  double mean = kNaN;            ///< [N]
  std::vector<double> cos, sin;  ///< [N]
  std::vector<double> levels;    ///< [N]
  std::vector<double> switches;  ///< [rad], increasing in [0, 2 pi)
  double max_abs = kNaN;         ///< max |F_N| [N]
};

/// The fastest drive in each direction, in the user's units.
struct DriveDesignResult {
  /// The winner of the dimensionless search (its force in units of (m1+m2) omega^2 L of its
  /// robot, with the motor phase phi0 of the search) and, for K >= 2, the ladder K = 1..K
  /// (a pulse: the sine's winner, then the pulse's).
  std::vector<ReachResult> ladder;
  DriveForce force;           ///< the forward drive
  FromRestBest forward;       ///< its robot checked from rest (m2, f, speed, power, COT, ...)
  DriveForce backward_force;  ///< the mirror image -F
  FromRestBest backward;      ///< its robot checked from rest, backward
  std::string message;        ///< one readable sentence

  const ReachResult& reach() const { return ladder.back(); }
  bool found() const { return forward.ok(); }
};

/// The fastest drive from rest over the waveforms of options.drive, the frequency range and
/// the inner mass range of `input` (its own motor force is not used). Throws
/// std::invalid_argument for invalid input or options. Deterministic when
/// options.effort.max_seconds is infinite.
DriveDesignResult DesignDrive(const DesignInput& input, const DriveDesignOptions& options);

}  // namespace capsubot
