// How far mu, e and m2 carry a designed gait (capsubot/job/design_robustness.hpp): mu is the
// continuation in T0 converted, the family over m2 is the design's own robot at every m2, and
// the limits in m2 lie where the design's own evaluation of the robot loses its gait (an
// independent computation: the continuation follows the simulated period map, the design the
// closed-form orbit).

#include "capsubot/job/design_robustness.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "design/example_robot.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

// Converting T0 to mu multiplies by omega^2 L / g, computed once as mu / T0: a few roundings.
constexpr double kConversionTol = 1e-12;
// How far beyond (or before) a limit of m2 the design's robot is evaluated: far wider than the
// limit's location (1e-10 in the relative mass), narrow enough that nothing else happens.
constexpr double kStep = 1e-4;

const Gait& ExampleGait() {
  static const Gait gait = Design(testing::ExampleRobot()).one_impact;
  return gait;
}

const GaitRobustness& ExampleRobustness() {
  static const GaitRobustness r = ComputeDesignRobustness(testing::ExampleRobot(), ExampleGait());
  return r;
}

TEST(DesignRobustness, NamesMuEAndM2InTheUsersUnits) {
  const GaitRobustness& r = ExampleRobustness();
  ASSERT_EQ(r.parameters.size(), 3u);
  EXPECT_EQ(r.parameters[0].name, "mu");
  EXPECT_EQ(r.parameters[1].name, "e");
  EXPECT_EQ(r.parameters[2].name, "m2_kg");
  EXPECT_TRUE(testing::RelNear(r.parameters[0].value, 0.3, kConversionTol));
  EXPECT_EQ(r.parameters[1].value, 0.7);
  EXPECT_EQ(r.parameters[2].value, ExampleGait().m2_kg);
  EXPECT_TRUE(testing::RelNear(r.parameters[2].from, 0.5 * ExampleGait().m2_kg, kConversionTol));
  for (const ParameterRobustness& p : r.parameters) {
    EXPECT_EQ(p.status, ContinuationStatus::kOk) << p.name << ": " << p.message;
    EXPECT_LT(p.down.parameter, p.value) << p.name;
    EXPECT_GT(p.up.parameter, p.value) << p.name;
  }
}

TEST(DesignRobustness, MuLimitsAreTheT0LimitsOfTheGaitsOrbitConverted) {
  const DesignInput in = testing::ExampleRobot();
  const Gait& gait = ExampleGait();
  const GaitRobustness reference = ComputeGaitRobustness(gait.solution.orbit);
  const ParameterRobustness& T0 = reference.parameters[0];
  const ParameterRobustness& mu = ExampleRobustness().parameters[0];
  const double omega = gait.model.omega;
  const double to_mu = omega * omega * in.L / in.g;  // mu = T0 omega^2 L / g
  for (const auto& [got, want] :
       {std::make_pair(&mu.down, &T0.down), std::make_pair(&mu.up, &T0.up)}) {
    EXPECT_EQ(std::string(got->Name()), want->Name());
    EXPECT_TRUE(testing::RelNear(got->parameter, to_mu * want->parameter, kConversionTol));
  }
  EXPECT_TRUE(testing::RelNear(mu.from, to_mu * T0.from, kConversionTol));
  EXPECT_TRUE(testing::RelNear(mu.to, to_mu * T0.to, kConversionTol));
  // e is continued as the optimiser's robustness continues it: the same limits.
  const ParameterRobustness& e = ExampleRobustness().parameters[1];
  EXPECT_EQ(e.down.parameter, reference.parameters[1].down.parameter);
  EXPECT_EQ(e.up.parameter, reference.parameters[1].up.parameter);
}

