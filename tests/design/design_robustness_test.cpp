// How far mu, e and m2 carry a designed gait (capsubot/design/design_robustness.hpp): mu is the
// continuation in T0 converted, the family over m2 is the design's own robot at every m2, and
// the limits in m2 lie where the design's own evaluation of the robot loses its gait (an
// independent computation: the continuation follows the simulated period map, the design the
// closed-form orbit).

#include "capsubot/design/design_robustness.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "design/example_robot.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

// Converting T0 to mu multiplies by omega^2 L / g, computed once as mu / T0: a few roundings.
constexpr double kConversionTol = 1e-12;
// The design continues its robot (motor phase 0) from the orbit's impact state, the reference
// the orbit's own robot (motor phase the impact's): the same motion, its special points each
// located to the location tolerance 1e-10 (ContinuationOptions), so they agree to about that.
constexpr double kLocationTol = 1e-10;
// The section-9 units written out in another order of operations than the library's: a few
// roundings.
constexpr double kUnitsTol = 1e-14;
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
  EXPECT_TRUE(testing::NearAbsBelowOne(r.parameters[0].value, 0.3, kConversionTol));
  EXPECT_EQ(r.parameters[1].value, 0.7);
  EXPECT_EQ(r.parameters[2].value, ExampleGait().m2_kg);
  EXPECT_TRUE(
      testing::NearAbsBelowOne(r.parameters[2].from, 0.5 * ExampleGait().m2_kg, kConversionTol));
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
    EXPECT_TRUE(testing::NearAbsBelowOne(got->parameter, to_mu * want->parameter, kLocationTol));
  }
  EXPECT_TRUE(testing::NearAbsBelowOne(mu.from, to_mu * T0.from, kConversionTol));
  EXPECT_TRUE(testing::NearAbsBelowOne(mu.to, to_mu * T0.to, kConversionTol));
  // e is continued as the optimiser's robustness continues it: the same limits.
  const ParameterRobustness& e = ExampleRobustness().parameters[1];
  EXPECT_EQ(std::string(e.down.Name()), reference.parameters[1].down.Name());
  EXPECT_TRUE(
      testing::Near(e.down.parameter, reference.parameters[1].down.parameter, kLocationTol));
  EXPECT_EQ(std::string(e.up.Name()), reference.parameters[1].up.Name());
  EXPECT_TRUE(testing::Near(e.up.parameter, reference.parameters[1].up.parameter, kLocationTol));
}

TEST(DesignRobustness, InnerMassFamilyIsTheDesignsRobotAtEveryMass) {
  // The robot at inner mass lambda m2, from the physical units written out (docs/model.md
  // section 9): omega = 2 pi f, T0 = mu g/(omega^2 L), alpha = m2/(m1+m2), the force divided by
  // (m1+m2) omega^2 L; e as given.
  const DesignInput in = testing::ExampleRobot();
  const Gait& gait = ExampleGait();
  const RobotFamily family = InnerMassFamily(in, gait.m2_kg, gait.frequency_hz);
  const double omega = kTau * gait.frequency_hz;
  for (const double lambda : {1.0, 0.7, 1.3}) {
    const RobotModel got = family(lambda);
    const double m2 = lambda * gait.m2_kg;
    const double force_unit = (in.m1 + m2) * omega * omega * in.L;
    EXPECT_TRUE(testing::Near(got.alpha, m2 / (in.m1 + m2), kUnitsTol)) << lambda;
    EXPECT_TRUE(testing::Near(got.params.T0, in.mu * in.g / (omega * omega * in.L),
                              kUnitsTol * got.params.T0))
        << lambda;
    EXPECT_EQ(got.params.e, in.e) << lambda;
    EXPECT_TRUE(testing::Near(got.forcing.amplitude(), in.force.amplitude / force_unit,
                              kUnitsTol * got.forcing.amplitude()))
        << lambda;
    EXPECT_TRUE(testing::Near(got.forcing.mean(), in.force.bias / force_unit,
                              kUnitsTol * got.forcing.mean()))
        << lambda;
  }
  // At the design's mass it is the gait's robot itself.
  EXPECT_EQ(family(1.0).alpha, gait.model.robot.alpha);
  EXPECT_EQ(family(1.0).forcing.amplitude(), gait.model.robot.forcing.amplitude());
  EXPECT_EQ(family(1.0).forcing.mean(), gait.model.robot.forcing.mean());
  EXPECT_EQ(family(1.0).params.T0, gait.model.robot.params.T0);
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
// straddle the wall once gave a multiplier -1 there). The design's own evaluation of the robot
// agrees: kStep inside each limit the robot still has a valid stable one-impact orbit, kStep beyond
// it has none (below the lower limit the gait's orbit has a multiplier past -1; above the upper one
// the robot's orbits have met in a fold of alpha(phi0) and vanished, a few 1e-5 after the analytic
// orbit grazes the right wall).
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
  EXPECT_TRUE(testing::NearAbsBelowOne(Design(StableGaitRobot()).one_impact.m2_kg,
                                       m2.down.parameter, 1e-6));
}

