#include "capsubot/job/orbits_job.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "capsubot/model/force_spec.hpp"
#include "capsubot/model/limits.hpp"

namespace capsubot {

void OrbitsJobOptions::Validate() const {
  RefusePulse(robot.forcing, "orbits");
  robot.params.Validate();
  margins.Validate();
  if (max_evaluations < 1 || max_evaluations > kMaxOrbitEvaluations) {
    throw std::invalid_argument(
        fmt::format("max_evaluations = {} is invalid: expected 1 <= max_evaluations <= {}",
                    max_evaluations, kMaxOrbitEvaluations));
  }
}

OrbitsJobResult RunOrbitsJob(const OrbitsJobOptions& options) {
  options.Validate();
  OrbitsJobResult r;
  r.options = options;
  r.options.interrupt = nullptr;
  r.orbits = FindRobotOrbits(options.robot, options.margins, &r.complete, options.max_evaluations,
                             [&options] { Poll(options.interrupt); });
  return r;
}

}  // namespace capsubot
