// Long-run answers that do not depend on numerical settings (docs/attractors.md "How a motion is
// classified"): the early stop only saves time, a long run is one continuous simulation (the
// same as a direct run of the start), a periodic motion's period is its smallest one, and
// motions are grouped by their period and velocity, never by impact counts alone.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <utility>
#include <vector>

#include "capsubot/attract/attractors.hpp"
#include "capsubot/attract/bifurcation.hpp"
#include "capsubot/attract/detail/stroboscopic.hpp"
#include "capsubot/attract/periodic.hpp"
#include "capsubot/orbit/robot_orbits.hpp"
#include "capsubot/orbit/stability.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::Near;

// Newton's method puts the fixed point within 1e-12 of the motion; mean velocities of the
// same periodic motion found from two states agree to rounding (observed ~1e-14 relative).
constexpr double kSameMotionRelTol = 1e-9;
// A multiplier found by finite differences of simulated iterates against the analytic one
// (docs/model.md section 8); observed ~1e-9.
constexpr double kMultiplierTol = 1e-7;
// The mean over starts against direct runs of the same starts: within 2 %.
constexpr double kMeanOverStartsRelTol = 0.02;
// A periodic motion (Newton's fixed point) against the record of a direct run of 3000 periods
// after 2000: the transients of these starts have decayed to rounding by then (measured: 7e-13
// relative at worst over both examples' 128 starts); another attractor differs by far more.
constexpr double kPeriodicAgainstRecordRelTol = 1e-9;
// A motion with no period is the average of the same record as the direct run (a long run is
// one continuous simulation): rounding only.
constexpr double kSameRecordRelTol = 1e-12;
// The same few velocities summed in another order.
constexpr double kSumRoundingTol = 1e-15;

// The design example robot's dimensionless form (`capsubot design --m1 0.2 --L 0.02 --mu 0.3
// --force-amplitude 0.5 --force-bias 0.1 --frequency 20 --e 0.7 --from-rest`): a period-2 motion
// and long irregular motions that pass through sticks of the inner body on a wall.
struct DesignExample {
  Forcing forcing = Forcing::Harmonic(0.007147513690343026, 0.0014295027380686054, 0.0);
  Params params = [] {
    Params p;
    p.T0 = 0.009318382608106253;
    p.e = 0.7;
    return p;
  }();
  double alpha = 0.09704790303928344;
};

// A direct simulation of a start of the long runs (testing::DirectVelocity).
double DirectVelocity(const Forcing& forcing, const Params& params, double alpha,
                      const PhaseState& start, int transient, int record) {
  return testing::DirectVelocity(forcing, params, alpha, start.x, start.u, start.v, start.psi,
                                 transient, record);
}

TEST(LongRun, EarlyStopChangesNoAnswerOverRandomRobots) {
  // 200 random robots of every kind: small and large T0, e from 0 to 1, light and heavy inner
  // bodies, forces near and far from the friction bound; two random starts from rest each.
  std::mt19937_64 rng(20261127);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  int periodic = 0, irregular = 0, early = 0, compared = 0;
  for (int robot = 0; robot < 200; ++robot) {
    Params params;
    params.T0 = std::pow(10.0, -2.0 + 2.0 * unit(rng));
    params.e = unit(rng);
    const double share = unit(rng);
    const double total = 0.5 + 0.5 * unit(rng);  // (A + c)/T0
    const Forcing forcing =
        Forcing::Harmonic(share * total * params.T0, (1.0 - share) * total * params.T0,
                          kTau * unit(rng) - 0.5 * kTau);
    const double alpha = 0.05 + 0.9 * unit(rng);
    AttractorOptions stop, full;
    stop.threads = full.threads = 1;
    full.motion.converged_tolerance = 0.0;
    const std::vector<PhaseState> starts = {RestStart(unit(rng), kTau * unit(rng)),
                                            RestStart(unit(rng), kTau * unit(rng))};
    const std::vector<Motion> a = LongRunMotions({forcing, params, alpha}, starts, stop);
    const std::vector<Motion> b = LongRunMotions({forcing, params, alpha}, starts, full);
    for (std::size_t k = 0; k < starts.size(); ++k) {
      SCOPED_TRACE("robot " + std::to_string(robot) + " start " + std::to_string(k));
      ASSERT_EQ(a[k].status, b[k].status);
      ++compared;
      if (a[k].status == MotionStatus::kEventLimit) continue;
      EXPECT_EQ(a[k].period, b[k].period);
      EXPECT_TRUE(testing::RelNear(a[k].mean_velocity, b[k].mean_velocity, kSameMotionRelTol));
      if (a[k].status == MotionStatus::kPeriodic) {
        ++periodic;
        EXPECT_EQ(a[k].impacts_right, b[k].impacts_right);
        EXPECT_EQ(a[k].impacts_left, b[k].impacts_left);
      } else {
        ++irregular;
        EXPECT_EQ(a[k].mean_velocity, b[k].mean_velocity);  // the same run, bit for bit
      }
      const std::vector<Motion> one =
          LongRunMotions({forcing, params, alpha}, {starts[k]}, stop);  // no cross-talk
      EXPECT_EQ(one[0].mean_velocity, a[k].mean_velocity);
    }
    // Did the early stop act? A run it stopped records no impact of the record.
    for (const PhaseState& start : starts) {
      detail::Recorder recorder;
      detail::ClassifyMotion({forcing, params, alpha}, stop.motion, {start, SimMode::kRest},
                             recorder, true);
      early += recorder.impacts.empty() ? 1 : 0;
    }
  }
  EXPECT_EQ(compared, 400);
  // The table holds both kinds of motion, and the early stop was used.
  EXPECT_GE(periodic, 100);
  EXPECT_GE(irregular, 5);
  EXPECT_GE(early, 50);
}

