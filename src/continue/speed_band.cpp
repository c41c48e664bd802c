#include "capsubot/continue/speed_band.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <map>
#include <stdexcept>

namespace capsubot {
namespace {

// The mean speed from rest over the start grid at each parameter value asked, each simulated
// once (the walk and the bisections of several levels meet at the same points).
class SpeedFromRest {
 public:
  SpeedFromRest(const RobotFamily& family, const FromRestOptions& options)
      : family_(family), options_(options) {}

  double operator()(double lambda) {
    const auto found = speeds_.find(lambda);
    if (found != speeds_.end()) return found->second;
    return Attractors(lambda).mean_velocity;
  }
  // The attractors at `lambda` (simulated anew), their speed kept.
  capsubot::Attractors Attractors(double lambda) {
    const RobotModel r = family_(lambda);
    capsubot::Attractors a = FindAttractors(r, options_);
    speeds_.emplace(lambda, a.mean_velocity);
    return a;
  }
  int evaluations() const { return static_cast<int>(speeds_.size()); }

 private:
  const RobotFamily& family_;
  const FromRestOptions& options_;
  std::map<double, double> speeds_;
};

// The starts whose motion from rest has not settled: no period, and the halves of the record
// differ by more than kSettledHalves (attractors.hpp).
std::int64_t UnsettledStarts(const Attractors& a) {
  std::int64_t n = 0;
  for (const Attractor& at : a.attractors) {
    if (at.motion.status == MotionStatus::kNoPeriod && !(at.halves_difference <= kSettledHalves)) {
      n += at.starts;
    }
  }
  return n;
}

// A point of the walk: the parameter and the speed there over the nominal speed.
struct WalkPoint {
  double parameter;
  double ratio;
};

// The walk from `value` towards `end`: steps first_step, 2 first_step, ... of the distance, the
// last one the end itself, until the speed falls below the lowest level. Starts with the value.
std::vector<WalkPoint> Walk(SpeedFromRest& speed, double nominal, double value, double end,
                            double first_step, double lowest) {
  std::vector<WalkPoint> walk = {{value, 1.0}};
  if (end == value) return walk;
  for (double f = first_step;; f = std::min(1.0, 2.0 * f)) {
    const double lambda = f >= 1.0 ? end : value + f * (end - value);
    walk.push_back({lambda, speed(lambda) / nominal});
    if (!(walk.back().ratio >= lowest) || f >= 1.0) return walk;
  }
}

// The edge of `level` on the walk: the first point below it and the one before, bisected.
BandEdge FindEdge(SpeedFromRest& speed, double nominal, const std::vector<WalkPoint>& walk,
                  double level, double width) {
  BandEdge edge;
  edge.level = level;
  std::size_t k = 1;
  while (k < walk.size() && walk[k].ratio >= level) ++k;
  if (k == walk.size()) {  // above the level up to the range's end
    edge.parameter = edge.inside = walk.back().parameter;
    edge.ratio_inside = walk.back().ratio;
    return edge;
  }
  WalkPoint in = walk[k - 1], out = walk[k];
  // Each bisection halves the bracket: bounded by log2(range / width) steps.
  while (std::abs(out.parameter - in.parameter) > width) {
    const double mid = 0.5 * (in.parameter + out.parameter);
    const WalkPoint m{mid, speed(mid) / nominal};
    (m.ratio >= level ? in : out) = m;
  }
  edge.within = true;
  edge.inside = in.parameter;
  edge.outside = out.parameter;
  edge.parameter = 0.5 * (in.parameter + out.parameter);
  edge.accuracy = std::abs(out.parameter - in.parameter);
  edge.ratio_inside = in.ratio;
  edge.ratio_outside = out.ratio;
  return edge;
}

}  // namespace

const char* SpeedBandStatusName(SpeedBandStatus status) {
  switch (status) {
    case SpeedBandStatus::kOk:
      return "ok";
    case SpeedBandStatus::kNoSpeed:
      return "no_speed";
    case SpeedBandStatus::kUnsettled:
      return "unsettled";
    case SpeedBandStatus::kNotRun:
      break;
  }
  return "not_run";
}

void SpeedBandOptions::Validate() const {
  if (levels.empty() || levels.size() > kMaxBandLevels) {
    throw std::invalid_argument(
        fmt::format("band_levels = {} levels is invalid: expected 1 to {} levels", levels.size(),
                    kMaxBandLevels));
  }
  for (std::size_t i = 0; i < levels.size(); ++i) {
    if (!(levels[i] > 0.0 && levels[i] < 1.0)) {
      throw std::invalid_argument(fmt::format(
          "band_levels = {} is invalid: expected fractions of the speed in (0, 1)", levels[i]));
    }
    if (std::find(levels.begin(), levels.begin() + i, levels[i]) != levels.begin() + i) {
      throw std::invalid_argument(
          fmt::format("band_levels = {} is invalid: expected distinct levels", levels[i]));
    }
  }
  if (!(tolerance >= 1e-9 && tolerance <= 0.1)) {
    throw std::invalid_argument(
        fmt::format("tolerance = {} is invalid: expected 1e-9 <= tolerance <= 0.1", tolerance));
  }
  if (!(first_step >= 1e-6 && first_step <= 1.0)) {
    throw std::invalid_argument(
        fmt::format("first_step = {} is invalid: expected 1e-6 <= first_step <= 1", first_step));
  }
  from_rest.Validate();
}

const BandEdge* SpeedBand::Edge(double level, bool up_side) const {
  for (const BandEdge& e : up_side ? up : down) {
    if (e.level == level) return &e;
  }
  return nullptr;
}

bool SpeedBand::Contains(double level, double parameter) const {
  const BandEdge* lo = Edge(level, false);
  const BandEdge* hi = Edge(level, true);
  return lo != nullptr && hi != nullptr && parameter >= lo->inside && parameter <= hi->inside;
}

SpeedBand ComputeSpeedBand(const RobotFamily& family, const std::string& name, double value,
                           double from, double to, const SpeedBandOptions& options) {
  options.Validate();
  if (!(from <= value && value <= to) || !std::isfinite(from) || !std::isfinite(to)) {
    throw std::invalid_argument(fmt::format(
        "{} = {} is invalid: expected a finite range {} <= {} <= {}", name, value, from, name, to));
  }
  SpeedBand band;
  band.name = name;
  band.value = value;
  band.from = from;
  band.to = to;
  SpeedFromRest speed(family, options.from_rest);
  const Attractors nominal = speed.Attractors(value);
  band.nominal_speed = nominal.mean_velocity;
  band.evaluations = speed.evaluations();
  band.unsettled_starts = UnsettledStarts(nominal);
  band.starts = nominal.starts;
  if (!std::isfinite(band.nominal_speed) || band.nominal_speed == 0.0) {
    band.status = SpeedBandStatus::kNoSpeed;
    return band;
  }
  if (band.unsettled_starts > 0) {
    band.status = SpeedBandStatus::kUnsettled;
    return band;
  }
  const double lowest = *std::min_element(options.levels.begin(), options.levels.end());
  const double width = options.tolerance * (to - from);
  for (const bool up_side : {false, true}) {
    const std::vector<WalkPoint> walk =
        Walk(speed, band.nominal_speed, value, up_side ? to : from, options.first_step, lowest);
    for (double level : options.levels) {
      (up_side ? band.up : band.down)
          .push_back(FindEdge(speed, band.nominal_speed, walk, level, width));
    }
  }
  band.status = SpeedBandStatus::kOk;
  band.evaluations = speed.evaluations();
  return band;
}

}  // namespace capsubot
