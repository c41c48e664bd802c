// The fastest motion reached from rest in each direction (docs/model.md sections 9, 11, 12, 13):
// the example robot's backward motion at a small inner mass against an independent scan with
// the simulator, the forward result against a direct simulation of every start, the fractions,
// the energy budget of the reached motion, a motor that slides the shell, bad options.

#include "capsubot/design/design_from_rest.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "capsubot/simulate/simulator.hpp"
#include "design/example_robot.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::NearAbsBelowOne;

// The small inner masses of the independent scan [kg]: where the example robot's light inner
// body drives the shell backward (docs/design.md, the from-rest figure).
const std::vector<double> kSmallM2 = {0.008, 0.012, 0.016, 0.02, 0.025};
// Forward one-impact gaits are scanned over the same region, densely (log-spaced).
constexpr double kSmallLo = 0.002, kSmallHi = 0.03;
constexpr int kGaitScan = 400;
// The search may end between the scan's points, or a little below the best of them: the
// optimum of a 1-D search over log m2 with 140 evaluations against 5 points of a scan.
constexpr double kScanRelTol = 0.02;
// Every start simulated directly (Simulate: the same transient, then kDirectRecord periods)
// against the motions classified by FindAttractors. A periodic motion's mean over whole
// periods is the same up to rounding (measured: 7e-13 for the example's backward motion).
constexpr double kDirectRelTol = 1e-9;
// A motion without a period is a time average: over the check's 1000 periods against the
// direct run's 5000. A chaotic motion's average over 1000 periods carries a statistical error
// of the order of one per cent (measured: 6e-4 and 8.6e-3 at two forward optima).
constexpr double kTimeAverageRelTol = 2e-2;
constexpr int kDirectRecord = 5000;
// Starts of the 64 that one long run carries into the backward motion, at least (measured:
// 62 of 64 at the default search's optimum).
constexpr int kReachedMin = 56;
// Motor work = friction + impact losses over whole periods of a periodic motion (the kinetic
// energy returns): the simulator's tally is exact up to rounding.
constexpr double kBalanceRelTol = 1e-9;

// Speed [mm/s] of the robot (m1, L, mu, e, motor of the example) with inner mass m2 at f Hz,
// mapped to the model by hand (docs/model.md section 9), from the default 8 x 8 grid of starts.
double ScanSpeed(double m2) {
  const DesignInput in = testing::ExampleRobot();
  const double w = 2.0 * M_PI * 20.0, M = in.m1 + m2;
  Params p;
  p.T0 = in.mu * in.g / (w * w * in.L);
  p.e = in.e;
  const Forcing f = Forcing::Harmonic(0.5 / (M * w * w * in.L), 0.1 / (M * w * w * in.L), 0.0);
  const Attractors a = FindAttractors({f, p, m2 / M}, FromRestOptions{});
  EXPECT_EQ(a.event_limit_starts, 0);
  return 1e3 * w * in.L * a.mean_velocity;
}

// The example robot's design from rest with the default options (computed once: a few seconds).
const DesignFromRestResult& ExampleResult() {
  static const DesignFromRestResult r = DesignFromRest(testing::ExampleRobot());
  return r;
}

TEST(DesignFromRest, ASmallInnerMassDrivesTheExampleBackwardFasterThanAnyForwardGaitThere) {
  const DesignInput in = testing::ExampleRobot();
  const DesignFromRestResult& r = ExampleResult();
  ASSERT_TRUE(r.backward.ok()) << r.backward.message;
  EXPECT_LT(r.backward.speed_mm_s, 0.0);
  EXPECT_LT(r.backward.m2_kg, kSmallHi);

  // Independent scan with the simulator: the search finds at least the best of its points.
  double best_scan = 0.0;
  int scanned = 0;
  for (double m2 : kSmallM2) {
    best_scan = std::min(best_scan, ScanSpeed(m2));
    ++scanned;
  }
  EXPECT_EQ(scanned, 5);
  EXPECT_LT(best_scan, 0.0);
  EXPECT_LE(r.backward.speed_mm_s, best_scan * (1.0 - kScanRelTol))
      << "search " << r.backward.speed_mm_s << " mm/s, scan " << best_scan << " mm/s";

  // Every valid one-impact orbit there (stable or not, margins off) is slower forward.
  DesignInput any = in;
  any.margin = any.margin_stroke = any.stick_margin = 0.0;
  any.rho_max = HUGE_VAL;
  double fastest_gait = 0.0;
  int gaits = 0;
  for (int i = 0; i < kGaitScan; ++i) {
    const double m2 = kSmallLo * std::pow(kSmallHi / kSmallLo, i / (kGaitScan - 1.0));
    const Gait g = EvaluateGait(any, m2, 20.0);
    if (!g.ok()) continue;
    fastest_gait = std::max(fastest_gait, g.speed_mm_s);
    ++gaits;
  }
  EXPECT_GT(gaits, 0);
  EXPECT_GT(-r.backward.speed_mm_s, fastest_gait);
}