TEST(LongRun, AttractorsAgreeWithDirectRunsOfTheSameStarts) {
  // The chaotic transients of this robot end in its period-2 motion or in long motions through
  // sticks; restarting the simulation every few periods (as an early stop used to) sent three
  // times as many starts into the period-2 motion as direct runs do.
  const DesignExample r;
  const int transient = 2000, record = 3000;
  FromRestOptions o;
  o.attractor.motion.transient = transient;
  o.attractor.motion.record = record;
  const Attractors a = FindAttractors({r.forcing, r.params, r.alpha}, o);
  ASSERT_EQ(a.motions.size(), 64U);
  const std::vector<PhaseState> starts = GridStarts(8, 8);
  double direct_sum = 0.0;
  int irregular = 0;
  for (std::size_t k = 0; k < starts.size(); ++k) {
    const double direct =
        DirectVelocity(r.forcing, r.params, r.alpha, starts[k], transient, record);
    direct_sum += direct;
    if (a.motions[k].status == MotionStatus::kNoPeriod) {
      ++irregular;
      EXPECT_TRUE(testing::RelNear(a.motions[k].mean_velocity, direct, 1e-12)) << "start " << k;
    } else {  // a direct run's record may still hold part of the chaotic transient
      ASSERT_EQ(a.motions[k].status, MotionStatus::kPeriodic);
    }
  }
  EXPECT_GE(irregular, 32);
  EXPECT_TRUE(testing::RelNear(a.mean_velocity, direct_sum / 64.0, kMeanOverStartsRelTol));
  // The irregular starts form a few irregular attractors (clusters of mean velocity), each
  // with the range of its starts' velocities; the ranges do not overlap.
  int irregular_starts = 0;
  std::vector<std::pair<double, double>> ranges;
  for (const Attractor& at : a.attractors) {
    if (at.motion.status != MotionStatus::kNoPeriod) continue;
    irregular_starts += static_cast<int>(at.starts);
    EXPECT_LE(at.velocity_min, at.mean_velocity);
    EXPECT_GE(at.velocity_max, at.mean_velocity);
    ranges.emplace_back(at.velocity_min, at.velocity_max);
  }
  EXPECT_EQ(irregular_starts, irregular);
  ASSERT_FALSE(ranges.empty());
  EXPECT_LT(ranges.size(), 4U);  // a few clusters, not one attractor per start
  std::sort(ranges.begin(), ranges.end());
  for (std::size_t k = 1; k < ranges.size(); ++k) {
    EXPECT_GT(ranges[k].first, ranges[k - 1].second * (1.0 + Grouping{}.irregular_tolerance));
  }
}

// The robots of the examples in docs/attractors.md (the stable optimum at T0 = 1, e = 1 and
// the orbit with clearance beside its period-12 motion).
struct Example {
  const char* name;
  Forcing forcing;
  Params params;
  double alpha;
  int max_period;
};

std::vector<Example> DocExamples() {
  Params paper;
  Params clearance;
  clearance.T0 = 0.1;
  clearance.e = 0.5;
  return {{"stable optimum",
           Forcing::Harmonic(0.34063197373861814, 0.06410131873607934, -3.1181183398453047), paper,
           0.6435592358295166, 8},
          {"orbit with clearance", Forcing::Harmonic(0.05, 0.02, -2.842), clearance,
           0.2792869076315278, 16}};
}

