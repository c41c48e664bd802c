// The long-run motions and the attractors reached from rest (docs/model.md sections 12 and 13).
// Reference numbers come from independent long runs of the simulator (Simulate called
// directly, 10,000 periods) and from the analytic one-impact orbit (ComputeOrbit).

#include "capsubot/attract/attractors.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "capsubot/attract/detail/stroboscopic.hpp"
#include "capsubot/orbit/robot_orbits.hpp"
#include "capsubot/orbit/stability.hpp"
#include "capsubot/orbit/validity.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::Near;

// A periodic motion's mean velocity is exact over whole periods: it agrees with a long
// independent run to rounding (observed ~1e-13 relative); 1e-9 is the required bar.
constexpr double kLongRunRelTol = 1e-9;
constexpr double kLongRunPeriods = 10000.0;
// The analytic orbit and the simulated section state agree to rounding (observed ~1e-14).
constexpr double kOrbitTol = 1e-9;

// The exact stable P2 optimum at T0 = 1, e = 1 without margins, from
// `capsubot optimize --problem forcing --stable --json`: its orbit grazes both walls and has
// a multiplier 1; from rest the robot settles into 3 right and 1 left impacts per period.
struct StableOptimum {
  Forcing forcing =
      Forcing::Harmonic(0.34063197373861814, 0.06410131873607934, -3.1181183398453047);
  Params params;
  double alpha = 0.6435592358295166;
};

// A stable valid one-impact orbit with clearance from both walls (x_min = 0.41, spectral radius
// 0.16; `capsubot solve --A 0.05 --c 0.02 --T0 0.1 --e 0.5 --phi0 -2.842 --stability`).
Solution SmallStableOrbit(Params* params) {
  params->T0 = 0.1;
  params->e = 0.5;
  return Solve(Forcing::Harmonic(0.05, 0.02, -2.842), *params);
}

// Mean velocity of an independent run of kLongRunPeriods periods from a section state.
double LongRunVelocity(const Forcing& forcing, const Params& params, double alpha,
                       const PhaseState& z) {
  const SimOptions o = testing::StartAt(alpha, z.x, z.u, z.v, kLongRunPeriods);
  const SimResult r = Simulate(forcing.WithPhase(forcing.phi0() + z.psi), params, o);
  EXPECT_EQ(r.status, SimStatus::kOk);
  return r.displacement / (kLongRunPeriods * kTau);
}

// The state after `periods` whole periods from a section state (an independent Simulate call).
SimState After(const Forcing& forcing, const Params& params, double alpha, const PhaseState& z,
               double periods) {
  const SimOptions o = testing::StartAt(alpha, z.x, z.u, z.v, periods);
  return Simulate(forcing.WithPhase(forcing.phi0() + z.psi), params, o).final_state;
}

TEST(Attractors, StableOptimumFromRestEndsInThreeRightOneLeftMotionAtItsLongRunVelocity) {
  const StableOptimum r;
  const Attractors a = FindAttractors({r.forcing, r.params, r.alpha}, FromRestOptions{});
  ASSERT_EQ(a.starts, 64);
  ASSERT_EQ(a.motions.size(), 64U);
  ASSERT_FALSE(a.attractors.empty());
  const Attractor& top = a.attractors.front();
  EXPECT_GE(top.fraction, 0.5);  // "most starts"
  EXPECT_EQ(top.motion.status, MotionStatus::kPeriodic);
  EXPECT_EQ(top.motion.period, 1);
  EXPECT_EQ(top.motion.impacts_right, 3);
  EXPECT_EQ(top.motion.impacts_left, 1);
  EXPECT_FALSE(top.one_impact_orbit);
  EXPECT_TRUE(Near(top.motion.mean_velocity, 0.0244, 1e-4));  // the figure users were told
  EXPECT_TRUE(testing::RelNear(top.motion.mean_velocity,
                               LongRunVelocity(r.forcing, r.params, r.alpha, top.motion.section),
                               kLongRunRelTol));
  // Every start of that attractor has the same exact mean velocity, whatever the start.
  int checked = 0;
  for (std::size_t k = 0; k < a.motions.size(); ++k) {
    if (a.labels[k] != 0) continue;
    EXPECT_TRUE(
        testing::RelNear(a.motions[k].mean_velocity, top.motion.mean_velocity, kLongRunRelTol));
    ++checked;
  }
  EXPECT_EQ(checked, top.starts);
  // The analytic one-impact orbits of this robot (the promised 0.0358) are reached by no start.
  const std::vector<Solution> orbits = FindRobotOrbits({r.forcing, r.params, r.alpha});
  ASSERT_GE(orbits.size(), 1U);
  for (const Solution& s : orbits) EXPECT_EQ(CountReached(a, r.forcing, s.orbit), 0);
}

