#pragma once
// The set of forces a reach search varies (docs/reach.md, "Drives"): the paper's sine plus a
// bias, a Fourier series of K harmonics, each under one bound max |F| <= bound, and the
// coordinates of the search box that describe them.
//
// Sine (today's problem): y = (s, r), A = s (1 - r) bound, c = s r bound, so A + c <= bound.
// Fourier, K >= 2: y = (g_0, g_1, ..., g_{2K-1}) in [-1, 1]^2K (g_1 in [0, 1]), the direction
//     G(t) = g_0 + g_1 sin t + sum_{k=2..K} (g_{2k-2} cos kt + g_{2k-1} sin kt),
// and F = bound G / max|G| (max|G| exact, from the zeros of G'), so that max |F| = bound holds
// at every point of the box, not only at the optimum: a drive of several harmonics uses its
// whole bound (a smaller one is the same drive, weaker). The first harmonic is a pure sine
// (a_1 = 0, b_1 >= 0): a shift of the time origin removes its cosine, and the starts from rest
// cover every phase of the motor.
// Pulse, N levels: y = (l_1, ..., l_N, w_1, ..., w_N): the levels l_j bound in [-bound, bound]
// and the widths w_j in [kMinPulseWidth, 1] of the pieces, the switches at
// s_j = 2 pi (w_1 + ... + w_j)/(w_1 + ... + w_N), s_0 = 0 (the starts cover every phase), so
// max |F| <= bound holds at every point of the box.

#include <string>
#include <vector>

#include "capsubot/model/forcing.hpp"

namespace capsubot {

/// The waveforms a reach search varies.
enum class Waveform {
  kSine,     ///< A sin(phi + phi0) + c, A + c <= bound
  kFourier,  ///< c + sum of K harmonics, max |F| <= bound
  kPulse,    ///< N constant levels between switching phases, |F| <= bound
};

/// The narrowest piece of a pulse drive, as a share of the largest: w_j >= kMinPulseWidth.
inline constexpr double kMinPulseWidth = 0.02;

/// "sine", "fourier", "pulse".
const char* WaveformName(Waveform waveform);

/// The forces a reach search varies.
struct DriveFamily {
  Waveform waveform = Waveform::kSine;
  /// kFourier: the number K of harmonics, 1 <= K <= kMaxHarmonics (K = 1 is the sine).
  int harmonics = 1;
  /// kPulse: the number N of levels, 2 <= N <= kMaxPulseLevels.
  int levels = 2;

  /// The sine family, or the Fourier series of K harmonics (K = 1: the sine).
  static DriveFamily Fourier(int harmonics);
  /// The pulse drives of N levels.
  static DriveFamily Pulse(int levels);

  /// Throws std::invalid_argument naming the bad field, its value and the rule.
  void Validate() const;
  /// True for the paper's sine plus a bias (kSine, or kFourier with K = 1).
  bool sine() const {
    return waveform == Waveform::kSine || (waveform == Waveform::kFourier && harmonics == 1);
  }
  /// The number of box coordinates of the force (2 for the sine, 2 K for K >= 2, 2 N for N
  /// levels).
  int Dimension() const;
  /// One line: "sine", "Fourier, K = 3", "pulse, N = 3".
  std::string Describe() const;
};

/// The box of the force coordinates of `family` (DriveFamily::Dimension entries each).
void DriveBox(const DriveFamily& family, std::vector<double>& lower, std::vector<double>& upper);

/// The force at box coordinates y[0..Dimension()) with the given bound and motor phase phi0 at
/// the impact (the seed's, from which start phases are counted). The zero force where the
/// direction G vanishes.
Forcing DriveAt(const DriveFamily& family, const double* y, double bound, double phi0);

/// The box coordinates of `forcing` in `family`, if it belongs to it: a sine A sin(s) + c
/// (motor phase s, any family), or a series of at most K harmonics whose first is a pure sine,
/// with max |F| <= bound. DriveAt(family, y, bound, forcing.phi0()) gives the same force to
/// rounding (for K >= 2: scaled to max |F| = bound). Empty when it does not belong.
std::vector<double> DriveCoordinates(const DriveFamily& family, const Forcing& forcing,
                                     double bound);

/// The same series times `factor` (every coefficient; phi0 kept).
Forcing ScaledDrive(const Forcing& forcing, double factor);

/// A force of the family written with the family's K harmonics (the missing ones 0): the same
/// force. The sine family returns it unchanged.
Forcing WithHarmonicsOf(const DriveFamily& family, const Forcing& forcing);

}  // namespace capsubot
