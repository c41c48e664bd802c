#include "capsubot/continue/gait_robustness.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <utility>

#include "capsubot/continue/parameter_branch.hpp"

namespace capsubot {
namespace {

// Whether the motion ends or loses stability at a special point (a fold, period doubling or
// Neimark-Sacker point); at a grazing or segment change it goes on with other impacts or
// another stick/slide pattern, and the branch goes on through it.
bool EndsOrDestabilises(SpecialPointType type) {
  return type == SpecialPointType::kFold || type == SpecialPointType::kPeriodDoubling ||
         type == SpecialPointType::kNeimarkSacker;
}

// The nearest fold, period doubling or Neimark-Sacker point on one part of the branch (`points`:
// the branch's special points kept, ParameterRobustness::special_points): the backward part
// (points before the start, walked from the start down) or the forward part.
MotionLimit NearestLimit(const Branch& b, const std::vector<SpecialPoint>& points, bool forward) {
  MotionLimit limit;
  const SpecialPoint* nearest = nullptr;
  for (const SpecialPoint& sp : points) {
    if (!EndsOrDestabilises(sp.type)) continue;
    const bool on_forward = sp.after_point >= b.start_index;
    if (on_forward != forward) continue;
    // Backward: the one closest to the start has the largest index; forward: the smallest.
    if (nearest == nullptr || (forward ? sp.after_point < nearest->after_point
                                       : sp.after_point >= nearest->after_point)) {
      nearest = &sp;
    }
  }
  if (nearest != nullptr) {
    limit.special = true;
    limit.type = nearest->type;
    limit.parameter = nearest->parameter;
    limit.located = nearest->located;
    limit.accuracy = nearest->accuracy;
    limit.motion = nearest->motion;
    return limit;
  }
  limit.end = forward ? b.forward_end : b.backward_end;
  limit.parameter = forward ? b.forward_parameter : b.backward_parameter;
  // A direction that ends at a wall: the motion with these impacts ends at that grazing, a
  // located special point of the branch.
  if (limit.end == BranchEnd::kGrazing) {
    for (const SpecialPoint& sp : b.special_points) {
      if (sp.type != SpecialPointType::kGrazing ||
          !(std::abs(sp.parameter - limit.parameter) <=
            std::abs(sp.accuracy) + 1e-12 * std::abs(limit.parameter))) {
        continue;
      }
      limit.special = true;
      limit.type = sp.type;
      limit.parameter = sp.parameter;
      limit.located = sp.located;
      limit.accuracy = sp.accuracy;
      limit.motion = sp.motion;
    }
  }
  return limit;
}

// The impacts of a periodic motion with its chattering sequences set apart: per wall, the
// chattering sequences (kChatterRun or more impacts in a row on the wall, each slower than the
// one before, or a run that ends with the inner body resting on the wall: the simulator sums
// the infinitely many impacts at their accumulation point after a number of its own choosing)
// and the impacts outside them.
struct ImpactSignature {
  int period = 0;
  std::int64_t sequences[2] = {0, 0};  // right, left
  std::int64_t free_impacts[2] = {0, 0};

  bool operator==(const ImpactSignature& o) const {
    return period == o.period && sequences[0] == o.sequences[0] && sequences[1] == o.sequences[1] &&
           free_impacts[0] == o.free_impacts[0] && free_impacts[1] == o.free_impacts[1];
  }
};

// The fewest impacts of a chattering sequence not ended by a stick: two slowing impacts in a
// row are a motion's own pattern as often as not; from three on, the speeds shrink as a chatter's.
constexpr std::int64_t kChatterRun = 3;

// Sorts the impacts of one run into runs on one wall (ended by an impact on the other wall, a
// stick or the end of the run).
class SignatureObserver : public SimObserver {
 public:
  explicit SignatureObserver(ImpactSignature& s) : s_(s) {}
  void OnEvent(const SimEvent& e) override {
    const int wall = e.after.x > 0.5 ? 0 : 1;
    if (e.kind == EventKind::kStick) {
      Flush(wall, true);
    } else if (e.kind == EventKind::kImpactRight || e.kind == EventKind::kImpactLeft) {
      Flush(1 - wall, false);
      const double speed = std::abs(e.u_before);
      slowing_[wall] = slowing_[wall] && (run_[wall] == 0 || speed < last_[wall]);
      last_[wall] = speed;
      ++run_[wall];
    }
  }
  void Finish() {
    for (int w : {0, 1}) Flush(w, false);
  }

 private:
  void Flush(int wall, bool stick) {
    if (stick || (run_[wall] >= kChatterRun && slowing_[wall])) {
      ++s_.sequences[wall];
    } else {
      s_.free_impacts[wall] += run_[wall];
    }
    run_[wall] = 0;
    slowing_[wall] = true;
  }