// One start of the check's grid simulated directly: the transient of the check settings,
// then kDirectRecord periods in one run; its mean velocity [mm/s].
double DirectStartSpeed(const DesignInput& in, const DesignModel& m, int i, int j) {
  const FromRestOptions o = DesignFromRestOptions().check;
  const PhaseState s = GridStart(i, j, o.n_x, o.n_psi);
  SimOptions so;
  so.alpha = m.robot.alpha;
  so.x0 = s.x;
  so.u0 = s.u;
  so.v0 = s.v;
  so.transient = o.attractor.motion.transient;
  so.periods = kDirectRecord;
  const SimResult r = Simulate(m.robot.forcing.WithPhase(s.psi), m.robot.params, so);
  EXPECT_EQ(r.status, SimStatus::kOk);
  return 1e3 * m.omega * in.L * r.v_mean;
}

// The example's backward optimum: one periodic motion. Every start simulated directly in one
// long run (no pieces, no early stop) ends in it (same mean velocity up to rounding), except a
// few: near a basin boundary the fate of a start changes with the last bits of the simulation,
// and the attractor search simulates in pieces. The design reports the search's fractions;
// docs/design.md says how many starts a long run carries elsewhere.
TEST(DesignFromRest, TheBackwardMotionIsWhatNearlyEveryStartReachesInOneLongRun) {
  const DesignInput in = testing::ExampleRobot();
  const FromRestBest& b = ExampleResult().backward;
  ASSERT_TRUE(b.ok()) << b.message;
  ASSERT_EQ(b.attractors.attractors.size(), 1u);
  const Attractor& a = b.attractors.attractors[0];
  ASSERT_EQ(a.motion.status, MotionStatus::kPeriodic);
  const DesignModel m = MapToModel(in, b.m2_kg, b.frequency_hz);
  const double v = 1e3 * m.omega * in.L * a.motion.mean_velocity;
  EXPECT_TRUE(NearAbsBelowOne(b.speed_mm_s, v, kDirectRelTol));
  const FromRestOptions o = DesignFromRestOptions().check;
  int reached = 0;
  for (int i = 0; i < o.n_x; ++i) {
    for (int j = 0; j < o.n_psi; ++j) {
      if (NearAbsBelowOne(DirectStartSpeed(in, m, i, j), v, kDirectRelTol)) ++reached;
    }
  }
  EXPECT_GE(reached, kReachedMin);
}

// The forward optimum above m2 = 50 g: one motion without a period, the same from every
// start; its time average over the check's record against the direct runs' longer record.
// Below 50 g the forward optimum mixes a period-2 attractor with motions without a period;
// which starts go where is sensitive to every rounding, so a direct run reproduces it only
// statistically.
TEST(DesignFromRest, TheForwardMotionWithoutAPeriodEqualsTheTimeAverageOfLongRuns) {
  DesignInput in = testing::ExampleRobot();
  in.m2_min = 0.05;
  in.m2_max = 2.0;
  const DesignFromRestResult r = DesignFromRest(in);
  const FromRestBest& b = r.forward;
  ASSERT_TRUE(b.ok()) << b.message;
  const auto& list = b.attractors.attractors;
  EXPECT_TRUE(std::none_of(list.begin(), list.end(), [](const Attractor& a) {
    return a.motion.status == MotionStatus::kPeriodic;
  }));
  const DesignModel m = MapToModel(in, b.m2_kg, b.frequency_hz);
  const FromRestOptions o = DesignFromRestOptions().check;
  double sum = 0.0;
  int starts = 0;
  for (int i = 0; i < o.n_x; ++i) {
    for (int j = 0; j < o.n_psi; ++j) {
      sum += DirectStartSpeed(in, m, i, j);
      ++starts;
    }
  }
  EXPECT_TRUE(NearAbsBelowOne(b.speed_mm_s, sum / starts, kTimeAverageRelTol));
}

TEST(DesignFromRest, FractionsOfTheStartsSumToOneAndSayWhereDirectionsCoexist) {
  const DesignInput in = testing::ExampleRobot();
  const DesignFromRestResult& r = ExampleResult();
  for (const FromRestBest* b : {&r.forward, &r.backward}) {
    double sum = 0.0;
    std::int64_t starts = 0;
    double forward = 0.0, backward = 0.0;
    for (const Attractor& a : b->attractors.attractors) {
      sum += a.fraction;
      starts += a.starts;
      if (a.motion.mean_velocity > 0.0) forward += a.fraction;
      if (a.motion.mean_velocity < 0.0) backward += a.fraction;
    }
    EXPECT_NEAR(sum, 1.0, 1e-12);
    EXPECT_EQ(starts, b->attractors.starts);
    EXPECT_NEAR(b->forward_fraction, forward, 1e-12);
    EXPECT_NEAR(b->backward_fraction, backward, 1e-12);
    EXPECT_NEAR(b->forward_fraction + b->backward_fraction, 1.0, 1e-12);  // none at rest
    const bool both = b->forward_fraction > 0.0 && b->backward_fraction > 0.0;
    EXPECT_EQ(b->message.find("coexist") != std::string::npos, both) << b->message;
  }
}

