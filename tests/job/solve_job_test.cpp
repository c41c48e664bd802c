// The solve job (capsubot/job/solve_job.hpp): the orbit, its energy and, asked, its stability
// and check from rest, as the library calls give them; bad options refused naming the parameter.

#include "capsubot/job/solve_job.hpp"

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "attract_job_cases.hpp"
#include "capsubot/orbit/orbit_energy.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::InvalidArgumentMessage;
using testing::SameAttractors;
using testing::SameBits;

SolveJobOptions SmallOrbitSolve() {
  const RobotModel robot = testing::SmallOrbit();
  SolveJobOptions o;
  o.forcing = robot.forcing;
  o.params = robot.params;
  return o;
}

TEST(SolveJob, IsTheOrbitWithItsEnergyAndNoStabilityUnlessAsked) {
  const SolveJobOptions o = SmallOrbitSolve();
  const SolveJobResult r = RunSolveJob(o);
  const Solution s = Solve(o.forcing, o.params);
  EXPECT_TRUE(SameBits(r.solution.orbit.alpha, s.orbit.alpha));
  // `capsubot solve` of this robot prints alpha = 0.2792869076 (docs/orbit.md).
  EXPECT_TRUE(testing::Near(r.solution.orbit.alpha, testing::SmallOrbit().alpha, 1e-15));
  EXPECT_EQ(r.solution.validity.valid(), s.validity.valid());
  EXPECT_TRUE(SameBits(r.energy.motor_work, OrbitEnergy(s.orbit).motor_work));
  EXPECT_FALSE(r.stability.computed);
  EXPECT_FALSE(r.from_rest.checked);
}

TEST(SolveJob, StabilityAddsTheMultipliersAndTheCheckFromRest) {
  SolveJobOptions o = SmallOrbitSolve();
  FromRestOptions check;
  check.n_x = 2;
  check.n_psi = 2;
  o.stability = check;
  std::vector<std::string> stages;
  o.on_stage = [&stages](const std::string& stage) { stages.push_back(stage); };
  const SolveJobResult r = RunSolveJob(o);
  EXPECT_EQ(stages, (std::vector<std::string>{"solve: 1/2 the orbit",
                                              "solve: 2/2 its stability and check from rest", ""}));
  const Solution s = Solve(o.forcing, o.params);
  const Stability st = ComputeStability(s.orbit);
  EXPECT_TRUE(SameBits(r.stability.spectral_radius, st.spectral_radius));
  EXPECT_TRUE(r.stability.stable);  // spectral radius 0.16 (docs/orbit.md)
  const GaitFromRest g = CheckGaitFromRest(s.orbit, o.params, check);
  EXPECT_TRUE(SameAttractors(r.from_rest.attractors, g.attractors));
  EXPECT_EQ(r.from_rest.reached, g.reached);
  EXPECT_EQ(r.from_rest.summary, g.summary);
}

TEST(SolveJob, BadOptionsAreRefusedNamingTheParameter) {
  SolveJobOptions o = SmallOrbitSolve();
  o.params.T0 = -1.0;
  EXPECT_EQ(InvalidArgumentMessage([&] { RunSolveJob(o); }).rfind("friction bound T0 = -1", 0), 0U)
      << InvalidArgumentMessage([&] { RunSolveJob(o); });
  o = SmallOrbitSolve();
  FromRestOptions check;
  check.n_x = 0;
  o.stability = check;
  EXPECT_EQ(InvalidArgumentMessage([&] { RunSolveJob(o); }).rfind("n_x = 0 is invalid", 0), 0U);
}

}  // namespace
}  // namespace capsubot
