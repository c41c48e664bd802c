// The simulator's reuse of located events along repeated cycles (SimOptions::reuse_cycles,
// docs/simulate.md "Repeated cycles"): a run with it is the run without it, bit for bit (every
// count, the state, the displacement, the energy budget, every reported event and sample),
// and a motion that settles on a periodic attractor takes most of its events from it.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cstdint>
#include <cstring>
#include <vector>

#include "capsubot/attract/orbit_start.hpp"
#include "capsubot/orbit/validity.hpp"
#include "capsubot/simulate/simulator.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::StartAt;

struct Log : SimObserver {
  std::vector<SimEvent> events;
  std::vector<SimState> samples;
  void OnEvent(const SimEvent& e) override { events.push_back(e); }
  void OnSample(const SimState& s) override { samples.push_back(s); }
};

// Bit for bit (0 and -0 differ; NaN equals NaN of the same bits); on failure both sides are
// printed to the last bit.
::testing::AssertionResult Same(const char* what, double a, double b) {
  if (std::memcmp(&a, &b, sizeof a) == 0) return ::testing::AssertionSuccess();
  return ::testing::AssertionFailure()
         << what << ": " << fmt::format("{:.17g}", a) << " with the reuse, "
         << fmt::format("{:.17g}", b) << " without";
}

void ExpectSameState(const SimState& a, const SimState& b) {
  EXPECT_EQ(a.mode, b.mode);
  EXPECT_TRUE(Same("phi", a.phi, b.phi));
  EXPECT_TRUE(Same("x", a.x, b.x));
  EXPECT_TRUE(Same("u", a.u, b.u));
  EXPECT_TRUE(Same("v", a.v, b.v));
  EXPECT_TRUE(Same("y", a.y, b.y));
}

void ExpectSameTally(const SimTally& a, const SimTally& b) {
  EXPECT_EQ(a.impacts_right, b.impacts_right);
  EXPECT_EQ(a.impacts_left, b.impacts_left);
  EXPECT_EQ(a.stops, b.stops);
  EXPECT_EQ(a.breakaways, b.breakaways);
  EXPECT_EQ(a.sticks, b.sticks);
  EXPECT_EQ(a.releases, b.releases);
  EXPECT_EQ(a.events, b.events);
  EXPECT_TRUE(Same("span", a.span, b.span));
  EXPECT_TRUE(Same("displacement", a.displacement, b.displacement));
  EXPECT_TRUE(Same("v_mean", a.v_mean, b.v_mean));
  EXPECT_TRUE(Same("motor_work", a.energy.motor_work, b.energy.motor_work));
  EXPECT_TRUE(
      Same("motor_work_positive", a.energy.motor_work_positive, b.energy.motor_work_positive));
  EXPECT_TRUE(Same("friction_loss", a.energy.friction_loss, b.energy.friction_loss));
  EXPECT_TRUE(Same("impact_loss", a.energy.impact_loss, b.energy.impact_loss));
}

struct Run {
  SimResult result;
  Log log;
};

Run Simulated(const Forcing& f, const Params& p, SimOptions opt, bool reuse) {
  opt.reuse_cycles = reuse;
  opt.energy = true;
  opt.sample_step = kTau / 7;
  Run run;
  run.result = Simulate(f, p, opt, &run.log);
  return run;
}

// Runs `opt` with and without the reuse, expects them identical, returns the run with it.
SimResult ExpectIdenticalWithReuse(const Forcing& f, const Params& p, const SimOptions& opt) {
  const Run off = Simulated(f, p, opt, false), on = Simulated(f, p, opt, true);
  EXPECT_EQ(off.result.reused_events, 0);
  EXPECT_EQ(on.result.status, off.result.status);
  EXPECT_EQ(on.result.message, off.result.message);
  ExpectSameTally(on.result, off.result);
  ExpectSameTally(on.result.transient, off.result.transient);
  ExpectSameState(on.result.final_state, off.result.final_state);
  EXPECT_EQ(on.log.events.size(), off.log.events.size());
  for (std::size_t i = 0; i < on.log.events.size() && i < off.log.events.size(); ++i) {
    const SimEvent &a = on.log.events[i], &b = off.log.events[i];
    EXPECT_EQ(a.kind, b.kind) << i;
    ExpectSameState(a.after, b.after);
    EXPECT_TRUE(Same("u_before", a.u_before, b.u_before)) << i;
    EXPECT_TRUE(Same("v_before", a.v_before, b.v_before)) << i;
    if (::testing::Test::HasFailure()) break;  // the first difference says it all
  }
  EXPECT_EQ(on.log.samples.size(), off.log.samples.size());
  for (std::size_t i = 0; i < on.log.samples.size() && i < off.log.samples.size(); ++i) {
    ExpectSameState(on.log.samples[i], off.log.samples[i]);
  }
  return on.result;
}