TEST(LongRun, DocExamplesAgreeWithDirectRunsOfTheSameStarts) {
  // Every start, not only the mean: a start in the wrong attractor would hide in the mean.
  const int transient = 2000, record = 3000;
  for (const Example& ex : DocExamples()) {
    SCOPED_TRACE(ex.name);
    FromRestOptions o;
    o.attractor.motion.transient = transient;
    o.attractor.motion.record = record;
    o.attractor.motion.max_period = ex.max_period;
    const Attractors a = FindAttractors({ex.forcing, ex.params, ex.alpha}, o);
    const std::vector<PhaseState> starts = GridStarts(8, 8);
    ASSERT_EQ(a.motions.size(), starts.size());
    EXPECT_EQ(a.event_limit_starts, 0);
    double direct_sum = 0.0;
    for (std::size_t k = 0; k < starts.size(); ++k) {
      const double direct =
          DirectVelocity(ex.forcing, ex.params, ex.alpha, starts[k], transient, record);
      direct_sum += direct;
      const Motion& m = a.motions[k];
      ASSERT_NE(m.status, MotionStatus::kEventLimit) << "start " << k;
      const double tol =
          m.status == MotionStatus::kPeriodic ? kPeriodicAgainstRecordRelTol : kSameRecordRelTol;
      EXPECT_TRUE(testing::RelNear(m.mean_velocity, direct, tol)) << "start " << k;
    }
    EXPECT_TRUE(testing::RelNear(a.mean_velocity, direct_sum / 64.0, kMeanOverStartsRelTol));
  }
}

TEST(LongRun, PeriodIsTheSmallestWithTheMultipliersOfOnePeriod) {
  // Started next to the stable one-impact orbit of this force, the closest return may be at
  // p = 3; Newton's fixed point is one of the first iterate.
  Params params;
  params.T0 = 0.03359258640909073;
  params.e = 1.0;
  const Forcing forcing =
      Forcing::Harmonic(0.012379276257211788, 0.018006366775342907, -2.3431342586039907);
  const Solution s = Solve(forcing, params);
  ASSERT_TRUE(s.validity.valid());
  const Stability st = ComputeStability(s.orbit);
  ASSERT_TRUE(st.stable);
  PhaseState z;
  z.x = 0.5032482015201704;
  z.u = 0.17018581585325004;
  z.v = 0.0;
  z.psi = 4.437859415761879;
  for (int period : {1, 2, 3, 6}) {
    SCOPED_TRACE("shot with period " + std::to_string(period));
    const PeriodicMotion pm = ShootPeriodicMotion({forcing, params, s.orbit.alpha}, z, period, {});
    ASSERT_EQ(pm.status, ShootingStatus::kConverged);
    EXPECT_EQ(pm.period, 1);
    EXPECT_EQ(pm.impacts_right, 1);
    EXPECT_EQ(pm.impacts_left, 0);
    EXPECT_TRUE(testing::RelNear(pm.mean_velocity, s.orbit.v_mean, kSameMotionRelTol));
    ASSERT_EQ(pm.multipliers.size(), 2U);
    EXPECT_TRUE(Near(std::abs(pm.multipliers[0]), st.spectral_radius, kMultiplierTol));
  }
  ShootingOptions from_near;
  from_near.max_period = 8;
  const PeriodicMotion found = FindPeriodicMotion({forcing, params, s.orbit.alpha}, z, from_near);
  EXPECT_EQ(found.period, 1);
  EXPECT_TRUE(Near(found.spectral_radius, st.spectral_radius, kMultiplierTol));
}

