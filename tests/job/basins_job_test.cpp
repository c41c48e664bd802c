// The basins job (capsubot/job/basins_job.hpp): the starts of its planes, its map equal to the
// classification of those starts and to the attractors job in the plane from rest, and its
// options checked naming the parameter.

#include "capsubot/job/basins_job.hpp"

#include <gtest/gtest.h>

#include <string>
#include <variant>
#include <vector>

#include "attract_job_cases.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::InvalidArgumentMessage;
using testing::SameAttractors;

// The small orbit's robot, whose one-impact orbit coexists with a period-12 motion, on a few
// starts (the period-12 motion needs max_period 16).
BasinsJobOptions SmallBasins() {
  const RobotModel robot = testing::SmallOrbit();
  BasinsJobOptions o;
  o.map.robot = robot;
  o.map.starts = {3, 2};
  o.map.attractor.motion.max_period = 16;
  o.map.attractor.motion.transient = 300;
  return o;
}

TEST(BasinsJob, VelocityPlaneStartsAtThePositionsAndVelocitiesOfItsCells) {
  BasinsJobOptions o = SmallBasins();
  VelocityPlane plane;
  plane.psi = 1.0;
  plane.u_min = -0.5;
  plane.u_max = 0.5;
  o.plane = plane;
  const std::vector<PhaseState> starts = BasinStarts(o);
  ASSERT_EQ(starts.size(), 6U);
  // Cell (i, j) = starts[i * 2 + j]: x0 = (i + 0.5)/3, u0 = -0.5 + (j + 0.5)/2, v0 = 0.
  EXPECT_DOUBLE_EQ(starts[3].x, 1.5 / 3.0);
  EXPECT_DOUBLE_EQ(starts[3].u, 0.25);
  EXPECT_EQ(starts[3].v, 0.0);
  EXPECT_EQ(starts[3].psi, 1.0);
  EXPECT_DOUBLE_EQ(starts[0].u, -0.25);
  EXPECT_STREQ(StartPlaneName(o.plane), "x0-u0");
  const BasinsJobResult r = RunBasinsJob(o);
  EXPECT_TRUE(
      SameAttractors(r.map.attractors, ClassifyStarts(o.map.robot, starts, o.map.attractor)));
}

TEST(BasinsJob, RestPlaneIsTheMapOfTheAttractorsJob) {
  const BasinsJobOptions o = SmallBasins();
  EXPECT_STREQ(StartPlaneName(o.plane), "x0-psi");
  const BasinsJobResult r = RunBasinsJob(o);
  EXPECT_TRUE(SameAttractors(r.map.attractors, RunAttractorsJob(o.map).attractors));
  // Both motions of docs/attractors.md are reached: the period-12 motion and the orbit.
  ASSERT_EQ(r.map.attractors.attractors.size(), 2U);
  EXPECT_EQ(BasinsJobWork(o).starts.size(), 6U);
}

TEST(BasinsJob, BadPlaneOrMapIsRefusedNamingTheParameter) {
  BasinsJobOptions o = SmallBasins();
  VelocityPlane plane;
  plane.u_min = 1.0;
  plane.u_max = 0.0;
  o.plane = plane;
  EXPECT_EQ(InvalidArgumentMessage([&] { RunBasinsJob(o); }),
            "u_min = 1 and u_max = 0 are invalid: expected u_min < u_max");
  o.plane = RestPlane{};
  o.map.starts.n_psi = 0;
  EXPECT_EQ(InvalidArgumentMessage([&] { RunBasinsJob(o); }).rfind("n_psi = 0 is invalid", 0), 0U);
}

TEST(BasinsJob, PlaneFromItsNameWithItsVelocityRangeChecked) {
  VelocityPlane v;
  v.psi = 1.0;
  EXPECT_TRUE(std::holds_alternative<RestPlane>(StartPlaneNamed("x0-psi", v)));
  EXPECT_EQ(std::get<VelocityPlane>(StartPlaneNamed("x0-u0", v)).psi, 1.0);
  EXPECT_EQ(InvalidArgumentMessage([&] { StartPlaneNamed("x0-v0", v); }),
            "plane = x0-v0 is invalid: expected x0-psi or x0-u0");
  v.u_max = v.u_min;  // refused in the plane from rest too: never accepted unchecked
  EXPECT_EQ(InvalidArgumentMessage([&] { StartPlaneNamed("x0-psi", v); }),
            "u_min = -1 and u_max = -1 are invalid: expected u_min < u_max");
}

}  // namespace
}  // namespace capsubot
