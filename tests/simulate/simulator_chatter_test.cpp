// Complete chattering (docs/model.md section 14, docs/simulate.md "Chattering"): a sequence of
// impacts on one wall ends at its extrapolated accumulation point. The point against its
// closed form for a constant force, against the impacts simulated one by one, the energy
// budget across it, the fallback where the speeds do not shrink, and long-run mean velocities
// that do not depend on the cut-off or the rule's tolerance.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "capsubot/simulate/simulator.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::InvalidArgumentMessage;
using testing::Near;
using testing::StartAt;

// The extrapolation is exact for a geometric sequence: what is left is the rounding of the
// phases of four impacts, amplified by the extrapolation (about 1/((1-r)(1-r^2)(1-r^3))).
constexpr double kClosedFormTol = 1e-12;
// The bar of docs/model.md section 11 (the budget across a jump closes by construction up to
// rounding, tests/simulate/simulator_energy_test.cpp).
constexpr double kBalanceTol = 1e-10;
// Mean velocities of long runs under chatter settings moved by orders of magnitude: each
// sequence ends within about the rule's tolerance (1e-8 at most here) in phase of its exact
// accumulation point; over a period this moves the mean velocity by far less than this.
constexpr double kSettingsRelTol = 1e-8;
// The work the rule leaves: events per simulated period at most (the cut-off 1e-6 took up to
// 280 for the main job's robot, 1e-8 and below ran into the work bound).
constexpr double kMaxEventsPerPeriod = 300.0;
// The accumulation point from impacts simulated one by one down to the cut-off 1e-6 (there the
// remaining tail, about 1e-5 of the sequence, is extrapolated) against the default rule
// (jump once the estimated error of the phase is below 1e-9): the phase, the capsule's
// velocity there and its displacement since the previous stick agree within a few times that
// (observed 1.9e-9, 5.0e-9, 6.2e-9).
constexpr double kBruteForceTol = 2e-8;

struct Stick {
  double phi, v, y;
};
struct StickLog : SimObserver {
  void OnEvent(const SimEvent& e) override {
    if (e.kind == EventKind::kStick) sticks.push_back({e.after.phi, e.after.v, e.after.y});
  }
  std::vector<Stick> sticks;
};

double Kinetic(double alpha, const SimState& s) {
  return 0.5 * ((1.0 - alpha) * s.v * s.v + alpha * (s.v + s.u) * (s.v + s.u));
}

::testing::AssertionResult Balanced(const Energy& en, double dK) {
  const double rhs = en.friction_loss + en.impact_loss + dK;
  const double scale =
      std::max({std::abs(en.motor_work), en.friction_loss, en.impact_loss, std::abs(dK), 1e-300});
  return Near(en.motor_work, rhs, kBalanceTol * scale);
}

// A constant force F = c pushes the body into the right wall while the capsule slides forward
// all along: the relative acceleration a = (c + alpha T0)/(alpha (1 - alpha)) is constant, so
// the speeds are u0 e^k exactly and the sequence (Budd and Dux 1994) ends after
// T = 2 e u0/(a (1 - e)), with the capsule's velocity and position in closed form
// (docs/model.md section 14): v* = v0 + alpha (1+e) u0/(1-e) - (T0 + c) T/(1 - alpha),
// y* = v0 T - (T0 + c) T^2/(2 (1 - alpha)) + alpha u0 T/(1 - e), and the impacts' loss is
// alpha (1 - alpha) u0^2/2 whatever e.
class ConstantForceChatter : public ::testing::TestWithParam<double> {};