TEST(LongRun, SlowlyConvergingPeriodOneNearPeriodDoublingIsPeriodOne) {
  // A = 0.2, c = 0.03, phi0 = -2.518525390 at T0 = 1, e = 1: the one-impact orbit has a
  // multiplier -1 at alpha = 0.64062; at alpha = 0.645 it is stable but converges slowly, so
  // the recorded states repeat better every 2 periods than every period.
  Params params;
  const Forcing forcing = Forcing::Harmonic(0.2, 0.03, -2.518525390);
  const double alpha = 0.645;
  const std::vector<Solution> orbits = FindRobotOrbits({forcing, params, alpha});
  const Solution* stable = nullptr;
  for (const Solution& s : orbits) {
    if (s.validity.valid() && ComputeStability(s.orbit).stable) stable = &s;
  }
  ASSERT_NE(stable, nullptr);
  const double rho = ComputeStability(stable->orbit).spectral_radius;
  ASSERT_GT(rho, 0.8);  // slowly converging: the case under test
  // Started off the orbit by 1e-3 in x, one radian after its impact.
  const double phi = 1.0;
  PhaseState start;
  start.x = stable->orbit.x(phi) - 1e-3;
  start.u = stable->orbit.dx(phi);
  start.v = stable->orbit.v(phi);
  start.psi = phi + stable->orbit.forcing.phi0() - forcing.phi0();
  // Short runs end while the motion still alternates about the orbit (deviations of 1e-6 to
  // 1e-5 after 30 to 50 periods): every 2 periods it returns 7 times closer than every period.
  int periodic = 0;
  for (int transient = 0; transient <= 60; transient += 5) {
    SCOPED_TRACE("transient " + std::to_string(transient));
    MotionOptions o;
    o.transient = transient;
    o.record = 16;
    o.converged_tolerance = 0.0;
    const Motion m = LongRunMotion({forcing, params, alpha}, start, o);
    if (m.status != MotionStatus::kPeriodic) continue;  // not yet within state_tolerance
    ++periodic;
    EXPECT_EQ(m.period, 1);
    EXPECT_TRUE(m.refined);
    EXPECT_TRUE(testing::RelNear(m.mean_velocity, stable->orbit.v_mean, kSameMotionRelTol));
    EXPECT_TRUE(Near(m.spectral_radius, rho, kMultiplierTol));
  }
  EXPECT_GE(periodic, 5);
}

// The orbit with clearance of docs/attractors.md: stable, spectral radius 0.16, its impact at
// the motor phase phi0, so starts at psi = 0 begin on its impact.
struct ClearanceOrbit {
  Forcing forcing = Forcing::Harmonic(0.05, 0.02, -2.842);
  Params params = [] {
    Params p;
    p.T0 = 0.1;
    p.e = 0.5;
    return p;
  }();
  double alpha = 0.2792869076315278;
};

TEST(LongRun, SectionIsOffTheImpactForEveryTransient) {
  const ClearanceOrbit r;
  const Solution s = Solve(r.forcing, r.params);
  const double rho = ComputeStability(s.orbit).spectral_radius;
  for (int transient : {0, 1, 2}) {
    SCOPED_TRACE("transient " + std::to_string(transient));
    AttractorOptions o;
    o.motion.transient = transient;
    o.motion.record = 200;
    const std::vector<PhaseState> starts = GridStarts(4, 3);
    const Attractors a = ClassifyStarts({r.forcing, r.params, r.alpha}, starts, o);
    int on_orbit = 0;
    for (std::size_t k = 0; k < starts.size(); ++k) {
      const Motion& m = a.motions[k];
      if (m.status != MotionStatus::kPeriodic || m.period != 1) continue;
      ++on_orbit;
      EXPECT_EQ(m.impacts_right, 1) << "start " << k;
      EXPECT_EQ(m.impacts_left, 0) << "start " << k;
    }
    EXPECT_GE(on_orbit, 4);  // the psi = 0 starts among them
    EXPECT_EQ(a.attractors.front().motion.impacts_right, 1);
    // The bifurcation diagram started on the impact reports the orbit's own spectral radius.
    BifurcationOptions b;
    b.param = ModelParameter::kAlpha;
    b.from = r.alpha;
    b.to = 0.28;
    b.steps = 2;
    b.start = RestStart(0.125, 0.0);
    b.motion.transient = transient;
    const BifurcationDiagram d = ComputeBifurcation({r.forcing, r.params, r.alpha}, b);
    ASSERT_FALSE(d.summary.empty());
    EXPECT_EQ(d.summary.front().motion.period, 1);
    EXPECT_TRUE(Near(d.summary.front().spectral_radius, rho, kMultiplierTol));
  }
}

Motion PeriodicWith(int period, std::int64_t right, std::int64_t left, double v) {
  Motion m;
  m.status = MotionStatus::kPeriodic;
  m.period = period;
  m.impacts_right = right;
  m.impacts_left = left;
  m.mean_velocity = m.first_half_velocity = m.second_half_velocity = v;
  return m;
}

Motion Irregular(double v, double first, double second) {
  Motion m;
  m.status = MotionStatus::kNoPeriod;
  m.mean_velocity = v;
  m.first_half_velocity = first;
  m.second_half_velocity = second;
  return m;
}