  ImpactSignature& s_;
  std::int64_t run_[2] = {0, 0};
  bool slowing_[2] = {true, true};
  double last_[2] = {0.0, 0.0};
};

// The signature of the periodic motion `m` of `robot`: one run of its period from its state.
ImpactSignature Signature(const RobotModel& robot, const PeriodicMotion& m,
                          const ShootingOptions& shooting) {
  ImpactSignature s;
  s.period = m.period;
  SignatureObserver observer(s);
  SimOptions o;
  o.alpha = robot.alpha;
  o.x0 = m.state.x;
  o.u0 = m.state.u;
  o.v0 = m.state.v;
  o.periods = m.period;
  o.chatter_velocity = shooting.chatter_velocity;
  o.max_events_per_period = shooting.max_events_per_period;
  Simulate(robot.forcing.WithPhase(robot.forcing.phi0() + m.state.psi), robot.params, o, &observer);
  observer.Finish();
  return s;
}

// Whether a grazing of the branch only changes how many impacts a chattering sequence has
// before the simulator sums the rest: the signatures of the points on its two sides agree.
bool ChatterChange(const RobotFamily& family, const Branch& b, const SpecialPoint& sp,
                   const ShootingOptions& shooting) {
  if (sp.type != SpecialPointType::kGrazing) return false;
  const auto i = static_cast<std::size_t>(sp.after_point);
  if (i + 1 >= b.points.size()) return false;
  const BranchPoint& p0 = b.points[i];
  const BranchPoint& p1 = b.points[i + 1];
  return Signature(family(p0.parameter), p0.motion, shooting) ==
         Signature(family(p1.parameter), p1.motion, shooting);
}

// Every value of a parameter's robustness times `factor` (the family's parameter to the unit
// reported).
void ScaleValues(ParameterRobustness& p, double factor) {
  for (double* v : {&p.value, &p.from, &p.to, &p.down.parameter, &p.down.accuracy, &p.up.parameter,
                    &p.up.accuracy, &p.band.value, &p.band.from, &p.band.to}) {
    *v *= factor;
  }
  for (SpecialPoint& sp : p.special_points) {
    sp.parameter *= factor;
    sp.accuracy *= factor;
  }
  for (std::vector<BandEdge>* side : {&p.band.down, &p.band.up}) {
    for (BandEdge& e : *side) {
      for (double* v : {&e.parameter, &e.inside, &e.outside, &e.accuracy}) *v *= factor;
    }
  }
}

// The branch of `p` through `start`, with its special points and nearest limits in `r`.
void FollowBranch(const RobustnessParameter& p, const PhaseState& start,
                  const ContinuationOptions& continuation, ParameterRobustness& r) {
  ContinuationOptions o = continuation;
  o.from = p.from;
  o.to = p.to;
  o.start = p.value;
  o.both_directions = true;
  const Branch b = ContinueBranch(p.family, start, o);
  r.status = b.status;
  r.message = b.message;
  if (b.status != ContinuationStatus::kOk) return;
  // The grazing where a direction ends (the motion meets a wall there and is not followed on)
  // is that end (BranchEnd::kGrazing, told by NearestLimit when nothing nearer ends the motion),
  // neither a chatter count's change nor a point the motion goes through.
  const auto at = [](const SpecialPoint& sp, double end) {
    return std::abs(sp.parameter - end) <= std::abs(sp.accuracy) + 1e-12 * std::abs(end);
  };
  const auto ends_branch = [&](const SpecialPoint& sp) {
    return (b.forward_end == BranchEnd::kGrazing && at(sp, b.forward_parameter)) ||
           (b.backward_end == BranchEnd::kGrazing && at(sp, b.backward_parameter));
  };
  for (const SpecialPoint& sp : b.special_points) {
    if (sp.type == SpecialPointType::kSpeedExtremum || ends_branch(sp)) continue;
    if (ChatterChange(p.family, b, sp, continuation.shooting)) {
      ++r.chatter_changes;
    } else {
      r.special_points.push_back(sp);
    }
  }
  r.down = NearestLimit(b, r.special_points, false);
  r.up = NearestLimit(b, r.special_points, true);
}

// What happens to the motion at a special point, in plain words.
const char* Meaning(SpecialPointType type) {
  switch (type) {
    case SpecialPointType::kFold:
      return "the motion ends in a fold";
    case SpecialPointType::kPeriodDoubling:
      return "a period doubling: the motion changes stability";
    case SpecialPointType::kNeimarkSacker:
      return "a Neimark-Sacker point: the motion changes stability";
    case SpecialPointType::kGrazing:
      return "a grazing: an impact appears or disappears";
    case SpecialPointType::kSegmentChange:
      return "a segment change: the stick/slide pattern changes";
    case SpecialPointType::kSpeedExtremum:
      break;
  }
  return "a speed extremum";
}

// The special points inside a band listed one by one in the text.
constexpr std::size_t kListedInBand = 6;

// One edge of a band in words: "0.982 (+-0.0015)" or "beyond 2 (the range's end)".
std::string EdgeText(const BandEdge& e, const ValueText& value) {
  if (!e.within) return fmt::format("beyond {} (the end of the range)", value(e.parameter));
  return fmt::format("{} (+-{:.2g})", value(e.parameter), 0.5 * e.accuracy);
}

// T0 (relative to its value), e over [0, 1] and alpha halfway to each end of (0, 1).
std::vector<RobustnessParameter> ModelParameters(const RobotModel& m,
                                                 const RobustnessOptions& options) {
  const auto along = [&](const char* name) { return NamedParameterFamily(m, name); };
  return {RelativeParameter("T0", along("T0"), m.params.T0, options.t0_factor),
          {"e", along("e"), m.params.e, 0.0, 1.0, 1.0},
          {"alpha", along("alpha"), m.alpha, 0.5 * m.alpha, 0.5 * (1.0 + m.alpha), 1.0}};
}

}  // namespace

std::string MotionLimit::Text(const std::string& name, const std::string& value) const {
  const MotionLimit& l = *this;
  if (!l.special) {
    switch (l.end) {
      case BranchEnd::kRangeEnd:
        return fmt::format("no limit up to the end of the range, {} = {}", name, value);
      case BranchEnd::kLost:
        return fmt::format(
            "the continuation stops at {} = {}: it cannot follow the motion further (a limit of "
            "the method, not necessarily of the motion: see the speed band)",
            name, value);
      case BranchEnd::kMaxPoints:
        return fmt::format("no limit found up to {} = {} (the most points were reached)", name,
                           value);
      case BranchEnd::kGrazing:
        return fmt::format(
            "the motion ends at a grazing at {} = {}: the inner body meets a wall and the motion "
            "with these impacts goes no further",
            name, value);
      case BranchEnd::kHalfPeriod:
        return fmt::format("the branch meets the motion of half its period at {} = {}", name,
                           value);
      case BranchEnd::kNotRun:
      case BranchEnd::kEventChange:  // ends curves, never branches
        break;
    }
    return "not computed";
  }
  return fmt::format("{} at {} = {}", Meaning(l.type), name, value);
}

std::string ParameterRobustness::BandText(const ValueText& value, const std::string& speed,
                                          const std::string& indent) const {
  const SpeedBand& b = band;
  if (b.status == SpeedBandStatus::kNotRun) return "";
  if (b.status == SpeedBandStatus::kNoSpeed) {
    return fmt::format(
        "{}speed band: none, the robot does not move from rest here (mean speed "
        "{})\n",
        indent, speed);
  }
  if (b.status == SpeedBandStatus::kUnsettled) {
    return fmt::format(
        "{}speed band: none, the speed from rest has not settled here: {} of {} "
        "starts end in no periodic motion whose record's halves differ by more "
        "than {:g} %\n",
        indent, b.unsettled_starts, b.starts, 100.0 * kSettledHalves);
  }
  std::string t = fmt::format(
      "{}speed band (simulated from rest): the mean speed from rest, {}, stays at or above\n",
      indent, speed);
  for (std::size_t i = 0; i < b.down.size() && i < b.up.size(); ++i) {
    t += fmt::format("{}  {:g} % of it for {} from {} to {}\n", indent, 100.0 * b.down[i].level,
                     name, EdgeText(b.down[i], value), EdgeText(b.up[i], value));
  }
  const std::vector<SpecialPoint> inside = InBand();
  for (std::size_t i = 0; i < inside.size() && i < kListedInBand; ++i) {
    const SpecialPoint& sp = inside[i];
    t += fmt::format("{}  inside the {:g} % band: {} at {} = {}; {}\n", indent,
                     100.0 * b.down.front().level, Meaning(sp.type), name, value(sp.parameter),
                     EndsOrDestabilises(sp.type) ? "the speed from rest stays in the band"
                                                 : "the motion goes on through it");
  }
  if (inside.size() > kListedInBand) {
    t += fmt::format("{}  inside the {:g} % band: {} more special points\n", indent,
                     100.0 * b.down.front().level, inside.size() - kListedInBand);
  }
  if (chatter_changes > 0) {
    t += fmt::format("{}  ({} changes of a chattering impact count left out: not bifurcations)\n",
                     indent, chatter_changes);
  }
  return t;
}

const char* MotionLimit::Name() const {
  return special ? SpecialPointTypeName(type) : BranchEndName(end);
}

void RobustnessOptions::Validate() const {
  if (!(t0_factor > 1.0) || !std::isfinite(t0_factor)) {
    throw std::invalid_argument(
        fmt::format("t0_factor = {} is invalid: expected a finite number > 1", t0_factor));
  }
  if (speed_bands) band.Validate();
}

std::vector<SpecialPoint> ParameterRobustness::InBand() const {
  std::vector<SpecialPoint> in;
  if (band.status != SpeedBandStatus::kOk || band.down.empty()) return in;
  for (const SpecialPoint& sp : special_points) {
    if (!band.Contains(band.down.front().level, sp.parameter)) continue;
    // The same point found from both of its sides (a branch through it and back) once.
    const bool again = std::any_of(in.begin(), in.end(), [&](const SpecialPoint& o) {
      return o.type == sp.type &&
             std::abs(o.parameter - sp.parameter) <= std::max(o.accuracy, sp.accuracy);
    });
    if (!again) in.push_back(sp);
  }
  return in;
}

RobustnessParameter RelativeParameter(const std::string& name, const RobotFamily& family,
                                      double value, double factor, double unit) {
  RobustnessParameter p;
  p.name = name;
  p.family = [family, value](double lambda) { return family(lambda * value); };
  p.value = 1.0;
  p.from = 1.0 / factor;
  p.to = factor;
  p.scale = value * unit;
  return p;
}

ParameterRobustness ContinueRobustness(const RobustnessParameter& p, const PhaseState& start,
                                       const RobustnessOptions& options) {
  ParameterRobustness r;
  r.name = p.name;
  r.value = p.value;
  r.from = p.from;
  r.to = p.to;
  // A part that cannot be computed says why and leaves the other parts (each is a study of
  // its own, as a point of a sweep).
  try {
    FollowBranch(p, start, options.continuation, r);
  } catch (const std::invalid_argument& e) {
    r.status = ContinuationStatus::kNotRun;
    r.message = e.what();
  }
  if (options.speed_bands) {
    r.band = ComputeSpeedBand(p.family, p.name, p.value, p.from, p.to, options.band);
  }
  ScaleValues(r, p.scale);
  return r;
}

GaitRobustness ComputeMotionRobustness(const MotionToContinue& m,
                                       const RobustnessOptions& options) {
  options.Validate();
  m.robot.params.Validate();
  GaitRobustness g;
  for (const RobustnessParameter& p : ModelParameters(m.robot, options)) {
    g.parameters.push_back(ContinueRobustness(p, m.start, options));
  }
  return g;
}

GaitRobustness ComputeSpeedBands(const RobotModel& robot, const RobustnessOptions& options,
                                 const std::string& why) {
  options.Validate();
  robot.params.Validate();
  GaitRobustness g;
  for (const RobustnessParameter& p : ModelParameters(robot, options)) {
    ParameterRobustness r;
    r.name = p.name;
    r.value = p.value;
    r.from = p.from;
    r.to = p.to;
    r.message = why;
    r.band = ComputeSpeedBand(p.family, p.name, p.value, p.from, p.to, options.band);
    ScaleValues(r, p.scale);
    g.parameters.push_back(std::move(r));
  }
  return g;
}

GaitRobustness ComputeGaitRobustness(const Orbit& orbit, const RobustnessOptions& options) {
  return ComputeMotionRobustness({{orbit.forcing, Params{orbit.T0, orbit.e}, orbit.alpha},
                                  OrbitImpactState(orbit, orbit.forcing)},
                                 options);
}

GaitRobustness ComputeMotionRobustness(const MotionToContinue& motion) {
  const RobustnessOptions defaults;
  return ComputeMotionRobustness(motion, defaults);
}

GaitRobustness ComputeGaitRobustness(const Orbit& orbit) {
  const RobustnessOptions defaults;
  return ComputeGaitRobustness(orbit, defaults);
}

std::string GaitRobustness::Summary(const std::string& indent) const {
  std::string t;
  const auto value = [](double v) { return fmt::format("{:.6g}", v); };
  for (const ParameterRobustness& p : parameters) {
    t += fmt::format("{}{} = {:.6g}, searched in [{:.6g}, {:.6g}]:\n", indent, p.name, p.value,
                     p.from, p.to);
    if (p.status != ContinuationStatus::kOk) {
      t += fmt::format("{}  continuation: not followed ({})\n", indent, p.message);
    } else {
      t += fmt::format("{}  down: {}\n", indent, p.down.Text(p.name, value(p.down.parameter)));
      t += fmt::format("{}  up:   {}\n", indent, p.up.Text(p.name, value(p.up.parameter)));
    }
    t += p.BandText(value, fmt::format("{:.6g} omega L", p.band.nominal_speed), indent + "  ");
  }
  return t;
}

}  // namespace capsubot
