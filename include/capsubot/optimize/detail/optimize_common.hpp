#pragma once
// What the optimisers of docs/model.md section 7 (P1, P2, P3) share: constants, the phase
// reduction and the check of their options.

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>

#include "capsubot/model/forcing.hpp"

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

/// Requires lo <= value <= hi of a count or size option: "<name> = <value> is invalid:
/// expected lo <= <name> <= hi". Every size is bounded before any work starts.
inline void RequireCount(const char* name, long long value, long long lo, long long hi) {
  Require(value >= lo && value <= hi,
          fmt::format("{} = {} is invalid: expected {} <= {} <= {}", name, value, lo, name, hi));
}

/// The wall-clock limit of one optimisation (OptimizeOptions::max_time), shared by its stages.
class Deadline {
 public:
  using Clock = std::chrono::steady_clock;
  /// max_time seconds from now; infinity (or beyond a year): no limit.
  explicit Deadline(double max_time = HUGE_VAL) {
    constexpr double kNoLimit = 3.2e7;  // a year: also keeps the time_point arithmetic finite
    if (max_time < kNoLimit) {
      end_ = Clock::now() +
             std::chrono::duration_cast<Clock::duration>(std::chrono::duration<double>(max_time));
    }
  }
  /// Seconds left (infinity without a limit; <= 0 once passed).
  double Remaining() const {
    if (end_ == Clock::time_point::max()) return HUGE_VAL;
    return std::chrono::duration<double>(end_ - Clock::now()).count();
  }
  /// True once the limit has passed; remembered (reached() stays true).
  bool Expired() {
    if (!reached_ && Remaining() <= 0.0) reached_ = true;
    return reached_;
  }
  void MarkReached() { reached_ = true; }
  bool reached() const { return reached_; }

 private:
  Clock::time_point end_ = Clock::time_point::max();
  bool reached_ = false;
};

}  // namespace capsubot::detail