TEST(LongRun, MotionsAreGroupedByPeriodAndVelocityNotImpactCounts) {
  // Two chattering motions cut after different numbers of impacts (176/14 and 227/17) with
  // velocities equal to 1e-10: one attractor. Irregular motions 0.0103 to 0.0104: one
  // irregular attractor; one far away: another.
  const std::vector<Motion> motions = {
      PeriodicWith(1, 176, 14, 0.151436), PeriodicWith(1, 227, 17, 0.151436 * (1 + 1e-10)),
      Irregular(0.01033, 0.0102, 0.0104), Irregular(0.01041, 0.0104, 0.0104),
      Irregular(0.01037, 0.0103, 0.0104), Irregular(-0.02, -0.02, -0.02),
      PeriodicWith(2, 1, 1, 0.151436)};
  const std::vector<PhaseState> starts(motions.size(), RestStart(0.5, 0.0));
  const Attractors a = GroupMotions(starts, motions, Grouping{});
  ASSERT_EQ(a.attractors.size(), 4U);
  EXPECT_EQ(a.labels[0], a.labels[1]);
  EXPECT_EQ(a.labels[2], a.labels[3]);
  EXPECT_EQ(a.labels[2], a.labels[4]);
  EXPECT_NE(a.labels[5], a.labels[2]);
  EXPECT_NE(a.labels[6], a.labels[0]);  // another period
  const Attractor& irregular = a.attractors[static_cast<std::size_t>(a.labels[2])];
  EXPECT_EQ(irregular.starts, 3);
  EXPECT_DOUBLE_EQ(irregular.velocity_min, 0.01033);
  EXPECT_DOUBLE_EQ(irregular.velocity_max, 0.01041);
  EXPECT_TRUE(Near(irregular.mean_velocity, (0.01033 + 0.01041 + 0.01037) / 3.0, 1e-15));
  EXPECT_TRUE(Near(irregular.halves_difference, 0.0002 / irregular.mean_velocity, 1e-12));
  EXPECT_GT(irregular.halves_difference, kSettledHalves);  // the record is too short
  // The grouping does not depend on the order of the starts.
  std::vector<Motion> reversed(motions.rbegin(), motions.rend());
  const Attractors b = GroupMotions(starts, reversed, Grouping{});
  EXPECT_EQ(b.attractors.size(), a.attractors.size());
}

TEST(LongRun, PeriodicMotionsOfOnePeriodApartByMoreThanTheToleranceStayTwoAttractors) {
  // The default tolerance is 1e-6 of the speed: two motions of period 1 whose speeds differ by
  // 1e-5 of it are two attractors (a grouping 100 times looser would merge them), two that
  // differ by 1e-7 are one (100 times tighter would split them). The speed is the 3-right/1-left
  // motion's of docs/attractors.md; any would do.
  constexpr double kV = 0.0244;
  const double tolerance = Grouping{}.velocity_tolerance;
  const std::vector<PhaseState> starts(2, RestStart(0.5, 0.0));
  const Attractors apart = GroupMotions(
      starts, {PeriodicWith(1, 3, 1, kV), PeriodicWith(1, 3, 1, kV * (1.0 + 10.0 * tolerance))},
      Grouping{});
  ASSERT_EQ(apart.attractors.size(), 2U);
  EXPECT_NE(apart.labels[0], apart.labels[1]);
  const Attractors together = GroupMotions(
      starts, {PeriodicWith(1, 3, 1, kV), PeriodicWith(1, 3, 1, kV * (1.0 + 0.1 * tolerance))},
      Grouping{});
  ASSERT_EQ(together.attractors.size(), 1U);
  EXPECT_EQ(together.labels[0], together.labels[1]);
  // Backward motions alike: the tolerance is relative to the magnitude.
  const Attractors backward = GroupMotions(
      starts, {PeriodicWith(1, 3, 1, -kV), PeriodicWith(1, 3, 1, -kV * (1.0 + 10.0 * tolerance))},
      Grouping{});
  EXPECT_EQ(backward.attractors.size(), 2U);
}