TEST_P(ConstantForceChatter, EndsAtTheClosedFormAccumulationPoint) {
  const double e = GetParam(), c = 0.1, T0 = 1.0, alpha = 0.5, u0 = 0.01, v0 = 1.0;
  SimOptions opt = StartAt(alpha, 1.0, u0, v0, 0.25);
  opt.energy = true;
  StickLog log;
  const SimResult r = Simulate(Forcing::Harmonic(0.0, c, 0.0), Params{T0, e}, opt, &log);
  ASSERT_EQ(r.status, SimStatus::kOk);
  const double a = (c + alpha * T0) / (alpha * (1.0 - alpha));
  const double T = 2.0 * e * u0 / (a * (1.0 - e));
  const double v_star = v0 + alpha * (1.0 + e) * u0 / (1.0 - e) - (T0 + c) * T / (1.0 - alpha);
  const double y_star =
      v0 * T - (T0 + c) * T * T / (2.0 * (1.0 - alpha)) + alpha * u0 * T / (1.0 - e);
  ASSERT_EQ(log.sticks.size(), 1U);
  EXPECT_TRUE(Near(log.sticks[0].phi, T, kClosedFormTol * T));
  EXPECT_TRUE(Near(log.sticks[0].v, v_star, kClosedFormTol));
  EXPECT_TRUE(Near(log.sticks[0].y, y_star, kClosedFormTol * y_star));
  // Five impacts (two estimates from four each agree at once), then the jump.
  EXPECT_EQ(r.impacts_right, 5);
  EXPECT_EQ(r.impacts_left, 0);
  EXPECT_TRUE(
      Near(r.energy.impact_loss, 0.5 * alpha * (1.0 - alpha) * u0 * u0, kClosedFormTol * u0 * u0));
  SimState start;
  start.u = u0;
  start.v = v0;
  EXPECT_TRUE(Balanced(r.energy, Kinetic(alpha, r.final_state) - Kinetic(alpha, start)));
}

INSTANTIATE_TEST_SUITE_P(Simulator, ConstantForceChatter, ::testing::Values(0.3, 0.5, 0.8, 0.95));

TEST(SimulatorChatter, ARunStoppedByItsImpactLimitEndsRightAfterTheImpact) {
  // The sequence of ConstantForceChatter jumps after its fifth impact; a run limited to five
  // right impacts ends right after that impact instead, as max_impacts_right promises.
  const double e = 0.5, u0 = 0.01;
  SimOptions opt = StartAt(0.5, 1.0, u0, 1.0, 0.25);
  opt.max_impacts_right = 5;
  const SimResult r = Simulate(Forcing::Harmonic(0.0, 0.1, 0.0), Params{1.0, e}, opt);
  ASSERT_EQ(r.status, SimStatus::kImpactLimit);
  EXPECT_EQ(r.impacts_right, 5);
  EXPECT_EQ(r.sticks, 0);
  EXPECT_EQ(r.final_state.x, 1.0);
  EXPECT_TRUE(Near(r.final_state.u, -std::pow(e, 5) * u0, kClosedFormTol * u0));
}

TEST(SimulatorChatter, ElasticImpactsThatDoNotShrinkEndPlasticBelowTheCutOff) {
  // e = 1 and the capsule sliding all along: the speeds repeat (r = 1), there is no
  // accumulation point. Below the cut-off the fifth impact is made plastic (the momentum of
  // the remaining ones, v+ = v + alpha u) and the body rests on the wall.
  const double c = 0.1, T0 = 1.0, alpha = 0.5, u0 = 1e-7, v0 = 1.0;
  SimOptions opt = StartAt(alpha, 1.0, u0, v0, 0.25);
  opt.energy = true;
  StickLog log;
  const SimResult r = Simulate(Forcing::Harmonic(0.0, c, 0.0), Params{T0, 1.0}, opt, &log);
  ASSERT_EQ(r.status, SimStatus::kOk);
  EXPECT_EQ(r.impacts_right, 5);
  ASSERT_EQ(log.sticks.size(), 1U);
  EXPECT_TRUE(Near(r.energy.impact_loss, 0.5 * alpha * (1.0 - alpha) * u0 * u0, 1e-6 * u0 * u0));
  // The same with the cut-off below the speeds: the impacts go on (here until the work bound).
  opt.chatter_velocity = 1e-8;
  opt.max_events_per_period = 1000;
  const SimResult on = Simulate(Forcing::Harmonic(0.0, c, 0.0), Params{T0, 1.0}, opt);
  EXPECT_EQ(on.status, SimStatus::kEventLimit);
  EXPECT_EQ(on.sticks, 0);
}

// The main job's robot ("fastest motion from rest": the paper's force at T0 = 1) and its
// variants, and the 3-right/1-left motion of the exact stable optimum at T0 = 1, e = 1
// (docs/attractors.md), from rest in the middle.
struct SettingsCase {
  std::string name;
  double A, c, phi0, alpha, e;
};

constexpr double kMainA = 0.676954732510288, kMainC = 0.323045267489712,
                 kMainPhi0 = -3.089378590956282, kMainAlpha = 0.9428190586419751;

