#pragma once
// A piecewise-constant (pulse) force seen from one origin (docs/model.md section 15): its
// constant pieces in the phase s from the origin, with Pi and Phi at the start of each, so that
// F, Pi and Phi at any s are one lookup and a polynomial of degree 0, 1 and 2. The analytic
// Forcing builds it from the impact, the simulator from the origin of each segment.

#include <array>

#include "capsubot/model/forcing.hpp"

namespace capsubot::detail {

class PulsePieces {
 public:
  /// Pieces of G(origin + s), G(t) = levels[j] for t in [switches[j], switches[j+1]) (mod tau),
  /// j = 0..n-1 (Forcing::Pulse's rules: switches strictly increasing in [0, tau)). A switch
  /// within `snap` of the origin (either side) is taken to be at the origin: the simulator's
  /// events at a switch leave the origin there to rounding, and the force from the origin on is
  /// the new level's.
  void Build(const double* levels, const double* switches, int n, double origin, double snap);

  /// F(s), Pi(s) = integral_0^s F, Phi(s) = integral_0^s Pi for any s (periodic extension; F
  /// is continuous from the right: at a switch it is the new level).
  ForceValues Values(double s) const;
  double F(double s) const { return level_[Piece(Reduce(s).r)]; }
  /// Switches in [lo, hi] (hi - lo <= tau), sorted: every one (`all`), or those where the sign
  /// of F - level changes (0 counts as a sign: a level F touches is crossed where it starts and
  /// where it ends).
  PhaseList Switches(double level, double lo, double hi, bool all) const;
  /// Smallest and largest value of F on [lo, hi] (hi - lo <= tau), F(hi) included.
  Range Bounds(double lo, double hi) const;

 private:
  struct Turns {
    double n;  // whole periods
    double r;  // the rest, in [0, tau)
  };
  static Turns Reduce(double s);
  int Piece(double r) const;  // the piece holding r in [0, tau)

  int n_ = 0;                   // pieces: start_[0] = 0 < start_[1] < ... < start_[n-1] < tau
  bool origin_switch_ = false;  // whether the origin is a switch of the force
  std::array<double, kMaxPulseLevels + 1> start_{}, level_{}, pi_{}, phi_{};
  double pi_tau_ = 0.0, phi_tau_ = 0.0;  // Pi(tau), Phi(tau)
};

}  // namespace capsubot::detail
