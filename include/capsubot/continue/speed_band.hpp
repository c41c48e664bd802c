#pragma once
// The speed band of a robot in one parameter (docs/continuation.md, "Speed bands"): how far the
// parameter can move, each way, before the robot's mean speed from rest (over a grid of starts,
// FindAttractors) falls below a fraction of its speed at the parameter's value. Found by
// simulation alone, so it holds whatever motion the robot settles in: a chattering motion whose
// impact count is not a signature, a motion that changes its impacts or its stick/slide pattern
// and goes on, or another motion that takes over.

#include <cstdint>
#include <string>
#include <vector>

#include "capsubot/attract/attractors.hpp"
#include "capsubot/continue/continuation.hpp"
#include "capsubot/numerics/not_computed.hpp"

namespace capsubot {

/// Most levels of one band.
inline constexpr std::size_t kMaxBandLevels = 8;

struct SpeedBandOptions {
  /// The fractions of the nominal speed whose edges are sought, each in (0, 1), distinct.
  std::vector<double> levels = {0.95};
  /// An edge is bisected until its bracket is at most this times the range (to - from) wide;
  /// 1e-9 <= tolerance <= 0.1.
  double tolerance = 1e-3;
  /// The walk outwards from the value: its first step is this fraction of the distance to the
  /// range's end, each next step twice the last, the last one the end itself; 1e-6 <= first_step
  /// <= 1. A dip of the speed below a level between two points of the walk is not seen.
  double first_step = 1.0 / 64.0;
  /// The starts from rest and how their motions are found (FindAttractors).
  FromRestOptions from_rest;

  /// Throws std::invalid_argument naming the first bad field, its value and the rule.
  void Validate() const;
};

/// Where the speed from rest falls below one level, one way from the value.
struct BandEdge {
  double level = kNaN;  ///< the fraction of the nominal speed
  /// The speed falls below the level inside the range; false: it stays above at every point of
  /// the walk up to the range's end ("beyond" the end).
  bool within = false;
  /// within: the middle of the final bracket; else the range's end.
  double parameter = kNaN;
  double inside = kNaN;         ///< the bracket's end towards the value: speed >= level there
  double outside = kNaN;        ///< its other end: speed < level there (NaN unless within)
  double accuracy = kNaN;       ///< |outside - inside| (NaN unless within)
  double ratio_inside = kNaN;   ///< the speed at `inside` over the nominal speed
  double ratio_outside = kNaN;  ///< the speed at `outside` over the nominal speed
};

enum class SpeedBandStatus {
  kNotRun,   ///< not computed
  kOk,       ///< the edges were sought
  kNoSpeed,  ///< the robot does not move from rest at the value (speed 0 or not finite)
  /// At the value, some starts end in no periodic motion whose record's halves differ by more
  /// than kSettledHalves: their mean speed has not settled, a band of it would be noise.
  kUnsettled,
};

/// "not_run", "ok", "no_speed", "unsettled".
const char* SpeedBandStatusName(SpeedBandStatus status);

/// One parameter's band.
struct SpeedBand {
  std::string name;     ///< the parameter's name
  double value = kNaN;  ///< the robot's value
  double from = kNaN;   ///< the range searched
  double to = kNaN;
  SpeedBandStatus status = SpeedBandStatus::kNotRun;
  double nominal_speed = kNaN;        ///< the mean speed from rest at the value (units of omega L)
  std::int64_t starts = 0;            ///< the starts from rest
  std::int64_t unsettled_starts = 0;  ///< of them, those whose speed has not settled (kUnsettled)
  std::vector<BandEdge> down;         ///< one edge per level (in the order of the levels), below
  std::vector<BandEdge> up;           ///< and above the value
  int evaluations = 0;                ///< simulations from rest (FindAttractors) made

  /// The edge of `level` one way (down: below the value), or null.
  const BandEdge* Edge(double level, bool up_side) const;
  /// Whether `parameter` lies inside the band of `level` (between its two edges' inside ends,
  /// or their range ends when the band reaches beyond them).
  bool Contains(double level, double parameter) const;
};

/// The speed band of the robots `family` (the robot at each value of the parameter `name`)
/// around `value` within [from, to]: the nominal speed from rest at `value`, then, each way, a
/// walk outwards (SpeedBandOptions::first_step) to the first point where the speed falls below
/// each level, and a bisection of that bracket to the tolerance. At most
/// 1 + 2 (1 + log2(1/first_step) + levels log2(1/tolerance)) simulations from rest. Throws
/// std::invalid_argument for bad options, from <= value <= to violated, or an invalid robot.
SpeedBand ComputeSpeedBand(const RobotFamily& family, const std::string& name, double value,
                           double from, double to, const SpeedBandOptions& options = {});

}  // namespace capsubot
