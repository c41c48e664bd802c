// The tables of the settings of simulate, solve, orbits and periodic
// (capsubot/job/simulate_settings.hpp, orbit_trajectory_settings.hpp, orbits_settings.hpp,
// shooting_settings.hpp): each row sets a field of its own, its help names known settings, and
// a range a front end checks while reading is the job's own rule.

#include <gtest/gtest.h>

#include <string>
#include <vector>

#include "capsubot/job/orbit_trajectory_settings.hpp"
#include "capsubot/job/orbits_settings.hpp"
#include "capsubot/job/shooting_settings.hpp"
#include "capsubot/job/simulate_settings.hpp"
#include "capsubot/model/limits.hpp"
#include "setting_table_checks.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::InvalidArgumentMessage;
using testing::RangesAreTheRules;
using testing::WellFormed;

// A valid simulation from a state of a robot at rest in its middle.
SimulateJobOptions SimulateFromRest() {
  SimulateJobOptions o;
  o.forcing = Forcing::Harmonic(0.5, 0.5, 0.0);
  o.params = Params{0.75, 0.5};
  o.start = SimulateFromState{0.5, 0.5, 0.0, 0.0};
  return o;
}

TEST(CommandSettings, TheSimulateRunsSettingsAreTheSimulatorsRules) {
  // The job's field trajectory (whether a trajectory is sampled) has no row: the front end
  // sets it from the file it writes.
  const SettingTable<SimulateJobOptions>& job = SimulateJobSettings();
  EXPECT_TRUE(WellFormed(job, {"trajectory"}));
  EXPECT_TRUE(RangesAreTheRules(job, SimulateFromRest(),
                                [](const SimulateJobOptions& o) { o.Validate(); }));
  const SettingTable<SimOptions>& run = SimulateRunSettings();
  EXPECT_TRUE(WellFormed(run));
  EXPECT_TRUE(RangesAreTheRules(run, SimulateFromRest().sim, [](const SimOptions& sim) {
    SimulateJobOptions o = SimulateFromRest();
    o.sim = sim;
    o.Validate();
  }));
}

TEST(CommandSettings, TheOrbitsWorkBoundIsTheJobsRule) {
  const SettingTable<OrbitsJobOptions>& table = OrbitsSettings();
  EXPECT_TRUE(WellFormed(table));
  OrbitsJobOptions valid;
  valid.robot.forcing = Forcing::Harmonic(0.5, 0.5, 0.0);
  valid.robot.alpha = 0.5;
  EXPECT_TRUE(RangesAreTheRules(table, valid, [](const OrbitsJobOptions& o) { o.Validate(); }));
}

TEST(CommandSettings, TheShootingSettingsAreWellFormed) {
  EXPECT_TRUE(WellFormed(ShootingSettings()));
}

TEST(CommandSettings, TheTrajectoryGridOfAnOrbitIsItsRule) {
  // Its help names the front end's option of the file written ({trajectory}).
  const SettingTable<OrbitTrajectoryOptions>& table = OrbitTrajectorySettings();
  EXPECT_TRUE(WellFormed(table, {"trajectory"}));
  EXPECT_TRUE(RangesAreTheRules(table, OrbitTrajectoryOptions{},
                                [](const OrbitTrajectoryOptions& o) { o.Validate(); }));
  OrbitTrajectoryOptions o;
  o.samples = 1;
  EXPECT_EQ(
      InvalidArgumentMessage([&] { o.Validate(); }),
      "samples = 1 is invalid: expected 2 <= samples <= " + std::to_string(kMaxTrajectoryRows));
}

// The checks themselves catch what they are for: a help naming an unknown setting, two rows on
// one member, a range its job does not refuse.
TEST(CommandSettings, TheChecksRefuseABrokenTable) {
  using O = OrbitTrajectoryOptions;
  const SettingTable<O> unknown = {{"samples", &O::samples, "rows of {nothing_such} file"}};
  EXPECT_FALSE(WellFormed(unknown));
  const SettingTable<O> twice = {{"samples", &O::samples, "rows of the trajectory"},
                                 {"rows", &O::samples, "rows of the trajectory"}};
  EXPECT_FALSE(WellFormed(twice));
  const SettingTable<O> outside = {{"samples", &O::samples, "rows of the trajectory", 2000, 3000}};
  EXPECT_FALSE(WellFormed(outside));  // the default 1001 is outside
  const SettingTable<O> wider = {{"samples", &O::samples, "rows of the trajectory", 1, 3000}};
  EXPECT_FALSE(RangesAreTheRules(wider, O{}, [](const O& o) { o.Validate(); }));
  EXPECT_EQ(testing::Placeholders("{a_b} {x, u, v} {} {c"), std::vector<std::string>{"a_b"});
}

}  // namespace
}  // namespace capsubot
