// The periodic job (capsubot/job/periodic_job.hpp): each start gives what the shooting call it
// stands for gives (FindPeriodicMotion after the start's transient, ShootPeriodicMotion with
// the period known), and a start phase that is no phase is refused naming psi.

#include "capsubot/job/periodic_job.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "attract_job_cases.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::InvalidArgumentMessage;
using testing::SameBits;

PeriodicJobOptions Robot(const RobotModel& robot, const PeriodicStart& start) {
  PeriodicJobOptions o;
  o.robot = robot;
  o.start = start;
  return o;
}

::testing::AssertionResult SameMotion(const PeriodicMotion& a, const PeriodicMotion& b) {
  if (a.status != b.status || a.period != b.period || a.iterations != b.iterations ||
      !SameBits(a.mean_velocity, b.mean_velocity) || !SameBits(a.state.x, b.state.x)) {
    return ::testing::AssertionFailure()
           << "period " << a.period << " vs " << b.period << ", mean velocity " << a.mean_velocity
           << " vs " << b.mean_velocity;
  }
  return ::testing::AssertionSuccess();
}

TEST(PeriodicJob, FromRestRunsItsTransientThenShoots) {
  const RobotModel robot = testing::StableOptimum();
  PeriodicFromRest rest;
  rest.x0 = 0.5;
  rest.psi = 1.0;
  PeriodicJobOptions o = Robot(robot, rest);
  std::vector<std::string> stages;
  o.on_stage = [&stages](const std::string& stage) { stages.push_back(stage); };
  const PeriodicJobResult r = RunPeriodicJob(o);
  EXPECT_EQ(stages, (std::vector<std::string>{"periodic: Newton shooting", ""}));
  ShootingOptions so;
  so.transient = 200;  // the start's default
  EXPECT_TRUE(SameMotion(r.motion, FindPeriodicMotion({robot.forcing, robot.params, robot.alpha},
                                                      RestStart(0.5, 1.0), so)));
  EXPECT_EQ(r.options.shooting.transient, 200);
  // The motion from rest of this robot (tests/attract/periodic_test.cpp): 3 right + 1 left.
  EXPECT_EQ(r.motion.status, ShootingStatus::kConverged);
  EXPECT_EQ(r.motion.impacts_right, 3);
}

TEST(PeriodicJob, FromAStateShootsAtOnceAndWithThePeriodKnownSkipsTheSearch) {
  const RobotModel robot = testing::SmallOrbit();
  // Near the post-impact state of the one-impact orbit (solve: u = 0.41620, v_plus = 0.17436).
  PeriodicFromState near;
  near.state = {1.0, -0.2, 0.17, 0.0};
  const PeriodicJobResult r = RunPeriodicJob(Robot(robot, near));
  EXPECT_TRUE(SameMotion(r.motion, FindPeriodicMotion({robot.forcing, robot.params, robot.alpha},
                                                      near.state, ShootingOptions{})));
  EXPECT_EQ(r.options.shooting.transient, 0);
  EXPECT_EQ(r.motion.period, 1);
  const PeriodicJobResult known = RunPeriodicJob(Robot(robot, PeriodicOfPeriod{near.state, 1}));
  EXPECT_TRUE(
      SameMotion(known.motion, ShootPeriodicMotion({robot.forcing, robot.params, robot.alpha},
                                                   near.state, 1, ShootingOptions{})));
}

TEST(PeriodicJob, StartPhaseThatIsNoPhaseIsRefusedNamingPsi) {
  PeriodicFromRest rest;
  rest.x0 = 0.5;
  rest.psi = 1e300;
  const std::string message =
      InvalidArgumentMessage([&] { RunPeriodicJob(Robot(testing::SmallOrbit(), rest)); });
  EXPECT_EQ(message.rfind("psi = 1e+300 is invalid", 0), 0U) << message;
  PeriodicFromState state;
  state.state = {0.5, 0.0, 0.0, std::nan("")};
  EXPECT_EQ(InvalidArgumentMessage([&] {
              RunPeriodicJob(Robot(testing::SmallOrbit(), state));
            }).rfind("psi = nan is invalid", 0),
            0U);
}

}  // namespace
}  // namespace capsubot