TEST(Attractors, DoNotDependOnTheThreadCountTheEarlyStopOrTheReuseOfCycles) {
  const StableOptimum r;
  FromRestOptions one;
  one.n_x = 4;
  one.n_psi = 4;
  one.attractor.threads = 1;
  FromRestOptions two = one;
  two.attractor.threads = 2;
  FromRestOptions full = one;
  full.attractor.motion.converged_tolerance = 0.0;  // the whole transient and record
  FromRestOptions searched = full;  // and every event searched, none taken from a cycle
  searched.attractor.motion.reuse_cycles = false;
  const Attractors a1 = FindAttractors({r.forcing, r.params, r.alpha}, one);
  const Attractors a2 = FindAttractors({r.forcing, r.params, r.alpha}, two);
  const Attractors af = FindAttractors({r.forcing, r.params, r.alpha}, full);
  const Attractors as = FindAttractors({r.forcing, r.params, r.alpha}, searched);
  ASSERT_EQ(a1.motions.size(), 16U);
  ASSERT_EQ(a2.motions.size(), 16U);
  ASSERT_EQ(af.motions.size(), 16U);
  ASSERT_EQ(as.motions.size(), 16U);
  for (std::size_t k = 0; k < a1.motions.size(); ++k) {
    EXPECT_EQ(af.motions[k].mean_velocity, as.motions[k].mean_velocity);  // bit for bit
    EXPECT_EQ(af.motions[k].section.x, as.motions[k].section.x);
    EXPECT_EQ(af.motions[k].section.u, as.motions[k].section.u);
    EXPECT_EQ(af.labels[k], as.labels[k]);
    EXPECT_EQ(a1.motions[k].mean_velocity, a2.motions[k].mean_velocity);  // bit for bit
    EXPECT_EQ(a1.motions[k].section.x, a2.motions[k].section.x);
    EXPECT_EQ(a1.labels[k], a2.labels[k]);
    EXPECT_EQ(a1.motions[k].period, af.motions[k].period);
    EXPECT_EQ(a1.motions[k].impacts_right, af.motions[k].impacts_right);
    EXPECT_TRUE(
        testing::RelNear(a1.motions[k].mean_velocity, af.motions[k].mean_velocity, kLongRunRelTol));
  }
  EXPECT_EQ(a1.attractors.size(), af.attractors.size());
}

TEST(Attractors, StartOnStableOneImpactOrbitWithClearanceStaysOnIt) {
  Params params;
  const Solution s = SmallStableOrbit(&params);
  ASSERT_TRUE(s.validity.valid());
  ASSERT_TRUE(ComputeStability(s.orbit).stable);
  const Orbit& o = s.orbit;
  // The robot's motor is the orbit's force: motor phase psi + phi0 = phi0 at the start is the
  // impact phase. Start right after the impact: every whole period ends on an impact, so the
  // section must be moved off it.
  PhaseState start;
  start.x = 1.0;
  start.u = -o.e * o.u;
  start.v = o.v_plus;
  start.psi = 0.0;
  const Motion m = LongRunMotion({o.forcing, params, o.alpha}, start, MotionOptions{});
  EXPECT_EQ(m.status, MotionStatus::kPeriodic);
  EXPECT_EQ(m.period, 1);
  EXPECT_EQ(m.impacts_right, 1);
  EXPECT_EQ(m.impacts_left, 0);
  EXPECT_TRUE(testing::RelNear(m.mean_velocity, o.v_mean, kLongRunRelTol));
  EXPECT_TRUE(MatchesOrbit(m, o.forcing, o, kOrbitTol));
  // As one start among others: the attractor is flagged and counted as reached.
  const std::vector<PhaseState> starts = {start, RestStart(0.5, 1.0)};
  const Attractors a = ClassifyStarts({o.forcing, params, o.alpha}, starts, AttractorOptions{});
  ASSERT_EQ(a.labels.size(), 2U);
  EXPECT_TRUE(a.attractors[static_cast<std::size_t>(a.labels[0])].one_impact_orbit);
  EXPECT_GE(CountReached(a, o.forcing, o), 1);
}