class ChatterSettings : public ::testing::TestWithParam<SettingsCase> {};

SimResult LongRun(const SettingsCase& k, double chatter_velocity, double chatter_tolerance,
                  bool energy = false, SimObserver* observer = nullptr) {
  SimOptions opt = StartAt(k.alpha, 0.5, 0.0, 0.0, 100.0);
  opt.transient = 200.0;
  opt.chatter_velocity = chatter_velocity;
  opt.chatter_tolerance = chatter_tolerance;
  opt.energy = energy;
  return Simulate(Forcing::Harmonic(k.A, k.c, k.phi0), Params{1.0, k.e}, opt, observer);
}

TEST_P(ChatterSettings, MeanVelocityDoesNotDependOnTheChatterSettings) {
  const SettingsCase& k = GetParam();
  const SimResult ref = LongRun(k, SimOptions{}.chatter_velocity, SimOptions{}.chatter_tolerance);
  ASSERT_EQ(ref.status, SimStatus::kOk);
  for (const double velocity : {1e-4, 1e-6, 1e-8, 1e-10}) {
    for (const double tolerance : {1e-9, 1e-10, 1e-11, 1e-12}) {
      const SimResult r = LongRun(k, velocity, tolerance);
      ASSERT_EQ(r.status, SimStatus::kOk) << velocity << " " << tolerance << " " << r.message;
      const double events = static_cast<double>(r.events + r.transient.events) / 300.0;
      EXPECT_LE(events, kMaxEventsPerPeriod) << velocity << " " << tolerance;
      EXPECT_TRUE(testing::RelNear(r.v_mean, ref.v_mean, kSettingsRelTol))
          << velocity << " " << tolerance;
    }
  }
}

TEST_P(ChatterSettings, EnergyBalancesOverTheRecordWithItsJumps) {
  const SettingsCase& k = GetParam();
  SimOptions opt = StartAt(k.alpha, 0.5, 0.0, 0.0, 200.0);
  const SimState s0 =
      Simulate(Forcing::Harmonic(k.A, k.c, k.phi0), Params{1.0, k.e}, opt).final_state;
  const SimResult r =
      LongRun(k, SimOptions{}.chatter_velocity, SimOptions{}.chatter_tolerance, true);
  ASSERT_EQ(r.status, SimStatus::kOk);
  EXPECT_TRUE(Balanced(r.energy, Kinetic(k.alpha, r.final_state) - Kinetic(k.alpha, s0)));
  if (k.e == 1.0) {
    EXPECT_EQ(r.energy.impact_loss, 0.0);  // elastic: no plastic fallback
  }
}

// The main job's robot at four restitutions (its motions chatter), and the 3-right/1-left
// motion of docs/attractors.md (no chattering: the rule must leave it alone).
INSTANTIATE_TEST_SUITE_P(
    Simulator, ChatterSettings,
    ::testing::Values(SettingsCase{"main_e_1", kMainA, kMainC, kMainPhi0, kMainAlpha, 1.0},
                      SettingsCase{"main_e_0p999", kMainA, kMainC, kMainPhi0, kMainAlpha, 0.999},
                      SettingsCase{"main_e_0p9", kMainA, kMainC, kMainPhi0, kMainAlpha, 0.9},
                      SettingsCase{"main_e_0p7", kMainA, kMainC, kMainPhi0, kMainAlpha, 0.7},
                      SettingsCase{"three_right_one_left", 0.34063197373861814, 0.06410131873607934,
                                   -3.1181183398453047, 0.6435592358295166, 1.0}),
    [](const ::testing::TestParamInfo<SettingsCase>& info) { return info.param.name; });