TEST(DesignFromRest, EnergyOfAPeriodicMotionBalancesAndMatchesADirectRunFromItsStart) {
  const DesignInput in = testing::ExampleRobot();
  const DesignFromRestResult& r = ExampleResult();
  const FromRestBest& b = r.backward;  // the example's backward motion: one period-1 attractor
  ASSERT_TRUE(b.ok()) << b.message;
  ASSERT_EQ(b.attractors.attractors.size(), 1u);
  const Attractor& a = b.attractors.attractors.front();
  ASSERT_EQ(a.motion.status, MotionStatus::kPeriodic);
  EXPECT_TRUE(NearAbsBelowOne(b.energy_mj, b.friction_loss_mj + b.impact_loss_mj, kBalanceRelTol));
  EXPECT_GE(b.cot, in.mu);
  EXPECT_TRUE(NearAbsBelowOne(b.efficiency, in.mu / b.cot, 1e-15));
  EXPECT_TRUE(NearAbsBelowOne(b.power_mw, b.energy_mj * b.frequency_hz, 1e-15));
  // The same budget from the attractor's own first start: transient, then its period, tallied.
  const DesignModel& m = b.model;
  SimOptions so;
  so.alpha = m.robot.alpha;
  so.x0 = a.example.x;
  so.u0 = a.example.u;
  so.v0 = a.example.v;
  so.transient = DesignFromRestOptions().check.attractor.motion.transient;
  so.periods = a.motion.period;
  so.energy = true;
  const SimResult run = Simulate(m.robot.forcing.WithPhase(a.example.psi), m.robot.params, so);
  ASSERT_EQ(run.status, SimStatus::kOk);
  const double unit = 1e3 * (in.m1 + b.m2_kg) * m.omega * m.omega * in.L * in.L;  // mJ
  EXPECT_TRUE(
      NearAbsBelowOne(b.energy_mj, unit * run.energy.motor_work / so.periods, kDirectRelTol));
  EXPECT_TRUE(
      NearAbsBelowOne(b.impact_loss_mj, unit * run.energy.impact_loss / so.periods, kDirectRelTol));
  // Two impacts per period (one on each wall): no single impact velocity.
  EXPECT_EQ(a.motion.impacts_right + a.motion.impacts_left, 2);
  EXPECT_TRUE(std::isnan(b.impact_velocity_m_s));
}

TEST(DesignFromRest, AMotorThatSlidesTheShellHasNoGaitButAMotionFromRest) {
  DesignInput in = testing::ExampleRobot();
  in.force.amplitude = 5.0;
  in.m2_min = 0.01;
  in.m2_max = 1.0;
  ASSERT_EQ(Design(in).status, DesignStatus::kMotorSlidesShell);
  const DesignFromRestResult r = DesignFromRest(in);
  EXPECT_TRUE(r.forward.ok() || r.backward.ok()) << r.forward.message << "; " << r.backward.message;
  EXPECT_GT(r.evaluations, 0);
}

TEST(DesignFromRest, BadOptionsNameTheFieldItsValueAndTheRule) {
  const struct {
    const char* name;
    void (*change)(DesignFromRestOptions&);
    const char* message;
  } cases[] = {
      {"global", [](DesignFromRestOptions& o) { o.global_evaluations = 0; },
       "global_evaluations = 0 is invalid: expected 1 <= global_evaluations <= 100000"},
      {"local", [](DesignFromRestOptions& o) { o.local_evaluations = -1; },
       "local_evaluations = -1 is invalid: expected 0 <= local_evaluations <= 100000"},
      {"candidates", [](DesignFromRestOptions& o) { o.candidates = 0; },
       "candidates = 0 is invalid: expected 1 <= candidates <= 64"},
      {"seconds", [](DesignFromRestOptions& o) { o.max_seconds = 0.0; },
       "max_seconds = 0 is invalid: expected a finite time > 0"},
      {"algorithm", [](DesignFromRestOptions& o) { o.global_algorithm = "LN_SBPLX"; },
       "global_algorithm"},
      {"grid", [](DesignFromRestOptions& o) { o.check.n_x = 0; }, "n_x = 0 is invalid"},
  };
  for (const auto& c : cases) {
    DesignFromRestOptions o;
    c.change(o);
    try {
      DesignFromRest(testing::ExampleRobot(), o);
      ADD_FAILURE() << c.name << ": no exception";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(c.message), std::string::npos)
          << c.name << ": " << e.what();
    }
  }
}

}  // namespace
}  // namespace capsubot