TEST(LongRun, GroupingGivesTheSameAnswerForTheStartsInAnyOrder) {
  // Three periodic motions (two of period 1, 1e-5 of their speed apart, one of period 2), one
  // irregular cluster and a start at the work bound, with 4, 3, 2, 5 and 1 starts (no two
  // classes of equal size, so the ranks are defined), each start's velocity jittered within
  // the tolerance. In every order of the starts each start gets the same attractor: the same
  // label, period, speed range, mean velocity and fraction.
  constexpr double kV = 0.0244;
  std::vector<Motion> motions;
  std::vector<PhaseState> starts;
  const auto add = [&](const Motion& m, int copies, double jitter) {
    for (int k = 0; k < copies; ++k) {
      Motion j = m;
      j.mean_velocity *= 1.0 + jitter * k;
      motions.push_back(j);
      starts.push_back(RestStart(0.05 + 0.06 * static_cast<double>(starts.size()), 0.0));
    }
  };
  add(PeriodicWith(1, 3, 1, kV), 4, 1e-9);
  add(PeriodicWith(1, 3, 1, kV * (1.0 + 1e-5)), 3, 1e-9);
  add(PeriodicWith(2, 4, 2, kV), 2, 1e-9);
  add(Irregular(0.0103, 0.0102, 0.0104), 5, 1e-3);
  Motion bound;
  bound.status = MotionStatus::kEventLimit;
  add(bound, 1, 0.0);
  const Attractors ref = GroupMotions(starts, motions, Grouping{});
  ASSERT_EQ(ref.attractors.size(), 5U);
  std::vector<std::size_t> order(motions.size());
  for (std::size_t k = 0; k < order.size(); ++k) order[k] = k;
  std::mt19937_64 rng(36);
  for (int trial = 0; trial < 20; ++trial) {
    std::shuffle(order.begin(), order.end(), rng);
    std::vector<Motion> m;
    std::vector<PhaseState> s;
    for (const std::size_t k : order) {
      m.push_back(motions[k]);
      s.push_back(starts[k]);
    }
    const Attractors got = GroupMotions(s, m, Grouping{});
    ASSERT_EQ(got.attractors.size(), ref.attractors.size()) << "trial " << trial;
    for (std::size_t i = 0; i < order.size(); ++i) {
      const auto g = static_cast<std::size_t>(got.labels[i]);
      const auto r = static_cast<std::size_t>(ref.labels[order[i]]);
      EXPECT_EQ(g, r) << "trial " << trial << ", start " << order[i];
      const Attractor &a = got.attractors[g], &b = ref.attractors[r];
      EXPECT_EQ(a.motion.status, b.motion.status);
      EXPECT_EQ(a.motion.period, b.motion.period);
      EXPECT_EQ(a.starts, b.starts);
      EXPECT_EQ(a.fraction, b.fraction);
      if (b.motion.status == MotionStatus::kEventLimit) continue;  // it has no velocity
      EXPECT_EQ(a.velocity_min, b.velocity_min);
      EXPECT_EQ(a.velocity_max, b.velocity_max);
      // The same velocities summed in another order: a few roundings.
      EXPECT_TRUE(
          Near(a.mean_velocity, b.mean_velocity, kSumRoundingTol * std::abs(b.mean_velocity)));
    }
    EXPECT_TRUE(
        Near(got.mean_velocity, ref.mean_velocity, kSumRoundingTol * std::abs(ref.mean_velocity)));
  }
  // The classes, largest first, from the counts written above.
  EXPECT_EQ(ref.attractors[0].starts, 5);
  EXPECT_EQ(ref.attractors[0].motion.status, MotionStatus::kNoPeriod);
  EXPECT_EQ(ref.attractors[1].starts, 4);
  EXPECT_EQ(ref.attractors[1].velocity_min, kV);
  EXPECT_EQ(ref.attractors[2].starts, 3);
  EXPECT_EQ(ref.attractors[2].velocity_min, kV * (1.0 + 1e-5));
  EXPECT_EQ(ref.attractors[3].motion.period, 2);
  EXPECT_EQ(ref.attractors[4].motion.status, MotionStatus::kEventLimit);
  EXPECT_EQ(ref.event_limit_starts, 1);
  EXPECT_DOUBLE_EQ(ref.attractors[1].fraction, 4.0 / 15.0);
}

TEST(LongRun, NoVerdictWithoutConvergence) {
  // A start far beyond any motion: Newton does not converge, so nothing is called stable.
  Params params;
  const Forcing forcing = Forcing::Harmonic(0.5, 0.3, -2.9);
  PhaseState z = RestStart(0.5, 0.0);
  z.u = 1e10;
  ShootingOptions o;
  o.max_iterations = 3;
  const PeriodicMotion pm = FindPeriodicMotion({forcing, params, 0.5}, z, o);
  EXPECT_NE(pm.status, ShootingStatus::kConverged);
  EXPECT_FALSE(pm.stable);
}

}  // namespace
}  // namespace capsubot