TEST(Attractors, OneImpactOrbitIsReachedFromRestAndRecognisedWhateverTheMotorPhase) {
  // The same robot with the motor phase counted from another origin: the grid starts at other
  // forcing phases but the orbit must be recognised the same way.
  Params params;
  const Solution s = SmallStableOrbit(&params);
  const Orbit& o = s.orbit;
  const Forcing robot = o.forcing.WithPhase(o.forcing.phi0() + 1.0);
  const Attractors a = FindAttractors({robot, params, o.alpha}, FromRestOptions{});
  int flagged = 0;
  for (const Attractor& at : a.attractors) flagged += at.one_impact_orbit ? 1 : 0;
  EXPECT_EQ(flagged, 1);
  std::int64_t reached = 0;
  for (const Attractor& at : a.attractors) reached += at.one_impact_orbit ? at.starts : 0;
  EXPECT_GE(reached, 1);
  EXPECT_EQ(CountReached(a, robot, o), reached);
}

TEST(Attractors, ClassifiesPeriodTwoMotion) {
  // Found by scanning T0 and alpha with the stable optimum's force (`capsubot attractors
  // --starts 2x2` over T0 in 0.5..2, alpha in 0.2..0.95): at T0 = 0.5, alpha = 0.8 every start
  // ends in 7 right and 1 left impacts per 2 periods.
  StableOptimum r;
  r.params.T0 = 0.5;
  r.alpha = 0.8;
  FromRestOptions opt;
  opt.n_x = 2;
  opt.n_psi = 2;
  const Attractors a = FindAttractors({r.forcing, r.params, r.alpha}, opt);
  ASSERT_EQ(a.attractors.size(), 1U);
  const Motion& m = a.attractors.front().motion;
  EXPECT_EQ(m.status, MotionStatus::kPeriodic);
  EXPECT_EQ(m.period, 2);
  EXPECT_EQ(m.impacts_right, 7);
  EXPECT_EQ(m.impacts_left, 1);
  // Independently: one period leads elsewhere, two periods come back.
  const SimState one = After(r.forcing, r.params, r.alpha, m.section, 1.0);
  const SimState two = After(r.forcing, r.params, r.alpha, m.section, 2.0);
  EXPECT_GT(std::abs(one.x - m.section.x) + std::abs(one.u - m.section.u), 1e-3);
  EXPECT_TRUE(Near(two.x, m.section.x, kOrbitTol));
  EXPECT_TRUE(Near(two.u, m.section.u, kOrbitTol));
  EXPECT_TRUE(Near(two.v, m.section.v, kOrbitTol));
  // The period search includes its bound: with max_period = 2 the same motion.
  opt.attractor.motion.max_period = 2;
  const Attractors bound = FindAttractors({r.forcing, r.params, r.alpha}, opt);
  ASSERT_EQ(bound.attractors.size(), 1U);
  EXPECT_EQ(bound.attractors.front().motion.status, MotionStatus::kPeriodic);
  EXPECT_EQ(bound.attractors.front().motion.period, 2);
  EXPECT_TRUE(testing::RelNear(
      m.mean_velocity, LongRunVelocity(r.forcing, r.params, r.alpha, m.section), kLongRunRelTol));
}