TEST(SimulatorChatter, RatioOfASequenceWhoseShellStopsIsItsClosedForm) {
  // The main job's robot at e = 1: after every right impact the capsule slides and stops
  // before the body returns (pattern (b) of docs/model.md section 14), so the speeds shrink
  // although no impact loses energy, by r^2 = e^2 - alpha (1+e) (2 e - (1+e) q) with
  // q = (F + alpha T0)/(T0 + F), F at the accumulation point. The ratios of the last three
  // speeds before the jump, rho1 and rho2, drift towards r as rho_k - r = g r^k (the force
  // changes along the sequence; rho2 is still 7e-5 off, relative): their limit
  // rho2 (1 - rho1)/(1 - rho2) leaves the next order of that drift (observed 3e-8).
  constexpr double kDriftTol = 1e-6;
  const Forcing f = Forcing::Harmonic(kMainA, kMainC, kMainPhi0);
  struct Log : SimObserver {
    void OnEvent(const SimEvent& e) override {
      if (done) return;
      if (e.kind == EventKind::kImpactRight) {
        first = prev;
        prev = last;
        last = e.u_before;
      } else if (e.kind == EventKind::kStick && e.after.phi > 10.0) {
        stick = e.after.phi;
        done = true;
      }
    }
    double first = NAN, prev = NAN, last = NAN, stick = NAN;
    bool done = false;
  } log;
  const SimResult r = Simulate(f, Params{1.0, 1.0}, StartAt(kMainAlpha, 0.5, 0.0, 0.0, 5.0), &log);
  ASSERT_EQ(r.status, SimStatus::kOk);
  ASSERT_TRUE(log.done);
  const double F = f.F(log.stick), e = 1.0, T0 = 1.0;
  const double q = (F + kMainAlpha * T0) / (T0 + F);
  const double ratio = std::sqrt(e * e - kMainAlpha * (1.0 + e) * (2.0 * e - (1.0 + e) * q));
  EXPECT_LT(ratio, 0.9);
  const double rho1 = log.prev / log.first, rho2 = log.last / log.prev;
  EXPECT_TRUE(testing::RelNear(rho2 * (1.0 - rho1) / (1.0 - rho2), ratio, kDriftTol));
}

TEST(SimulatorChatter, AccumulationPointAgreesWithTheImpactsSimulatedOneByOne) {
  // e = 0.7: every sequence of the main job's robot simulated impact by impact down to the
  // cut-off 1e-6 (the rule's own test never passes: tolerance 1e-300) against the default
  // rule, which jumps dozens of impacts earlier. Same sticks, same states there (the
  // displacement compared stick to stick: the position itself adds up the differences).
  const SettingsCase k{"main_e_0p7", kMainA, kMainC, kMainPhi0, kMainAlpha, 0.7};
  StickLog rule, brute;
  const SimResult a = LongRun(k, 1e-6, 1e-9, false, &rule);
  const SimResult b = LongRun(k, 1e-6, 1e-300, false, &brute);
  ASSERT_EQ(a.status, SimStatus::kOk);
  ASSERT_EQ(b.status, SimStatus::kOk);
  EXPECT_GT(b.events, a.events);
  ASSERT_EQ(rule.sticks.size(), brute.sticks.size());
  ASSERT_GE(rule.sticks.size(), 100U);
  double worst_phi = 0.0, worst_v = 0.0, worst_dy = 0.0;
  for (std::size_t i = 1; i < rule.sticks.size(); ++i) {
    const Stick &a0 = rule.sticks[i - 1], &a1 = rule.sticks[i];
    const Stick &b0 = brute.sticks[i - 1], &b1 = brute.sticks[i];
    worst_phi = std::max(worst_phi, std::abs(a1.phi - b1.phi));
    worst_v = std::max(worst_v, std::abs(a1.v - b1.v));
    worst_dy = std::max(worst_dy, std::abs((a1.y - a0.y) - (b1.y - b0.y)));
  }
  EXPECT_LE(worst_phi, kBruteForceTol);
  EXPECT_LE(worst_v, kBruteForceTol);
  EXPECT_LE(worst_dy, kBruteForceTol);
  EXPECT_TRUE(testing::RelNear(a.v_mean, b.v_mean, kSettingsRelTol));
}

TEST(SimulatorChatter, ToleranceOutsideItsRangeIsRefusedWithItsRule) {
  for (const double bad : {0.0, -1e-9, static_cast<double>(INFINITY), static_cast<double>(NAN)}) {
    SimOptions opt = StartAt(0.5, 0.5, 0.0, 0.0, 1.0);
    opt.chatter_tolerance = bad;
    const std::string msg = InvalidArgumentMessage([&] { opt.Validate(); });
    EXPECT_NE(msg.find("chatter_tolerance = "), std::string::npos) << msg;
    EXPECT_NE(msg.find("is invalid: expected a finite number > 0"), std::string::npos) << msg;
  }
}

}  // namespace
}  // namespace capsubot
