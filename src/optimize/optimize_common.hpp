#pragma once
// What the optimisers of docs/model.md section 7 (P1, P2, P3) share: constants, the phase
// reduction and the check of their options.

#include <cmath>
#include <stdexcept>
#include <string>

#include "capsubot/forcing.hpp"

namespace capsubot::detail {

inline constexpr double kPi = kTau / 2.0;
/// Smallest mean force c of P2 and P3 (fraction of the bound): c > 0 for a directed orbit.
inline constexpr double kMinMeanFraction = 1e-9;
/// Phases scanned by the final P1 polish of P2 and P3 (PolishPhase).
inline constexpr int kFinalPhaseScan = 720;

/// phi0 reduced into [-pi, pi): reduce where the force is built, so that the evaluated and the
/// reported numbers are the same (a wrap afterwards can flip a grazing orbit's validity).
inline double ReducePhase(double phi0) { return phi0 - kTau * std::floor((phi0 + kPi) / kTau); }

/// Throws std::invalid_argument(message) unless ok: the options' Validate().
inline void Require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument(message);
}

}  // namespace capsubot::detail
