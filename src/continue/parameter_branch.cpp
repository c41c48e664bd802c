#include "capsubot/continue/parameter_branch.hpp"

#include <fmt/format.h>

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "capsubot/model/force_spec.hpp"
#include "capsubot/model/model_parameter.hpp"
#include "capsubot/orbit/robot_orbits.hpp"
#include "capsubot/orbit/stability.hpp"

namespace capsubot {

PhaseState OrbitImpactState(const Orbit& orbit, const Forcing& forcing) {
  return {1.0, -orbit.e * orbit.u, orbit.v_plus, orbit.forcing.phi0() - forcing.phi0()};
}

PhaseState OneImpactOrbitStart(const RobotModel& robot) {
  RefusePulse(robot.forcing, "from_orbit (a start on the analytic one-impact orbit)");
  const std::vector<Solution> orbits = FindRobotOrbits(robot);
  const Solution* best = nullptr;
  double best_radius = 0.0;
  for (const Solution& s : orbits) {
    if (!s.validity.valid()) continue;
    const double radius = ComputeStability(s.orbit).spectral_radius;
    if (best == nullptr || radius < best_radius) {
      best = &s;
      best_radius = radius;
    }
  }
  if (best == nullptr) {
    throw std::invalid_argument(fmt::format(
        "from_orbit is invalid for this robot: it has no valid one-impact orbit at alpha = {} "
        "(capsubot orbits lists them)",
        robot.alpha));
  }
  return OrbitImpactState(best->orbit, robot.forcing);
}

RobotFamily NamedParameterFamily(const RobotModel& robot, const std::string& param) {
  int harmonic = 0;
  const ModelParameter which = ParseRobotParameter(param, &harmonic);
  CheckRobotParameter(robot.forcing, which, harmonic);
  return [base = robot, which, harmonic](double value) {
    RobotModel r = base;
    SetParameter(r, which, harmonic, value);
    return r;
  };
}

double RobotValueInRange(const RobotModel& robot, const std::string& param, const RangeEnd& from,
                         const RangeEnd& to, const char* what) {
  int harmonic = 0;
  const ModelParameter which = ParseRobotParameter(param, &harmonic);
  const double value = ParameterValue(robot, which, harmonic);
  if (!(value >= from.value && value <= to.value)) {
    throw std::invalid_argument(fmt::format(
        "the robot's {} = {} is outside the range: expected {} = {} <= {} <= {} = {} (the {} "
        "starts at the robot's value)",
        param, value, from.name, from.value, param, to.name, to.value, what));
  }
  return value;
}

RobotSurface NamedParameterSurface(const RobotModel& robot, const std::string& param,
                                   const std::string& param2) {
  int h1 = 0, h2 = 0;
  const ModelParameter p1 = ParseRobotParameter(param, &h1);
  CheckRobotParameter(robot.forcing, p1, h1);
  ModelParameter p2 = ModelParameter::kA;
  try {  // the messages name the second parameter: "param2 = ..." instead of "parameter = ..."
    p2 = ParseRobotParameter(param2, &h2);
    CheckRobotParameter(robot.forcing, p2, h2);
  } catch (const std::invalid_argument& e) {
    const std::string message = e.what(), word = "parameter";
    if (message.compare(0, word.size(), word) != 0) throw;
    throw std::invalid_argument("param2" + message.substr(word.size()));
  }
  // A is the sine coefficient b1 of the harmonic family: the same parameter.
  const auto key = [](ModelParameter p, int h) {
    return p == ModelParameter::kA ? std::make_pair(ModelParameter::kSin, 1) : std::make_pair(p, h);
  };
  if (key(p1, h1) == key(p2, h2)) {
    throw std::invalid_argument(fmt::format(
        "param2 = {} is invalid: expected a parameter other than param = {}", param2, param));
  }
  // A is set first: it makes the force the harmonic family anew, which a1 set before would
  // leave (a1 != 0 is no longer that family, and A no longer settable).
  const bool a_second = p2 == ModelParameter::kA;
  return [base = robot, p1, h1, p2, h2, a_second](double lambda, double mu) {
    RobotModel r = base;
    if (a_second) SetParameter(r, p2, h2, mu);
    SetParameter(r, p1, h1, lambda);
    if (!a_second) SetParameter(r, p2, h2, mu);
    return r;
  };
}

Branch ContinueParameter(const RobotModel& robot, const std::string& param, const PhaseState& start,
                         ContinuationOptions options) {
  const RobotFamily family = NamedParameterFamily(robot, param);
  robot.params.Validate();
  ContinuationOptions range = options;  // the options' own rules first, the start's value aside
  range.start = options.from;
  range.Validate();
  options.start =
      RobotValueInRange(robot, param, {"from", options.from}, {"to", options.to}, "branch");
  return ContinueBranch(family, start, options);
}

}  // namespace capsubot
