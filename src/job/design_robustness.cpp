// How far mu, e and m2 carry a designed gait (docs/design.md, "Robustness").

#include "capsubot/job/design_robustness.hpp"

#include <fmt/format.h>

#include <stdexcept>

#include "capsubot/continue/parameter_branch.hpp"

namespace capsubot {
namespace {

// A parameter's continuation in another unit: every value of the parameter times `factor`,
// under the name `name`.
ParameterRobustness Scaled(ParameterRobustness p, const char* name, double factor) {
  p.name = name;
  for (double* v : {&p.value, &p.from, &p.to, &p.down.parameter, &p.down.accuracy, &p.up.parameter,
                    &p.up.accuracy}) {
    *v *= factor;
  }
  return p;
}

}  // namespace

RobotFamily InnerMassFamily(const DesignInput& input, double m2, double frequency) {
  return [input, m2, frequency](double lambda) {
    const DesignModel m = MapToModel(input, lambda * m2, frequency);
    return RobotModel{m.forcing, m.params, m.alpha};
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
  const double f = options.t0_factor;
  const ContinuationOptions& c = options.continuation;
  const Params params{o.T0, o.e, 0.0};
  const PhaseState start = OrbitImpactState(o, o.forcing);
  const auto along = [&](const char* name) {
    return NamedParameterFamily(o.forcing, params, o.alpha, name);
  };
  GaitRobustness g;
  // mu = T0 omega^2 L / g: the factor is the robot's mu over its T0.
  g.parameters.push_back(
      Scaled(ContinueRobustness(along("T0"), start, "T0", o.T0, o.T0 / f, o.T0 * f, c), "mu",
             input.mu / o.T0));
  g.parameters.push_back(ContinueRobustness(along("e"), start, "e", o.e, 0.0, 1.0, c));
  // The design's robot has phi0 = 0: the orbit's impact falls at its phase phi0 of that force.
  g.parameters.push_back(
      Scaled(ContinueRobustness(InnerMassFamily(input, gait.m2_kg, gait.frequency_hz),
                                OrbitImpactState(o, gait.model.forcing), "m2", 1.0, 1.0 / f, f, c),
             "m2_kg", gait.m2_kg));
  return g;
}

}  // namespace capsubot
