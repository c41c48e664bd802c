#include "capsubot/optimize_result.hpp"

namespace capsubot {

const char* OptimizeStatusName(OptimizeStatus status) {
  switch (status) {
    case OptimizeStatus::kNotRun:
      return "not_run";
    case OptimizeStatus::kOk:
      return "ok";
    case OptimizeStatus::kNoValidOrbit:
      return "no_valid_orbit";
    case OptimizeStatus::kMaxEvaluations:
      return "max_evaluations";
    case OptimizeStatus::kMaxTime:
      return "max_time";
    case OptimizeStatus::kRoundoffLimited:
      return "roundoff_limited";
    case OptimizeStatus::kForcedStop:
      return "forced_stop";
    case OptimizeStatus::kInvalidArguments:
      return "invalid_arguments";
    case OptimizeStatus::kOutOfMemory:
      return "out_of_memory";
    case OptimizeStatus::kFailure:
      return "failure";
  }
  return "unknown";
}

}  // namespace capsubot
