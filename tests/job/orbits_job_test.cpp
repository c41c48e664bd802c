// The orbits job is the orbit search of a robot in one call: the same orbits, its work bound
// checked before any work, an interrupt let through.

#include "capsubot/job/orbits_job.hpp"

#include <gtest/gtest.h>

#include <stdexcept>

namespace capsubot {
namespace {

// The robot of docs/orbit.md's example: A = 0.05, c = 0.02, T0 = 0.1, e = 0.5, alpha = 0.28.
OrbitsJobOptions Robot() {
  OrbitsJobOptions o;
  o.robot.forcing = Forcing::Harmonic(0.05, 0.02, 0.0);
  o.robot.params = Params{0.1, 0.5};
  o.robot.alpha = 0.28;
  return o;
}

TEST(OrbitsJob, FindsWhatTheSearchFinds) {
  const OrbitsJobOptions o = Robot();
  const OrbitsJobResult r = RunOrbitsJob(o);
  bool complete = false;
  const std::vector<Solution> direct = FindRobotOrbits(o.robot, {}, &complete);
  ASSERT_FALSE(direct.empty());
  ASSERT_EQ(r.orbits.size(), direct.size());
  for (std::size_t i = 0; i < direct.size(); ++i) {
    EXPECT_EQ(r.orbits[i].orbit.forcing.phi0(), direct[i].orbit.forcing.phi0());
    EXPECT_EQ(r.orbits[i].orbit.v_mean, direct[i].orbit.v_mean);
  }
  EXPECT_EQ(r.complete, complete);
  EXPECT_EQ(r.options.robot.alpha, 0.28);
}

// The margins judge every orbit found: each validity is CheckValidity's with them, and a
// clearance of 0.49 (the inner body kept within 0.49..0.51) breaks the orbits that exist.
TEST(OrbitsJob, JudgesEveryOrbitWithTheMargins) {
  OrbitsJobOptions o = Robot();
  const OrbitsJobResult plain = RunOrbitsJob(o);
  o.margins.clearance = 0.49;
  const OrbitsJobResult strict = RunOrbitsJob(o);
  ASSERT_FALSE(plain.orbits.empty());
  ASSERT_EQ(strict.orbits.size(), plain.orbits.size());
  int broken = 0;
  for (std::size_t i = 0; i < plain.orbits.size(); ++i) {
    EXPECT_EQ(strict.orbits[i].validity.violations,
              CheckValidity(plain.orbits[i].orbit, o.margins).violations);
    EXPECT_FALSE(plain.orbits[i].validity.violated(Condition::kClearance)) << i;
    if (strict.orbits[i].validity.violated(Condition::kClearance)) ++broken;
  }
  EXPECT_GT(broken, 0);
  o.margins.clearance = 0.5;
  EXPECT_THROW(RunOrbitsJob(o), std::invalid_argument);
}

TEST(OrbitsJob, RefusesAWorkBoundOutOfRangeNamingIt) {
  OrbitsJobOptions o = Robot();
  o.max_evaluations = 0;
  try {
    o.Validate();
    FAIL() << "max_evaluations = 0 passed";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("max_evaluations = 0 is invalid", 0), 0U);
  }
}

// A friction bound that dwarfs the motor (T0 = 3e7, the long call of the Python module's
// interrupt test) makes the search refine the circle for long: it is asked, and stops.
TEST(OrbitsJob, AnInterruptStopsTheSearch) {
  struct Stop {};
  OrbitsJobOptions o;
  o.robot.forcing = Forcing::Harmonic(0.00527714, 0.00105543, 0.0);
  o.robot.params = Params{3e7, 0.7};
  o.robot.alpha = 0.3333;
  o.max_evaluations = 1000000000;
  int asked = 0;
  o.interrupt = [&asked] {
    if (++asked == 2) throw Stop{};
  };
  EXPECT_THROW(RunOrbitsJob(o), Stop);
  EXPECT_EQ(asked, 2);
}

}  // namespace
}  // namespace capsubot