// The exact stable P2 optimum at T0 = 1, e = 1 (`capsubot optimize --problem forcing --stable
// --json`): from rest it settles within a few tens of periods on a 3-right/1-left motion with
// 8 events a period; at T0 = 1.3 it chatters (a dozen impacts and stops a period, ending on
// the wall).
const Forcing kOptimum =
    Forcing::Harmonic(0.34063197373861814, 0.06410131873607934, -3.1181183398453047);
constexpr double kOptimumAlpha = 0.6435592358295166;

TEST(SimulatorReuse, ASettledMotionReusesMostEventsAndChangesNoBit) {
  SimOptions opt = StartAt(kOptimumAlpha, 0.5, 0.0, 0.0, 100.0);
  opt.transient = 200.0;
  const std::int64_t reused =
      ExpectIdenticalWithReuse(kOptimum, Params{1.0, 1.0}, opt).reused_events;
  // 300 periods of 8 events; the motion repeats bit for bit after about 20 periods.
  EXPECT_GT(reused, 2000);
}

TEST(SimulatorReuse, StartsAllOverThePhaseAndTheWallsChangeNoBit) {
  std::int64_t reused = 0;
  int runs = 0;
  for (const double T0 : {0.6, 1.0, 1.3, 2.0}) {
    for (const double x0 : {0.0, 0.3, 1.0}) {
      for (const double psi : {0.0, 2.0, 4.5}) {
        SimOptions opt = StartAt(kOptimumAlpha, x0, 0.0, 0.0, 60.0);
        const Forcing f = kOptimum.WithPhase(kOptimum.phi0() + psi);
        reused += ExpectIdenticalWithReuse(f, Params{T0, 1.0}, opt).reused_events;
        ++runs;
      }
    }
  }
  EXPECT_EQ(runs, 36);
  EXPECT_GT(reused, 0);
}

TEST(SimulatorReuse, AStableOneImpactOrbitChangesNoBit) {
  // A valid, stable orbit (spectral radius ~0.16, see stability_test), from its post-impact
  // state: 1000 periods of one impact and one stop.
  const Params p{0.1, 0.5};
  const Orbit o = ComputeOrbit(Forcing::Harmonic(0.05, 0.02, -2.842), p);
  ASSERT_TRUE(o.ok());
  EXPECT_GT(ExpectIdenticalWithReuse(o.forcing, p, StartAfterImpact(o, 1000.0)).reused_events,
            1000);
}

TEST(SimulatorReuse, StickingBreakAwayAndWorkBoundChangeNoBit) {
  // Chattering that ends resting on the wall and releases (SimulatorTest's case) over many
  // periods; a strong force with break-aways both ways; the chattering again with a work bound
  // of 10 events a period, which its 11 a period reach after the cycle is taken up.
  Params p;
  p.T0 = 0.1;
  p.e = 0.5;
  const Forcing chatter = Forcing::Harmonic(0.05, 0.02, 0.0);
  EXPECT_GT(ExpectIdenticalWithReuse(chatter, p, StartAt(0.3, 0.999, 0.001, 0.0, 50.0)).sticks, 0);
  EXPECT_GT(ExpectIdenticalWithReuse(Forcing::Harmonic(2.0, 0.0, 0.0), Params{1.0, 0.5},
                                     StartAt(0.9, 0.5, -2.0 / 0.9, 0.0, 50.0))
                .breakaways,
            0);
  SimOptions bounded = StartAt(0.3, 0.999, 0.001, 0.0, 50.0);
  bounded.max_events_per_period = 10;
  const SimResult stopped = ExpectIdenticalWithReuse(chatter, p, bounded);
  EXPECT_EQ(stopped.status, SimStatus::kEventLimit);
  EXPECT_GT(stopped.reused_events, 0);
}

TEST(SimulatorReuse, AWallSlideThatRepeatsAllButTheVelocityChangesNoBit) {
  // The body pressed into the right wall (F + alpha T0 >= 0.18 > 0 throughout) while the
  // capsule slides from v = 5 and slows at T0: every period starts at phase 0 with x = 1,
  // u = 0, only v differs, and the stop comes at phase v0 / T0 = 50 (then the robot rests on
  // the wall, a repeated cycle). Without v in what the reuse compares, the stop is never found.
  const Params p{0.1, 1.0};
  const SimResult r = ExpectIdenticalWithReuse(Forcing::Harmonic(0.05, 0.2, 0.0), p,
                                               StartAt(0.3, 1.0, 0.0, 5.0, 30.0));
  EXPECT_EQ(r.stops, 1);
  EXPECT_EQ(r.final_state.mode, SimMode::kOnRightWall);
  EXPECT_GT(r.reused_events, 0);
}

}  // namespace
}  // namespace capsubot
