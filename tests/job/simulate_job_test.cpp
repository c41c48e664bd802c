// The simulate job (capsubot/job/simulate_job.hpp): from a state or from the analytic orbit it
// gives the run of the simulator from that start (energy on, samples where asked), tells the
// observer, and refuses bad options naming the parameter.

#include "capsubot/job/simulate_job.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <vector>

#include "attract_job_cases.hpp"
#include "capsubot/attract/orbit_start.hpp"
#include "capsubot/model/limits.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::InvalidArgumentMessage;
using testing::SameBits;

// Counts what the simulator tells.
struct Counter : SimObserver {
  int events = 0, samples = 0;
  void OnEvent(const SimEvent&) override { ++events; }
  void OnSample(const SimState&) override { ++samples; }
};

SimulateJobOptions SmallOrbitRun(const SimulateStart& start) {
  const RobotModel robot = testing::SmallOrbit();
  SimulateJobOptions o;
  o.forcing = robot.forcing;
  o.params = robot.params;
  o.start = start;
  o.sim.periods = 10;
  return o;
}

::testing::AssertionResult SameRun(const SimResult& a, const SimResult& b) {
  if (a.status != b.status || a.impacts_right != b.impacts_right ||
      !SameBits(a.displacement, b.displacement) || !SameBits(a.final_state.x, b.final_state.x) ||
      !SameBits(a.energy.motor_work, b.energy.motor_work)) {
    return ::testing::AssertionFailure()
           << "displacement " << a.displacement << " vs " << b.displacement;
  }
  return ::testing::AssertionSuccess();
}

TEST(SimulateJob, FromTheOrbitIsTheSimulatorStartedRightAfterItsImpact) {
  const SimulateJobOptions o = SmallOrbitRun(SimulateFromOrbit{});
  const SimulateJobResult r = RunSimulateJob(o);
  ASSERT_TRUE(r.orbit.has_value());
  const OrbitStart start = StartFromOrbit(o.forcing, o.params);
  SimOptions sim = start.start;
  sim.periods = 10;
  sim.energy = true;
  EXPECT_TRUE(SameRun(r.run, Simulate(o.forcing, o.params, sim)));
  EXPECT_TRUE(SameBits(r.sim.alpha, start.orbit.orbit.alpha));
  // The orbit returns to its start: 10 steps I of the orbit (docs/simulate.md).
  EXPECT_TRUE(testing::Near(r.run.displacement, 10 * r.orbit->orbit.I, 1e-9));
}

TEST(SimulateJob, FromAStateWithItsTrajectoryTellsTheObserverEverySample) {
  SimulateJobOptions o = SmallOrbitRun(SimulateFromState{0.3, 0.5, 0.0, 0.0});
  o.sim.transient = 2;
  o.trajectory = true;
  o.samples_per_period = 7;
  Counter counter;
  o.observer = &counter;
  std::vector<std::string> stages;
  o.on_stage = [&stages](const std::string& stage) { stages.push_back(stage); };
  const SimulateJobResult r = RunSimulateJob(o);
  EXPECT_EQ(stages, (std::vector<std::string>{"simulate: 12 periods", ""}));
  EXPECT_FALSE(r.orbit.has_value());
  EXPECT_EQ(r.options.observer, nullptr);
  EXPECT_EQ(counter.samples, 7 * 12 + 1);  // the transient sampled too, both ends
  SimOptions sim = testing::StartAt(0.3, 0.5, 0.0, 0.0, 10);
  sim.transient = 2;
  sim.energy = true;
  sim.sample_step = kTau / 7;
  EXPECT_TRUE(SameRun(r.run, Simulate(o.forcing, o.params, sim)));
  EXPECT_EQ(counter.events, r.run.events + r.run.transient.events);
}

TEST(SimulateJob, BadOptionsAreRefusedNamingTheParameter) {
  SimulateJobOptions o = SmallOrbitRun(SimulateFromOrbit{});
  o.samples_per_period = 0;
  EXPECT_EQ(InvalidArgumentMessage([&] { RunSimulateJob(o); }),
            "samples_per_period = 0 is invalid: expected 1 <= samples_per_period <= 1000000");
  o.samples_per_period = 100;
  o.sim.max_events_per_period = kMaxEventsPerPeriod + 1;
  EXPECT_EQ(InvalidArgumentMessage([&] {
              RunSimulateJob(o);
            }).rfind("max_events_per_period = 1000000001 is invalid", 0),
            0U);
  o.sim.max_events_per_period = 1000;
  o.trajectory = true;
  o.sim.periods = 1e6;
  EXPECT_EQ(InvalidArgumentMessage([&] {
              RunSimulateJob(o);
            }).rfind("samples_per_period = 100 with transient + periods = 1000000 is invalid", 0),
            0U);
  o = SmallOrbitRun(SimulateFromState{1.5, 0.5, 0.0, 0.0});
  EXPECT_EQ(InvalidArgumentMessage([&] {
              RunSimulateJob(o);
            }).rfind("mass ratio alpha = 1.5 is invalid", 0),
            0U);
  o = SmallOrbitRun(SimulateFromOrbit{});
  o.forcing = Forcing::Harmonic(0.5, -0.5, 0.0);  // a negative mean force: no orbit
  EXPECT_EQ(InvalidArgumentMessage([&] { RunSimulateJob(o); }),
            "from_orbit: no one-impact orbit exists for this force, T0 and e "
            "(non_positive_mean_force)");
}

TEST(SimulateJob, StateBeyondDoublePrecisionIsAnError) {
  // docs/errors.md: a capsule velocity of 1.7e308 overflows at the first impact.
  SimulateJobOptions o = SmallOrbitRun(SimulateFromState{0.5, 0.5, 0.0, 1.7e308});
  o.forcing = Forcing::Harmonic(0.5, 0.5, 0.0);
  o.params = Params{};
  EXPECT_THROW(RunSimulateJob(o), std::runtime_error);
}

}  // namespace
}  // namespace capsubot