TEST(Attractors, StartsThatHitTheWorkBoundFormTheirOwnClass) {
  // At T0 = 0.7, alpha = 0.95 the stable optimum's force makes about 100 impacts per period;
  // a work bound of 10 events per period stops every start.
  StableOptimum r;
  r.params.T0 = 0.7;
  r.alpha = 0.95;
  FromRestOptions opt;
  opt.n_x = 2;
  opt.n_psi = 2;
  opt.attractor.motion.max_events_per_period = 10;
  const Attractors a = FindAttractors({r.forcing, r.params, r.alpha}, opt);
  ASSERT_EQ(a.attractors.size(), 1U);
  EXPECT_EQ(a.attractors.front().motion.status, MotionStatus::kEventLimit);
  EXPECT_TRUE(std::isnan(a.attractors.front().motion.mean_velocity));
  EXPECT_EQ(a.event_limit_starts, 4);
  EXPECT_TRUE(std::isnan(a.mean_velocity));  // no start finished
}

TEST(Stroboscopic, SectionGoesToTheMiddleOfTheLargestGapBetweenEvents) {
  std::vector<double> phases = {0.2, 3.0, 0.1};
  // Gaps 0.1, 2.8 and, across phase 0, 0.1 + tau - 3.0 = 3.383...: the middle of the last.
  EXPECT_TRUE(Near(detail::SectionShift(phases), 3.0 + 0.5 * (0.1 + kTau - 3.0), 1e-15));
  phases = {1.0, 2.0};
  EXPECT_TRUE(Near(detail::SectionShift(phases), 2.0 + 0.5 * (kTau - 1.0), 1e-15));
  phases.clear();
  EXPECT_EQ(detail::SectionShift(phases), 0.0);
}

TEST(Stroboscopic, PeriodIsTheSmallestThatRepeatsEveryStateOfTheLastPeriod) {
  std::vector<SimState> samples(9);
  for (std::size_t k = 0; k < samples.size(); ++k) {
    samples[k].x = (k % 3 == 0) ? 0.1 : (k % 3 == 1 ? 0.2 : 0.3);  // period 3
    samples[k].u = 0.0;
    samples[k].v = 0.0;
  }
  EXPECT_EQ(detail::DetectPeriod(samples, 8, 1e-9), 3);
  EXPECT_EQ(detail::DetectPeriod(samples, 2, 1e-9), 0);
  samples[7].mode = SimMode::kSlideForward;  // same numbers, another mode: not the same state
  EXPECT_EQ(detail::DetectPeriod(samples, 8, 1e-9), 0);
}

TEST(AttractorsInput, BadOptionsAreNamedWithTheirValueAndRule) {
  const StableOptimum r;
  const auto message = [&](const FromRestOptions& o, double alpha) -> std::string {
    try {
      FindAttractors({r.forcing, r.params, alpha}, o);
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "no exception";
  };
  FromRestOptions o;
  EXPECT_EQ(message(o, 1.5), "mass ratio alpha = 1.5 is invalid: expected 0 < alpha < 1");
  o.n_x = 0;
  EXPECT_EQ(message(o, 0.5), "n_x = 0 is invalid: expected 1 <= n_x <= 100000 starting positions");
  o = FromRestOptions{};
  o.attractor.motion.record = 10;
  EXPECT_EQ(message(o, 0.5),
            "record = 10 is invalid: expected 2 * max_period = 16 <= record <= 1e7 periods");
  o = FromRestOptions{};
  o.attractor.motion.max_period = 0;
  EXPECT_EQ(message(o, 0.5), "max_period = 0 is invalid: expected 1 <= max_period <= 64");
  o = FromRestOptions{};
  o.attractor.threads = -1;
  EXPECT_EQ(message(o, 0.5),
            "threads = -1 is invalid: expected 1 <= threads <= 1024 (0: all cores)");
  o = FromRestOptions{};
  o.attractor.motion.state_tolerance = 0.0;
  EXPECT_EQ(message(o, 0.5), "state_tolerance = 0 is invalid: expected a finite number > 0");
}

}  // namespace
}  // namespace capsubot