TEST(DesignRobustness, InnerMassFamilyIsTheDesignsRobotAtEveryMass) {
  const DesignInput in = testing::ExampleRobot();
  const Gait& gait = ExampleGait();
  const RobotFamily family = InnerMassFamily(in, gait.m2_kg, gait.frequency_hz);
  for (const double lambda : {1.0, 0.7, 1.3}) {
    const RobotModel got = family(lambda);
    const DesignModel want = MapToModel(in, lambda * gait.m2_kg, gait.frequency_hz);
    EXPECT_EQ(got.alpha, want.alpha) << lambda;
    EXPECT_EQ(got.params.T0, want.params.T0) << lambda;
    EXPECT_EQ(got.params.e, want.params.e) << lambda;
    EXPECT_EQ(got.forcing.amplitude(), want.forcing.amplitude()) << lambda;
    EXPECT_EQ(got.forcing.mean(), want.forcing.mean()) << lambda;
  }
  // At the design's mass it is the gait's robot itself.
  EXPECT_EQ(family(1.0).alpha, gait.model.alpha);
  EXPECT_EQ(family(1.0).forcing.amplitude(), gait.model.forcing.amplitude());
  EXPECT_EQ(family(1.0).forcing.mean(), gait.model.forcing.mean());
  EXPECT_EQ(family(1.0).params.T0, gait.model.params.T0);
}

// The example robot with the margins off and rho_max = 1: its gait (EvaluateGait) is any valid
// and stable one-impact orbit, the design's own test of "the motion is there".
DesignInput StableGaitRobot() {
  DesignInput in = testing::ExampleRobot();
  in.margin_stroke = in.stick_margin = 0.0;
  in.rho_max = 1.0;
  return in;
}

// The example's gait (spectral radius 0.9) ends below in m2 at a period doubling of the
// simulated motion, and above at a grazing: its inner body's free flight touches the right
// wall (the continuation locates it by the flight's distance from the wall; differences that
// straddle the wall once gave a multiplier -1 there). The design's own evaluation of the robot agrees: kStep inside each limit the
// robot still has a valid stable one-impact orbit, kStep beyond it has none (below the lower
// limit the gait's orbit has a multiplier past -1; above the upper one the robot's orbits have
// met in a fold of alpha(phi0) and vanished, a few 1e-5 after the analytic orbit grazes the
// right wall).
TEST(DesignRobustness, InnerMassLimitsAreWhereTheDesignsGaitEnds) {
  const ParameterRobustness& m2 = ExampleRobustness().parameters[2];
  const double f = ExampleGait().frequency_hz;
  ASSERT_TRUE(m2.down.special);
  EXPECT_EQ(m2.down.type, SpecialPointType::kPeriodDoubling);
  ASSERT_TRUE(m2.up.special);
  EXPECT_EQ(m2.up.type, SpecialPointType::kGrazing);
  for (const MotionLimit* limit : {&m2.down, &m2.up}) {
    const double toward = limit->parameter < m2.value ? 1.0 : -1.0;  // towards the gait
    const double inside = limit->parameter * (1.0 + toward * kStep);
    const double outside = limit->parameter * (1.0 - toward * kStep);
    const Gait in = EvaluateGait(StableGaitRobot(), inside, f);
    EXPECT_TRUE(in.ok()) << "m2 = " << inside << ": " << GaitStatusName(in.status);
    EXPECT_LT(in.stability.spectral_radius, 1.0) << "m2 = " << inside;
    const Gait out = EvaluateGait(StableGaitRobot(), outside, f);
    EXPECT_FALSE(out.ok()) << "m2 = " << outside;
  }
  // The lower limit is the stable design's inner mass (docs/design.md: with rho_max = 1 and no
  // margins the design sits on the period doubling).
  EXPECT_TRUE(
      testing::RelNear(Design(StableGaitRobot()).one_impact.m2_kg, m2.down.parameter, 1e-6));
}

TEST(DesignRobustness, RefusesAGaitThatIsNotOk) {
  Gait none;
  none.status = GaitStatus::kNoOrbit;
  EXPECT_EQ(testing::InvalidArgumentMessage(
                [&] { ComputeDesignRobustness(testing::ExampleRobot(), none); }),
            "gait status = no_orbit is invalid: expected a gait (ok) to continue");
}

}  // namespace
}  // namespace capsubot
