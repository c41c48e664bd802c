// `capsubot continue` as one call (docs/continuation.md).

#include "capsubot/job/continue_job.hpp"

#include <fmt/format.h>

#include <cmath>
#include <stdexcept>

#include "capsubot/continue/branch_switch.hpp"
#include "capsubot/continue/parameter_branch.hpp"

namespace capsubot {
namespace {

// The branch's first special point of the type, a located one if `located` (null if none):
// the first met from the start, the nearest to it along the arclength (either direction).
const SpecialPoint* First(const Branch& b, SpecialPointType type, bool located) {
  const SpecialPoint* first = nullptr;
  for (const SpecialPoint& sp : b.special_points) {
    if (sp.type == type && (sp.located || !located) &&
        (first == nullptr || std::abs(sp.arclength) < std::abs(first->arclength))) {
      first = &sp;
    }
  }
  return first;
}

SpecialPointType TypeOf(SwitchPoint point) {
  return point == SwitchPoint::kGrazing ? SpecialPointType::kGrazing
                                        : SpecialPointType::kPeriodDoubling;
}

// The branch switched to at the branch's first located period doubling or first grazing
// (located or not: the grazing switch steps far wider than its bracket).
SwitchResult Switch(const ContinueJobOptions& options, const Branch& branch) {
  SwitchResult s;
  s.point = *options.switch_at;
  const bool grazing = s.point == SwitchPoint::kGrazing;
  const SpecialPoint* at = First(branch, TypeOf(s.point), !grazing);
  if (at == nullptr) return s;
  s.at = *at;
  const RobotFamily family = NamedParameterFamily(options.robot, options.param);
  s.branch = grazing ? SwitchAtGrazing(family, branch, *at, options.continuation)
                     : SwitchAtPeriodDoubling(family, *at, options.continuation);
  return s;
}

FollowResult FollowCurve(const ContinueJobOptions& options, const Branch& branch) {
  const FollowOptions& f = *options.follow;
  FollowResult r;
  r.param2 = f.param2;
  r.type = f.type;
  r.value2 =
      RobotValueInRange(options.robot, f.param2, {"from2", f.from2}, {"to2", f.to2}, "curve");
  r.curve.type = f.type;
  const SpecialPoint* sp = First(branch, f.type, true);
  if (sp == nullptr) {
    r.curve.message = fmt::format("no located {} on the branch in {}: no curve to follow",
                                  SpecialPointTypeName(f.type), options.param);
    return r;
  }
  r.at = *sp;
  CurveOptions c;
  c.from2 = f.from2;
  c.to2 = f.to2;
  c.start2 = r.value2;
  c.continuation = options.continuation;
  r.curve =
      FollowSpecialPoint(NamedParameterSurface(options.robot, options.param, f.param2), *sp, c);
  return r;
}

}  // namespace

const char* SwitchPointName(SwitchPoint point) { return SpecialPointTypeName(TypeOf(point)); }

SwitchPoint ParseSwitchPoint(const std::string& name) {
  for (SwitchPoint point : {SwitchPoint::kPeriodDoubling, SwitchPoint::kGrazing}) {
    if (name == SwitchPointName(point)) return point;
  }
  throw std::invalid_argument(
      fmt::format("switch = {} is invalid: expected period_doubling or grazing", name));
}

void ContinueJobOptions::Validate() const {
  robot.params.Validate();
  if (const PhaseState* state = std::get_if<PhaseState>(&start)) RequirePhase("psi", state->psi);
  NamedParameterFamily(robot, param);        // the name, and the force has it
  ContinuationOptions range = continuation;  // the options' own rules, the start's value aside
  range.start = range.from;
  range.Validate();
  RobotValueInRange(robot, param, {"from", continuation.from}, {"to", continuation.to}, "branch");
  if (!follow) return;
  NamedParameterSurface(robot, param, follow->param2);
  if (!IsFollowable(follow->type)) {
    throw std::invalid_argument(fmt::format(
        "follow = {} is invalid: expected one of fold, period_doubling, grazing, speed_extremum",
        SpecialPointTypeName(follow->type)));
  }
  CurveOptions curve;
  curve.from2 = follow->from2;
  curve.to2 = follow->to2;
  curve.start2 = follow->from2;  // the range's own rules, the robot's value aside
  curve.continuation = range;
  curve.Validate();
  RobotValueInRange(robot, follow->param2, {"from2", follow->from2}, {"to2", follow->to2}, "curve");
}

ContinueJobResult RunContinueJob(const ContinueJobOptions& options) {
  options.Validate();
  const int stages = 1 + (options.switch_at ? 1 : 0) + (options.follow ? 1 : 0);
  int stage = 0;
  const auto tell = [&](const std::string& what) {
    TellStage(options.on_stage, fmt::format("continue: {}/{} {}", ++stage, stages, what));
  };
  ContinueJobResult result;
  result.param = options.param;
  tell(fmt::format("the branch in {}", options.param));
  const PhaseState start = std::holds_alternative<FromOneImpactOrbit>(options.start)
                               ? OneImpactOrbitStart(options.robot)
                               : std::get<PhaseState>(options.start);
  result.branch = ContinueParameter(options.robot, options.param, start, options.continuation);
  if (options.switch_at) {
    tell(*options.switch_at == SwitchPoint::kGrazing
             ? "the branch beyond its first grazing"
             : "the period-2p branch born at its first period doubling");
    result.switched = Switch(options, result.branch);
  }
  if (options.follow) {
    tell(fmt::format("the {} in ({}, {})", SpecialPointTypeName(options.follow->type),
                     options.param, options.follow->param2));
    result.follow = FollowCurve(options, result.branch);
  }
  TellStage(options.on_stage, "");
  return result;
}

}  // namespace capsubot
