// capsubot periodic as one call: Newton shooting from the start the options give.

#include "capsubot/job/periodic_job.hpp"

namespace capsubot {
namespace {

// The state Newton's method starts from (after the transient, if any).
PhaseState StartState(const PeriodicStart& start) {
  if (const auto* rest = std::get_if<PeriodicFromRest>(&start)) {
    return RestStart(rest->x0, rest->psi);
  }
  if (const auto* known = std::get_if<PeriodicOfPeriod>(&start)) return known->state;
  return std::get<PeriodicFromState>(start).state;
}

// The periods simulated before shooting: the start's (none with the period known).
int Transient(const PeriodicStart& start) {
  if (const auto* rest = std::get_if<PeriodicFromRest>(&start)) return rest->transient;
  if (const auto* state = std::get_if<PeriodicFromState>(&start)) return state->transient;
  return 0;
}

}  // namespace

void PeriodicJobOptions::Validate() const {
  RequirePhase("psi", StartState(start).psi);  // a start phase in radians, as phi0
}

PeriodicJobResult RunPeriodicJob(const PeriodicJobOptions& options) {
  options.Validate();
  ShootingOptions shooting = options.shooting;
  shooting.transient = Transient(options.start);
  PeriodicJobResult result;
  result.options = options;
  result.options.shooting = shooting;
  result.options.shooting.interrupt = {};
  result.options.on_stage = {};
  TellStage(options.on_stage, "periodic: Newton shooting");
  const PhaseState state = StartState(options.start);
  const RobotModel& robot = options.robot;
  if (const auto* known = std::get_if<PeriodicOfPeriod>(&options.start)) {
    result.motion = ShootPeriodicMotion(robot, state, known->period, shooting);
  } else {
    result.motion = FindPeriodicMotion(robot, state, shooting);
  }
  TellStage(options.on_stage, "");
  return result;
}

}  // namespace capsubot