TEST(DesignRobustness, RefusesAGaitThatIsNotOk) {
  Gait none;
  none.status = GaitStatus::kNoOrbit;
  EXPECT_EQ(testing::InvalidArgumentMessage(
                [&] { ComputeDesignRobustness(testing::ExampleRobot(), none); }),
            "gait status = no_orbit is invalid: expected a gait (ok) to continue");
}

// testing::SmallRobot's gait binds the stick margin s = 0.02 (docs/model.md section 12): its
// capsule sticks with a margin of 2 % of the friction bound, so at mu (1 - s) = 0.294 its
// stick/slide pattern changes, and the gait goes on.
using testing::SmallRobot;
// The segment change is located to 1e-10 in T0 relative to its value; mu = 0.294 is exact.
constexpr double kSegmentTol = 1e-6;
// The speed from rest a designer is told about: within 95 % of the design's.
constexpr double kLevel = 0.95;

TEST(DesignRobustness, ASegmentChangeTheGaitSurvivesIsNoLimitAndTheBandSaysHowFarItGoes) {
  const DesignInput in = SmallRobot();
  const Gait gait = Design(in).one_impact;
  ASSERT_TRUE(gait.ok());
  RobustnessOptions options;
  options.speed_bands = true;
  const ParameterRobustness mu = ComputeDesignRobustness(in, gait, options).parameters[0];
  ASSERT_EQ(mu.status, ContinuationStatus::kOk) << mu.message;
  // The segment change at the stick margin is listed, and is not the limit below.
  bool listed = false;
  for (const SpecialPoint& sp : mu.special_points) {
    listed = listed || (sp.type == SpecialPointType::kSegmentChange &&
                        std::abs(sp.parameter - in.mu * (1.0 - in.stick_margin)) <= kSegmentTol);
  }
  EXPECT_TRUE(listed);
  EXPECT_LT(mu.down.parameter, in.mu * (1.0 - in.stick_margin) - kSegmentTol) << mu.down.Name();
  // The band reaches far below it: the speed from rest at mu = 0.24 (beyond the segment change
  // and two more) is still within it, simulated anew here.
  ASSERT_EQ(mu.band.status, SpeedBandStatus::kOk);
  const BandEdge& down = mu.band.down.front();
  ASSERT_TRUE(down.within);
  EXPECT_LT(down.parameter, 0.24);
  DesignInput moved = in;
  moved.mu = 0.24;
  const DesignModel m = MapToModel(moved, gait.m2_kg, gait.frequency_hz);
  const double speed = FindAttractors(m.robot, options.band.from_rest).mean_velocity;
  EXPECT_GE(speed, kLevel * mu.band.nominal_speed);
}

}  // namespace
}  // namespace capsubot
