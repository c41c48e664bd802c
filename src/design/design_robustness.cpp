// How far mu, e and m2 carry a designed gait (docs/design.md, "Robustness").

#include "capsubot/design/design_robustness.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "capsubot/continue/parameter_branch.hpp"

namespace capsubot {

RobotFamily InnerMassFamily(const DesignInput& input, double m2, double frequency) {
  return [input, m2, frequency](double lambda) {
    const DesignModel m = MapToModel(input, lambda * m2, frequency);
    return m.robot;
  };
}

GaitRobustness ComputeDesignRobustness(const DesignInput& input, const Gait& gait,
                                       const RobustnessOptions& options) {
  if (!gait.ok()) {
    throw std::invalid_argument(
        fmt::format("gait status = {} is invalid: expected a gait (ok) to continue",
                    GaitStatusName(gait.status)));
  }
  options.Validate();
  const Orbit& o = gait.solution.orbit;
  // The design's robot has phi0 = 0: the orbit's impact falls at its phase phi0 of that force.
  // Every family is of that robot, so that the bands' starts from rest are the same.
  const RobotModel robot{gait.model.robot.forcing, Params{o.T0, o.e}, o.alpha};
  const PhaseState start = OrbitImpactState(o, robot.forcing);
  const auto along = [&](const char* name) { return NamedParameterFamily(robot, name); };
  GaitRobustness g;
  const auto follow = [&](const RobustnessParameter& p) {
    return ContinueRobustness(p, start, options);
  };
  // mu = T0 omega^2 L / g: the unit is the robot's mu over its T0.
  g.parameters.push_back(
      follow(RelativeParameter("mu", along("T0"), o.T0, options.t0_factor, input.mu / o.T0)));
  g.parameters.push_back(follow({"e", along("e"), o.e, 0.0, 1.0, 1.0}));
  g.parameters.push_back(follow(RelativeParameter(
      "m2_kg", InnerMassFamily(input, 1.0, gait.frequency_hz), gait.m2_kg, options.t0_factor)));
  return g;
}

GaitRobustness ComputeDesignRobustness(const DesignInput& input, const Gait& gait) {
  const RobustnessOptions defaults;
  return ComputeDesignRobustness(input, gait, defaults);
}

}  // namespace capsubot
