#pragma once
// The accumulation point of a chattering sequence (docs/model.md section 14): impacts on one
// wall whose approach speeds shrink geometrically while the free relative acceleration pushes
// the inner body into the wall. With the force locally constant, the impact-to-impact map is
// homogeneous of degree 1 in (u, v, time), so every increment between impacts (phase, capsule
// position, capsule velocity, energy tallies) becomes a sum of geometric series in r, r^2, r^3
// (r the ratio of successive speeds): degree 1 (phase), 2 (a displacement, a loss), 3 (the
// motor's work over a flight, whose first order cancels), and the drift of the force adds
// series of the next degrees. The limit is extrapolated from the last impacts by eliminating
// the series of degrees 1 to 3, with r itself extrapolated from its drift.

#include <array>

#include "capsubot/model/energy.hpp"
#include "capsubot/numerics/not_computed.hpp"

namespace capsubot::detail {

/// The run right before one impact of a sequence. Phase, capsule position and the energy
/// tallies are counted from the sequence's first impact, so their increments keep their digits.
struct ChatterRecord {
  double phase = 0.0;  ///< phase since the sequence's first impact
  double speed = 0.0;  ///< |u| right before the impact
  double v = 0.0;      ///< capsule velocity right before the impact (P = v + alpha u is the same)
  double y = 0.0;      ///< capsule position minus its value at the first impact
  Energy energy;       ///< tallies since the first impact (NaN without the energy budget)
};

/// The accumulation point estimated from the last impacts (ChatterSequence::Limit).
struct ChatterLimit {
  bool valid = false;  ///< enough impacts, speeds shrinking, both ratio estimates in (0, 1)
  double ratio = 0.0;  ///< r, the ratio of successive speeds extrapolated to the limit
  /// |r from the last impacts - r from the impacts one before| / (1 - r): the ratio's drift
  /// relative to the contraction (small once the sequence is geometric).
  double ratio_spread = 0.0;
  /// Error of the accumulation phase: the estimates from the last four impacts and from the
  /// four one impact earlier differ by the change of the first neglected term, of degree 3
  /// (through the error of the extrapolated r) or higher, which shrinks by at least r^3 per
  /// impact; so the error left is at most about that difference times r^3/(1 - r^3).
  double phase_error = 0.0;
  /// phase_error at the previous impact of the sequence (NaN: none). Truncation makes the
  /// error shrink by r^3 or faster per impact; once it grows instead, rounding limits it.
  double previous_phase_error = kNaN;
  /// The state at the accumulation point (speed 0): phase, v, y and energy since the first
  /// impact, as ChatterRecord.
  ChatterRecord at;
};

/// The last impacts of the current sequence, oldest first.
class ChatterSequence {
 public:
  /// Impacts the extrapolation uses: two estimates from four successive impacts each.
  static constexpr int kImpacts = 5;

  void Clear() {
    n_ = 0;
    error_ = kNaN;
  }
  int Size() const { return n_; }
  /// Adds the record of the next impact and returns the accumulation point from the last
  /// kImpacts impacts (valid = false with fewer).
  ChatterLimit Add(const ChatterRecord& record);

 private:
  std::array<ChatterRecord, kImpacts> rec_{};
  int n_ = 0;
  double error_ = kNaN;  // the last phase_error
};

}  // namespace capsubot::detail
