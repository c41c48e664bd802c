#include "capsubot/continue/gait_robustness.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "capsubot/continue/parameter_branch.hpp"

namespace capsubot {
namespace {

// The nearest special point other than a speed extremum on one part of the branch: the
// backward part (points before the start, walked from the start down) or the forward part.
MotionLimit NearestLimit(const Branch& b, bool forward) {
  MotionLimit limit;
  const SpecialPoint* nearest = nullptr;
  for (const SpecialPoint& sp : b.special_points) {
    if (sp.type == SpecialPointType::kSpeedExtremum) continue;
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
  return limit;
}

// The motion through `m.start` continued in the model parameter `name` over [from, to].
ParameterRobustness Continue(const MotionToContinue& m, const char* name, double value, double from,
                             double to, const ContinuationOptions& continuation) {
  m.params.Validate();
  return ContinueRobustness(NamedParameterFamily(m.forcing, m.params, m.alpha, name), m.start, name,
                            value, from, to, continuation);
}

}  // namespace

std::string MotionLimit::Text(const std::string& name, const std::string& value) const {
  const MotionLimit& l = *this;
  if (!l.special) {
    switch (l.end) {
      case BranchEnd::kRangeEnd:
        return fmt::format("no limit up to the end of the range, {} = {}", name, value);
      case BranchEnd::kLost:
        return fmt::format("lost at {} = {} (the continuation cannot proceed there)", name, value);
      case BranchEnd::kMaxPoints:
        return fmt::format("no limit found up to {} = {} (the most points were reached)", name,
                           value);
      case BranchEnd::kNotRun:
      case BranchEnd::kEventChange:  // ends curves, never branches
      case BranchEnd::kGrazing:      // its grazing is the special point found before it
      case BranchEnd::kHalfPeriod:   // a gait's one-impact motion has period 1
        break;
    }
    return "not computed";
  }
  const char* meaning = "";
  switch (l.type) {
    case SpecialPointType::kFold:
      meaning = "the motion ends in a fold";
      break;
    case SpecialPointType::kPeriodDoubling:
      meaning = "a period doubling: the motion changes stability";
      break;
    case SpecialPointType::kNeimarkSacker:
      meaning = "a Neimark-Sacker point: the motion changes stability";
      break;
    case SpecialPointType::kGrazing:
      meaning = "a grazing: an impact appears or disappears";
      break;
    case SpecialPointType::kSegmentChange:
      meaning = "a segment change: the stick/slide pattern changes";
      break;
    case SpecialPointType::kSpeedExtremum:
      break;
  }
  return fmt::format("{} at {} = {}", meaning, name, value);
}

const char* MotionLimit::Name() const {
  return special ? SpecialPointTypeName(type) : BranchEndName(end);
}

void RobustnessOptions::Validate() const {
  if (!(t0_factor > 1.0) || !std::isfinite(t0_factor)) {
    throw std::invalid_argument(
        fmt::format("t0_factor = {} is invalid: expected a finite number > 1", t0_factor));
  }
}

ParameterRobustness ContinueRobustness(const RobotFamily& family, const PhaseState& start,
                                       const std::string& name, double value, double from,
                                       double to, const ContinuationOptions& continuation) {
  ParameterRobustness r;
  r.name = name;
  ContinuationOptions o = continuation;
  o.from = from;
  o.to = to;
  o.start = value;
  o.both_directions = true;
  const Branch b = ContinueBranch(family, start, o);
  r.value = value;
  r.from = from;
  r.to = to;
  r.status = b.status;
  r.message = b.message;
  if (b.status == ContinuationStatus::kOk) {
    r.down = NearestLimit(b, false);
    r.up = NearestLimit(b, true);
  }
  return r;
}

GaitRobustness ComputeMotionRobustness(const MotionToContinue& m,
                                       const RobustnessOptions& options) {
  options.Validate();
  GaitRobustness g;
  const ContinuationOptions& c = options.continuation;
  const double T0 = m.params.T0, e = m.params.e, alpha = m.alpha;
  g.parameters.push_back(Continue(m, "T0", T0, T0 / options.t0_factor, T0 * options.t0_factor, c));
  g.parameters.push_back(Continue(m, "e", e, 0.0, 1.0, c));
  g.parameters.push_back(Continue(m, "alpha", alpha, 0.5 * alpha, 0.5 * (1.0 + alpha), c));
  return g;
}

GaitRobustness ComputeGaitRobustness(const Orbit& orbit, const RobustnessOptions& options) {
  return ComputeMotionRobustness({orbit.forcing, Params{orbit.T0, orbit.e, 0.0}, orbit.alpha,
                                  OrbitImpactState(orbit, orbit.forcing)},
                                 options);
}

std::string GaitRobustness::Summary(const std::string& indent) const {
  std::string t;
  for (const ParameterRobustness& p : parameters) {
    if (p.status != ContinuationStatus::kOk) {
      t += fmt::format("{}{}: not followed ({})\n", indent, p.name, p.message);
      continue;
    }
    t += fmt::format("{}{} = {:.6g}, searched in [{:.6g}, {:.6g}]:\n", indent, p.name, p.value,
                     p.from, p.to);
    t += fmt::format("{}  down: {}\n", indent,
                     p.down.Text(p.name, fmt::format("{:.6g}", p.down.parameter)));
    t += fmt::format("{}  up:   {}\n", indent,
                     p.up.Text(p.name, fmt::format("{:.6g}", p.up.parameter)));
  }
  return t;
}

}  // namespace capsubot
