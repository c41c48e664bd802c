// The event-driven simulator (docs/model.md sections 3 and 10) and the validation of the analytic
// orbit against it. The simulator never calls the orbit code; these tests
// compare the two.

#include "capsubot/simulate/simulator.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "capsubot/orbit/validity.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::StartAt;

using testing::Near;
using testing::NearAbsBelowOne;

// Events are located to a few ulp in phase and the closed forms are exact: after a period
// the state agrees with the analytic orbit to rounding (observed ~1e-15); 1e-9 is the
// agreement asked of the analytic orbit.
constexpr double kPeriodTol = 1e-9;
// Grid of impact phases scanned for orbits in each validation case.
constexpr int kScan = 64;

SimOptions PostImpact(const Orbit& o, double periods) {
  SimOptions opt = StartAt(o.alpha, 1.0, -o.e * o.u, o.v_plus, periods);
  return opt;
}

struct Case {
  std::string name;
  bool fourier;
  double A, c, T0, e;
  int min_valid;  // valid orbits the scan must contain (found with a scan of `capsubot solve`)
};

Forcing Force(const Case& k, double phi0) {
  // The Fourier case adds a second harmonic of 10% (cosine) to the paper's sine.
  return k.fourier ? Forcing::Fourier(k.c, {0.0, 0.1 * k.A}, {k.A, 0.0}, phi0)
                   : Forcing::Harmonic(k.A, k.c, phi0);
}

Params CaseParams(const Case& k) {
  Params p;
  p.T0 = k.T0;
  p.e = k.e;
  return p;
}

// The orbits of a kScan-phase scan whose violations are exactly `want_violations`.
std::vector<Solution> ScanOrbits(const Case& k, unsigned want_violations) {
  std::vector<Solution> out;
  for (int i = 0; i < kScan; ++i) {
    const Solution s = Solve(Force(k, -M_PI + kTau * i / kScan), CaseParams(k));
    if (s.orbit.ok() && s.validity.violations == want_violations) out.push_back(s);
  }
  return out;
}

class ValidOrbitGrid : public ::testing::TestWithParam<Case> {
 protected:
  std::vector<Solution> Scan(unsigned want_violations) const {
    return ScanOrbits(GetParam(), want_violations);
  }
  Params P() const { return CaseParams(GetParam()); }
};

TEST_P(ValidOrbitGrid, ReturnsToPostImpactStateAfterOnePeriodWithOneImpactAndOneStop) {
  const std::vector<Solution> valid = Scan(0);
  ASSERT_GE(static_cast<int>(valid.size()), GetParam().min_valid);
  for (const Solution& s : valid) {
    const Orbit& o = s.orbit;
    SCOPED_TRACE("phi0 = " + std::to_string(o.forcing.phi0()));
    const SimResult r = Simulate(o.forcing, P(), PostImpact(o, 1.0));
    EXPECT_EQ(r.status, SimStatus::kOk);
    EXPECT_EQ(r.impacts_right, 1);
    EXPECT_EQ(r.stops, 1);
    EXPECT_EQ(r.impacts_left, 0);
    EXPECT_EQ(r.breakaways, 0);
    EXPECT_EQ(r.sticks, 0);
    EXPECT_TRUE(Near(r.final_state.phi, kTau, kPeriodTol));
    EXPECT_TRUE(Near(r.final_state.x, 1.0, kPeriodTol));
    EXPECT_TRUE(NearAbsBelowOne(r.final_state.u, -o.e * o.u, kPeriodTol));
    EXPECT_TRUE(NearAbsBelowOne(r.final_state.v, o.v_plus, kPeriodTol));
    EXPECT_TRUE(NearAbsBelowOne(r.displacement, o.I, kPeriodTol));
  }
}

TEST_P(ValidOrbitGrid, SimulatedMeanVelocityEqualsAnalytic) {
  // Three periods: long enough to average, short enough that rounding (1e-16) amplified by an
  // unstable orbit (multipliers up to ~10) stays far below the tolerance.
  for (const Solution& s : Scan(0)) {
    const Orbit& o = s.orbit;
    SCOPED_TRACE("phi0 = " + std::to_string(o.forcing.phi0()));
    const SimResult r = Simulate(o.forcing, P(), PostImpact(o, 3.0));
    EXPECT_EQ(r.impacts_right, 3);
    EXPECT_TRUE(NearAbsBelowOne(r.v_mean, o.v_mean, kPeriodTol));
  }
}

// Parameter sets chosen with a scan of `capsubot solve` over phi0 (with this file's
// scan, 64 phases): each holds valid orbits; T0 from 0.01 to 0.3, e from 0 to 1.
INSTANTIATE_TEST_SUITE_P(
    Simulator, ValidOrbitGrid,
    ::testing::Values(Case{"harmonic_T0_0p1_e_0p5", false, 0.05, 0.02, 0.1, 0.5, 10},
                      Case{"harmonic_T0_0p1_e_1", false, 0.05, 0.02, 0.1, 1.0, 10},
                      Case{"harmonic_T0_0p1_e_0p2", false, 0.05, 0.01, 0.1, 0.2, 5},
                      Case{"harmonic_small_T0_0p02", false, 0.01, 0.004, 0.02, 0.5, 10},
                      Case{"harmonic_T0_0p01_e_0", false, 0.005, 0.001, 0.01, 0.0, 2},
                      Case{"harmonic_large_T0_0p3", false, 0.12, 0.05, 0.3, 0.8, 10},
                      Case{"fourier_T0_0p1_e_0p5", true, 0.05, 0.02, 0.1, 0.5, 10},
                      Case{"fourier_T0_0p02_e_0p2", true, 0.01, 0.004, 0.02, 0.2, 5}),
    [](const ::testing::TestParamInfo<Case>& info) { return info.param.name; });

// Orbits that the validity check rejects for one wall condition alone must show that wall in
// simulation. Each parameter set holds at least min_left orbits invalid by the left-wall
// condition alone and min_right by the right-wall condition alone (counted with a 64-phase
// scan of `capsubot solve`; about half the count found), so no instantiation checks nothing.
struct WallCase {
  Case k;
  int min_left, min_right;
};

class WallViolationGrid : public ::testing::TestWithParam<WallCase> {};

TEST_P(WallViolationGrid, OrbitInvalidByLeftWallHitsTheLeftWall) {
  const Case& k = GetParam().k;
  const std::vector<Solution> left =
      ScanOrbits(k, 1U << static_cast<unsigned>(Condition::kLeftWall));
  ASSERT_GE(static_cast<int>(left.size()), GetParam().min_left);
  for (const Solution& s : left) {
    SCOPED_TRACE("phi0 = " + std::to_string(s.orbit.forcing.phi0()));
    const SimResult r = Simulate(s.orbit.forcing, CaseParams(k), PostImpact(s.orbit, 1.0));
    EXPECT_GE(r.impacts_left, 1);
  }
}

TEST_P(WallViolationGrid, OrbitInvalidByRightWallHitsTheRightWallEarly) {
  const Case& k = GetParam().k;
  const std::vector<Solution> right =
      ScanOrbits(k, 1U << static_cast<unsigned>(Condition::kRightWall));
  ASSERT_GE(static_cast<int>(right.size()), GetParam().min_right);
  for (const Solution& s : right) {
    SCOPED_TRACE("phi0 = " + std::to_string(s.orbit.forcing.phi0()));
    SimOptions opt = PostImpact(s.orbit, 1.0);
    opt.max_impacts_right = 1;
    const SimResult r = Simulate(s.orbit.forcing, CaseParams(k), opt);
    EXPECT_EQ(r.status, SimStatus::kImpactLimit);
    EXPECT_LT(r.final_state.phi, kTau - 1e-6);
  }
}

// Found counts (left, right): (2, 13), (1, 16), (6, 13), (8, 15), (15, 7), (1, 7), (3, 7),
// (5, 14), (1, 6).
INSTANTIATE_TEST_SUITE_P(
    Simulator, WallViolationGrid,
    ::testing::Values(WallCase{{"harmonic_T0_0p1_e_0p2", false, 0.05, 0.01, 0.1, 0.2, 0}, 1, 6},
                      WallCase{{"harmonic_T0_0p1_e_0p5", false, 0.07, 0.01, 0.1, 0.5, 0}, 1, 8},
                      WallCase{{"harmonic_T0_0p3_e_0p5", false, 0.15, 0.03, 0.3, 0.5, 0}, 3, 6},
                      WallCase{{"harmonic_T0_0p3_e_0p2", false, 0.21, 0.03, 0.3, 0.2, 0}, 4, 7},
                      WallCase{{"harmonic_T0_0p3_e_1", false, 0.21, 0.06, 0.3, 1.0, 0}, 7, 3},
                      WallCase{{"harmonic_T0_0p02_e_0p2", false, 0.014, 0.004, 0.02, 0.2, 0}, 1, 3},
                      WallCase{{"fourier_T0_0p1_e_0p5", true, 0.07, 0.02, 0.1, 0.5, 0}, 1, 3},
                      WallCase{{"fourier_T0_0p3_e_0p8", true, 0.15, 0.03, 0.3, 0.8, 0}, 2, 7},
                      WallCase{{"fourier_T0_0p02_e_0p2", true, 0.014, 0.004, 0.02, 0.2, 0}, 1, 3}),
    [](const ::testing::TestParamInfo<WallCase>& info) { return info.param.k.name; });

// A free rest phase x = x0 + u0 s + Phi(s)/alpha (docs/model.md section 3) whose maximum lies
// 1e-10 below or above the right wall: the grazing contact must be seen exactly when it
// happens. The maximum is located independently by a dense scan plus golden-section search.
TEST(Simulator, GrazingContactIsNeitherMissedNorInvented) {
  // F = 0.02 - 0.05 sin(s): Pi < 0 after a while, so x' = u0 + Pi/alpha turns negative.
  const Forcing f = Forcing::Harmonic(0.05, 0.02, M_PI);
  Params p;
  p.T0 = 0.1;
  const double alpha = 0.3, u0 = 0.05;
  const auto x = [&](double s) { return u0 * s + f.Phi(s) / alpha; };  // x - x0
  // Dense scan for the first maximum of x - x0 (x' = u0 + Pi/alpha turns negative).
  double best = 0.0, s_best = 0.0;
  for (int i = 1; i <= 20000; ++i) {
    const double s = kTau * i / 20000;
    if (u0 + f.Pi(s) / alpha < 0.0) break;
    if (x(s) > best) {
      best = x(s);
      s_best = s;
    }
  }
  double lo = s_best - kTau / 20000, hi = s_best + kTau / 20000;
  for (int it = 0; it < 200; ++it) {  // golden section on a unimodal bracket
    const double m1 = lo + 0.382 * (hi - lo), m2 = lo + 0.618 * (hi - lo);
    if (x(m1) < x(m2)) {
      lo = m1;
    } else {
      hi = m2;
    }
  }
  const double peak = x(0.5 * (lo + hi));
  ASSERT_GT(peak, 0.01);
  for (const double gap : {1e-10, -1e-10}) {
    SimOptions opt;
    opt.alpha = alpha;
    opt.x0 = 1.0 - peak - gap;  // maximum at 1 - gap
    opt.u0 = u0;
    opt.v0 = 0.0;
    opt.periods = 0.5 * (lo + hi) / kTau + 1e-3;  // just past the maximum
    opt.max_impacts_right = 1;
    const SimResult r = Simulate(f, p, opt);
    EXPECT_EQ(r.impacts_right, gap > 0.0 ? 0 : 1) << "gap " << gap;
    EXPECT_EQ(r.stops + r.breakaways + r.impacts_left, 0);
  }
}

// Chattering: the inner body arrives slowly at the right wall while the force pushes it there
// (e = 0.5): impacts at geometrically shrinking velocity. It must end with the body resting
// on the wall (a stick event), and the body must leave the wall later when the force turns.
// Parameters found by trying states near the wall with `capsubot simulate --events`.
TEST(Simulator, ChatteringEndsRestingOnTheWallAndReleases) {
  const Forcing f = Forcing::Harmonic(0.05, 0.02, 0.0);
  Params p;
  p.T0 = 0.1;
  p.e = 0.5;
  SimOptions opt = StartAt(0.3, 0.999, 0.001, 0.0, 1.0);
  struct Log : SimObserver {
    std::vector<SimEvent> events;
    void OnEvent(const SimEvent& e) override { events.push_back(e); }
  } log;
  const SimResult r = Simulate(f, p, opt, &log);
  EXPECT_EQ(r.status, SimStatus::kOk);
  EXPECT_EQ(r.sticks, 1);
  EXPECT_EQ(r.releases, 1);
  EXPECT_GE(r.impacts_right, 3);
  EXPECT_LT(r.events, 100);  // bounded by the chattering cut-off, not by the work bound
  bool stuck_seen = false;
  for (const SimEvent& e : log.events) {
    if (e.kind == EventKind::kStick) {
      stuck_seen = true;
      EXPECT_EQ(e.after.x, 1.0);
      EXPECT_EQ(e.after.u, 0.0);
      EXPECT_EQ(e.after.mode, SimMode::kOnRightWall);
    }
    if (e.kind == EventKind::kRelease) {
      EXPECT_TRUE(stuck_seen);
      // The body leaves the right wall at rest when F turns negative (contact force -F).
      EXPECT_TRUE(Near(f.F(e.after.phi), 0.0, 1e-12));
    }
  }
}

// With e = 1 there is no decay, yet slow impacts with the force pushing into the wall must
// not hang: the cut-off makes the body rest on the wall.
TEST(Simulator, SlowElasticImpactsIntoThePushingWallDoNotHang) {
  const Forcing f = Forcing::Harmonic(0.05, 0.02, 0.0);
  Params p;
  p.T0 = 0.1;
  p.e = 1.0;
  SimOptions opt;
  opt.alpha = 0.3;
  opt.x0 = 1.0;
  opt.u0 = 1e-8;  // below chatter_velocity
  opt.v0 = 0.0;
  opt.periods = 1.0;
  const SimResult r = Simulate(f, p, opt);
  EXPECT_EQ(r.status, SimStatus::kOk);
  EXPECT_EQ(r.sticks, 1);
}

TEST(Simulator, WorkBoundStopsWithAStatusInsteadOfHanging) {
  // A large velocity between the walls with e = 1: many impacts per period.
  const Forcing f = Forcing::Harmonic(0.05, 0.02, 0.0);
  Params p;
  p.T0 = 0.1;
  SimOptions opt = StartAt(0.3, 0.5, 50.0, 0.0, 1.0);
  opt.max_events_per_period = 10;
  const SimResult r = Simulate(f, p, opt);
  EXPECT_EQ(r.status, SimStatus::kEventLimit);
  EXPECT_NE(r.message.find("work bound"), std::string::npos) << r.message;
}

TEST(Simulator, EventLogIsOrderedAndMatchesTheCounters) {
  Params p;
  p.T0 = 0.1;
  p.e = 0.5;
  const Orbit o = ComputeOrbit(Forcing::Harmonic(0.05, 0.02, -2.3), p);  // left-wall violation
  ASSERT_TRUE(o.ok());
  struct Log : SimObserver {
    std::vector<SimEvent> events;
    std::vector<SimState> samples;
    void OnEvent(const SimEvent& e) override { events.push_back(e); }
    void OnSample(const SimState& s) override { samples.push_back(s); }
  } log;
  SimOptions opt = PostImpact(o, 5.0);
  opt.sample_step = kTau / 50;
  const SimResult r = Simulate(o.forcing, p, opt, &log);
  ASSERT_EQ(static_cast<std::int64_t>(log.events.size()), r.events);
  std::int64_t left = 0, right = 0, stops = 0;
  for (std::size_t i = 0; i < log.events.size(); ++i) {
    const SimEvent& e = log.events[i];
    if (i > 0) {
      EXPECT_GE(e.after.phi, log.events[i - 1].after.phi);
    }
    left += e.kind == EventKind::kImpactLeft;
    right += e.kind == EventKind::kImpactRight;
    stops += e.kind == EventKind::kStop;
    EXPECT_GE(e.after.x, 0.0);
    EXPECT_LE(e.after.x, 1.0);
  }
  EXPECT_EQ(left, r.impacts_left);
  EXPECT_EQ(right, r.impacts_right);
  EXPECT_EQ(stops, r.stops);
  EXPECT_GE(left, 1);
  // Samples: the grid 0, tau/50, ..., 5 tau, all inside the walls.
  ASSERT_EQ(log.samples.size(), 251U);
  for (std::size_t i = 0; i < log.samples.size(); ++i) {
    EXPECT_TRUE(Near(log.samples[i].phi, kTau / 50 * static_cast<double>(i), 1e-9));
    EXPECT_GE(log.samples[i].x, -1e-12);
    EXPECT_LE(log.samples[i].x, 1.0 + 1e-12);
  }
}

// A stable orbit (spectral radius ~0.16, see stability_test) stays on itself for many periods.
TEST(Simulator, StableOrbitRepeatsOverAThousandPeriods) {
  Params p;
  p.T0 = 0.1;
  p.e = 0.5;
  const Orbit o = ComputeOrbit(Forcing::Harmonic(0.05, 0.02, -2.842), p);
  ASSERT_TRUE(o.ok());
  const SimResult r = Simulate(o.forcing, p, PostImpact(o, 1000.0));
  EXPECT_EQ(r.impacts_right, 1000);
  EXPECT_EQ(r.stops, 1000);
  EXPECT_TRUE(NearAbsBelowOne(r.final_state.v, o.v_plus, kPeriodTol));
  EXPECT_TRUE(NearAbsBelowOne(r.v_mean, o.v_mean, kPeriodTol));
}

// Break-away both ways: with A > T0 the motor alone moves the capsule. A heavy inner body
// (alpha = 0.9) with u0 = -A/alpha oscillates about the middle; found with
// `capsubot simulate --events` (3 break-aways in 2 periods, backward first).
TEST(Simulator, StrongForceBreaksAwayAndSlidesBothWays) {
  const Forcing f = Forcing::Harmonic(0.15, 0.0, 0.0);  // |F| up to 0.15 > T0 = 0.1
  Params p;
  p.T0 = 0.1;
  SimOptions opt = StartAt(0.9, 0.5, -0.15 / 0.9, 0.0, 2.0);
  struct Log : SimObserver {
    bool forward = false, backward = false;
    double worst_level = 0.0;  // |F| - T0 at the break-aways: zero
    const Forcing* f = nullptr;
    void OnEvent(const SimEvent& e) override {
      if (e.kind != EventKind::kBreakaway) return;
      forward |= e.after.mode == SimMode::kSlideForward;
      backward |= e.after.mode == SimMode::kSlideBackward;
      worst_level = std::max(worst_level, std::abs(std::abs(f->F(e.after.phi)) - 0.1));
    }
  } log;
  log.f = &f;
  const SimResult r = Simulate(f, p, opt, &log);
  EXPECT_GE(r.breakaways, 3);
  EXPECT_GE(r.stops, 2);
  EXPECT_TRUE(log.forward);
  EXPECT_TRUE(log.backward);
  EXPECT_LT(log.worst_level, 1e-12);
}

// Momentum: between impacts v + alpha u changes only by friction, and at an impact it is
// conserved (docs/model.md section 3). Checked at every impact of a run with both walls.
TEST(Simulator, ImpactsConserveMomentum) {
  Params p;
  p.T0 = 0.1;
  p.e = 0.5;
  const Orbit o = ComputeOrbit(Forcing::Harmonic(0.05, 0.02, -2.3), p);
  struct Log : SimObserver {
    double alpha = 0.0, worst = 0.0;
    void OnEvent(const SimEvent& e) override {
      if (e.kind != EventKind::kImpactLeft && e.kind != EventKind::kImpactRight) return;
      const double before = e.v_before + alpha * e.u_before, after = e.after.v + alpha * e.after.u;
      worst = std::max(worst, std::abs(after - before));
    }
  } log;
  log.alpha = o.alpha;
  Simulate(o.forcing, p, PostImpact(o, 5.0), &log);
  EXPECT_LT(log.worst, 1e-15);
}

// No missed event, as an invariant: if an impact, a stop or a break-away were missed, the
// closed-form motion would carry on past it and a dense sample would show x outside the walls,
// a capsule velocity against its mode, or rest under a force above friction. Random initial
// states (fixed seed), both force families, e = 0.5 and 1, forces above and below T0.
TEST(Simulator, DenseSamplesOfRandomRunsRespectWallsModesAndFriction) {
  struct Checker : SimObserver {
    const Forcing* f = nullptr;
    double T0 = 0.0;
    int bad = 0;
    std::string first;
    void OnSample(const SimState& s) override {
      constexpr double kTol = 1e-12;  // rounding of closed forms at the walls
      bool ok = s.x >= -kTol && s.x <= 1.0 + kTol;
      if (s.mode == SimMode::kSlideForward) ok = ok && s.v >= -kTol;
      if (s.mode == SimMode::kSlideBackward) ok = ok && s.v <= kTol;
      if (s.mode == SimMode::kRest) ok = ok && s.v == 0.0 && std::abs(f->F(s.phi)) <= T0 + kTol;
      if (!ok && bad++ == 0) {
        first = "phi " + std::to_string(s.phi) + " x " + std::to_string(s.x) + " v " +
                std::to_string(s.v) + " mode " + SimModeName(s.mode);
      }
    }
  };
  std::uint64_t seed = 12345;
  const auto uniform = [&seed](double lo, double hi) {  // a small LCG: reproducible anywhere
    seed = seed * 6364136223846793005ULL + 1442695040888963407ULL;
    return lo + (hi - lo) * static_cast<double>(seed >> 11) / 9007199254740992.0;
  };
  int runs = 0;
  for (int i = 0; i < 120; ++i) {
    const double A = uniform(0.0, 0.2), c = uniform(0.0, 0.05), phi0 = uniform(-M_PI, M_PI);
    const Forcing f = i % 2 == 0 ? Forcing::Harmonic(A, c, phi0)
                                 : Forcing::Fourier(c, {0.0, 0.2 * A}, {A, 0.0}, phi0);
    Params p;
    p.T0 = 0.1;
    p.e = i % 3 == 0 ? 1.0 : 0.5;
    SimOptions opt = StartAt(uniform(0.05, 0.95), uniform(0.0, 1.0), uniform(-0.3, 0.3),
                             uniform(-0.1, 0.1), 3.0);
    opt.sample_step = kTau / 400;
    Checker check;
    check.f = &f;
    check.T0 = p.T0;
    const SimResult r = Simulate(f, p, opt, &check);
    EXPECT_EQ(check.bad, 0) << "run " << i << ": " << check.first;
    runs += r.status == SimStatus::kOk;
  }
  EXPECT_EQ(runs, 120);
}

// A force that only TOUCHES the friction bound (A + c = T0, the paper's boundary, where the
// P2/P3 optima sit) never moves the resting capsule: at the touch dF is rounding noise of
// either sign, which must not be taken for a break-away (before the fix: a fake break-away,
// an immediate stop, again and again until the stall guard gave up with event_limit).
struct TouchCase {
  std::string name;
  bool fourier;
  double T0;  // force scale: A = 0.7 T0, c = 0.3 T0 (second harmonic for Fourier)
};

class ForceTouchingFriction : public ::testing::TestWithParam<TouchCase> {};

// Few events: at T0 = 0.01 the body stays between the walls (no event at all); at T0 = 1 it
// hits the walls and chatters (e = 0.5), 50-65 events in 1.5 periods (counted with the fixed
// simulator); a stall is stopped only after 1000 events without progress.
constexpr std::int64_t kFewEvents = 200;

TEST_P(ForceTouchingFriction, RestingCapsuleDoesNotBreakAwayAndTheRunEndsOk) {
  const TouchCase& k = GetParam();
  constexpr int kPhases = 48;  // impact phases over the circle: the touch at every position
  for (int i = 0; i < kPhases; ++i) {
    const double phi0 = -M_PI + kTau * i / kPhases;
    const Forcing f = k.fourier
                          ? Forcing::Fourier(0.3 * k.T0, {0.0, 0.1 * k.T0}, {0.7 * k.T0, 0.0}, phi0)
                          : Forcing::Harmonic(0.7 * k.T0, 0.3 * k.T0, phi0);
    Params p;
    // The Fourier force's maximum is not a round number: T0 is its exact max |F|.
    p.T0 = k.fourier ? f.MaxAbs() : k.T0;
    p.e = 0.5;
    SimOptions opt = StartAt(0.5, 0.5, 0.0, 0.0, 1.5);
    const SimResult r = Simulate(f, p, opt);
    SCOPED_TRACE("phi0 = " + std::to_string(phi0));
    EXPECT_EQ(r.status, SimStatus::kOk) << r.message;
    EXPECT_EQ(r.breakaways, 0);  // |F| <= T0 everywhere: no real break-away exists
    EXPECT_LT(r.events, kFewEvents);
    if (k.T0 < 0.1) {
      EXPECT_EQ(r.events, 0);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Simulator, ForceTouchingFriction,
                         ::testing::Values(TouchCase{"harmonic_T0_0p01", false, 0.01},
                                           TouchCase{"harmonic_T0_1", false, 1.0},
                                           TouchCase{"fourier_T0_0p01", true, 0.01},
                                           TouchCase{"fourier_T0_1", true, 1.0}),
                         [](const ::testing::TestParamInfo<TouchCase>& info) {
                           return info.param.name;
                         });

// A body resting on a wall whose contact force only touches zero (c = A: F = A (sin + 1) >= 0
// pushes into the right wall; the mirror force into the left one) stays on the wall: a touch
// is no release (before the fix: a fake release, then zero-velocity impacts at the same phase
// until the stall guard gave up with event_limit).
TEST(Simulator, ContactForceTouchingZeroKeepsTheBodyOnTheWall) {
  constexpr int kPhases = 32;
  for (const double scale : {0.01, 0.5}) {
    for (const double dir : {1.0, -1.0}) {
      for (int i = 0; i < kPhases; ++i) {
        const double phi0 = -M_PI + kTau * i / kPhases;
        // dir = -1: -scale (sin(phi + phi0) + 1), pushing into the left wall.
        const Forcing f = Forcing::Harmonic(scale, dir * scale, dir > 0.0 ? phi0 : phi0 + M_PI);
        Params p;
        p.T0 = 2.0 * scale;  // the capsule rests: |F| <= 2 scale
        p.e = 0.5;
        SimOptions opt = StartAt(0.5, dir > 0.0 ? 1.0 : 0.0, 0.0, 0.0, 2.0);
        const SimResult r = Simulate(f, p, opt);
        SCOPED_TRACE("scale " + std::to_string(scale) + " dir " + std::to_string(dir) + " phi0 " +
                     std::to_string(phi0));
        EXPECT_EQ(r.status, SimStatus::kOk) << r.message;
        EXPECT_EQ(r.sticks, 1);  // at the start, pushed into the wall
        EXPECT_EQ(r.releases, 0);
        EXPECT_EQ(r.events, 1);
        EXPECT_EQ(r.final_state.mode, dir > 0.0 ? SimMode::kOnRightWall : SimMode::kOnLeftWall);
      }
    }
  }
}

// The same touch reached from inside: the body comes to the right wall (A = c = 0.5, T0 = 1,
// a grazing start), chatters (e = 1: by the cut-off), rests on the wall, and the contact
// force F = 0.5 (sin + 1) touches zero at phase 3 pi / 2 without changing sign.
TEST(Simulator, BodyComingToRestOnTheWallStaysThroughATouchOfTheContactForce) {
  const Forcing f = Forcing::Harmonic(0.5, 0.5, 0.0);
  Params p;
  SimOptions opt = StartAt(0.5, 0.5, 0.0, 0.0, 3.0);
  const SimResult r = Simulate(f, p, opt);
  EXPECT_EQ(r.status, SimStatus::kOk) << r.message;
  EXPECT_EQ(r.releases, 0);
  EXPECT_EQ(r.sticks, 1);
  EXPECT_LT(r.events, 200);  // the chattering run-in, not the work bound
  EXPECT_EQ(r.final_state.mode, SimMode::kOnRightWall);
}

// max_events_per_period * ceil(periods) is beyond int64 for valid options: the bound
// saturates (before the fix the product overflowed, here wrapping to 0: an immediate
// event_limit at phase 0).
TEST(Simulator, HugeWorkBoundSaturatesInsteadOfOverflowing) {
  const Forcing f = Forcing::Harmonic(0.05, 0.02, 0.0);
  Params p;
  p.T0 = 0.1;
  SimOptions opt;
  opt.alpha = 0.3;
  opt.x0 = 0.5;
  opt.u0 = 0.3;  // reaches the right wall within a period
  opt.v0 = 0.0;
  opt.max_impacts_right = 1;
  for (const double periods : {4.0, 1e8}) {
    for (const std::int64_t per_period : {std::int64_t{1} << 62, std::int64_t{1000000000000000},
                                          std::numeric_limits<std::int64_t>::max()}) {
      opt.periods = periods;
      opt.max_events_per_period = per_period;
      const SimResult r = Simulate(f, p, opt);
      EXPECT_EQ(r.status, SimStatus::kImpactLimit)
          << "periods " << periods << " per period " << per_period << ": " << r.message;
      EXPECT_EQ(r.impacts_right, 1);
    }
  }
}

TEST(SimOptions, BadInputsAreRejectedWithTheirRule) {
  const auto message = [](SimOptions o) {
    try {
      o.Validate();
    } catch (const std::invalid_argument& e) {
      return std::string(e.what());
    }
    return std::string("no exception");
  };
  SimOptions ok;
  ok.alpha = 0.3;
  ok.x0 = 0.5;
  ok.u0 = 0.0;
  ok.v0 = 0.0;
  EXPECT_EQ(message(ok), "no exception");
  SimOptions o = ok;
  o.alpha = 1.0;
  EXPECT_EQ(message(o), "mass ratio alpha = 1 is invalid: expected 0 < alpha < 1");
  o = ok;
  o.x0 = 1.5;
  EXPECT_EQ(message(o), "initial position x0 = 1.5 is invalid: expected 0 <= x0 <= 1");
  o = ok;
  o.u0 = NAN;
  EXPECT_EQ(message(o), "initial relative velocity u0 = nan is invalid: expected a finite number");
  o = ok;
  o.v0 = INFINITY;
  EXPECT_EQ(message(o), "initial capsule velocity v0 = inf is invalid: expected a finite number");
  o = ok;
  o.periods = 0.0;
  EXPECT_EQ(message(o), "periods = 0 is invalid: expected 0 < periods <= 1e8");
  o = ok;
  o.max_impacts_right = -1;
  EXPECT_EQ(message(o), "max_impacts_right = -1 is invalid: expected >= 0 (0: no limit)");
  o = ok;
  o.chatter_velocity = 0.0;
  EXPECT_EQ(message(o), "chatter_velocity = 0 is invalid: expected a finite number > 0");
  o = ok;
  o.max_events_per_period = 5;
  EXPECT_EQ(message(o), "max_events_per_period = 5 is invalid: expected >= 10");
  o = ok;
  o.sample_step = -1.0;
  EXPECT_EQ(message(o),
            "sample_step = -1 is invalid: expected a finite number >= 0 (0: no samples)");
  o = ok;
  o.y0 = NAN;
  EXPECT_EQ(message(o), "initial capsule position y0 = nan is invalid: expected a finite number");
}

TEST(Simulator, SimulateValidatesParams) {
  SimOptions ok;
  ok.alpha = 0.3;
  ok.x0 = 0.5;
  ok.u0 = 0.0;
  ok.v0 = 0.0;
  Params p;
  p.e = 2.0;
  EXPECT_THROW(Simulate(Forcing::Harmonic(0.05, 0.02, 0.0), p, ok), std::invalid_argument);
}

TEST(Simulator, NonFiniteStateEndsTheRunWithItsStatus) {
  // y = y0 + v0 s overflows within the first slide for v0 near the largest double: the run
  // must not report ok (or any count of events) with inf in the state.
  int checked = 0;
  for (double v0 : {1.7e308, -1e308}) {
    const SimResult r =
        Simulate(Forcing::Harmonic(0.5, 0.5, 0.0), Params{}, StartAt(0.5, 0.5, 0.0, v0, 10.0));
    EXPECT_EQ(r.status, SimStatus::kNonFinite) << v0;
    EXPECT_STREQ(SimStatusName(r.status), "non_finite");
    EXPECT_NE(r.message.find("the state is not finite"), std::string::npos) << r.message;
    ++checked;
  }
  EXPECT_EQ(checked, 2);
}

TEST(Simulator, HugeRelativeVelocityBouncesUntilTheWorkBound) {
  // u0 near the largest double with e = 1: the body crosses the gap in about 3e-309 of phase
  // and bounces between the walls without losing speed; every impact is located (no overflow
  // on the way) until the work bound ends the run with a finite state.
  const Params elastic{1.0, 1.0};
  const SimOptions opt = StartAt(0.5, 0.5, 1.7e308, 0.0, 10.0);
  const SimResult r = Simulate(Forcing::Harmonic(0.5, 0.5, 0.0), elastic, opt);
  EXPECT_EQ(r.status, SimStatus::kEventLimit);
  EXPECT_EQ(r.events, opt.max_events_per_period * 10);
  EXPECT_EQ(r.impacts_right + r.impacts_left, r.events);
  EXPECT_EQ(r.impacts_right, r.impacts_left);
  EXPECT_TRUE(std::isfinite(r.final_state.x) && std::isfinite(r.final_state.u) &&
              std::isfinite(r.final_state.v) && std::isfinite(r.final_state.y));
  EXPECT_LT(r.final_state.phi, 1e-300);
}

TEST(Simulator, ANearTouchOfAContactLevelInsideAPieceHidesNoImpact) {
  // F = cos phi + c with c = 0.5 + eps nearly touches the contact level -alpha T0 = -0.5 at
  // phi = pi, inside its only piece (no crossing). The sign of F + alpha T0 that decides
  // whether a body leaving the wall comes back must come from the whole piece, not from that
  // point: otherwise every return to the right wall while sliding is missed and the body
  // passes through it. Every event and every sample stays between the walls, and the run
  // has the events of a force that keeps clear of the level (eps = 1e-9).
  std::int64_t events_clear = -1;
  int checked = 0;
  for (const double eps : {1e-9, 1e-13, 1e-16}) {
    struct Log : SimObserver {
      void OnEvent(const SimEvent& e) override { x.push_back(e.after.x); }
      void OnSample(const SimState& st) override { x.push_back(st.x); }
      std::vector<double> x;
    } log;
    SimOptions opt = StartAt(0.5, 0.5, 0.3, 0.0, 3.0);
    opt.sample_step = 1e-3;
    const SimResult r =
        Simulate(Forcing::Harmonic(1.0, 0.5 + eps, M_PI / 2), Params{1.0, 0.5}, opt, &log);
    ASSERT_EQ(r.status, SimStatus::kOk) << eps;
    ASSERT_GT(log.x.size(), 18000u);
    for (const double x : log.x) {
      ASSERT_GE(x, -1e-12) << eps;
      ASSERT_LE(x, 1.0 + 1e-12) << eps;
    }
    if (events_clear < 0) events_clear = r.events;
    EXPECT_EQ(r.events, events_clear) << eps;
    // 36 right impacts (chattering sequences ended at their accumulation point); a missed
    // return to the wall would leave a handful.
    EXPECT_GT(r.impacts_right, 30) << eps;
    ++checked;
  }
  EXPECT_EQ(checked, 3);
}

TEST(Simulator, EventsDoNotDependOnWhereTheRunEnds) {
  // The events of a run of 32 periods are the first events of a run of 40, to the last bit:
  // the search for an event never depends on how much of the run is left. The chattering
  // motion (T0 = 1.3: a dozen impacts and stops a period, ending on the wall) amplifies a
  // last-bit difference in an event to 1e-10 within a period, so it would show one.
  const Forcing f =
      Forcing::Harmonic(0.34063197373861814, 0.06410131873607934, -3.1181183398453047);
  int compared = 0;
  for (const double T0 : {1.0, 1.3}) {
    struct Log : SimObserver {
      void OnEvent(const SimEvent& e) override { events.push_back(e); }
      std::vector<SimEvent> events;
    } shorter, longer;
    SimOptions opt = StartAt(0.6435592358295166, 0.5, 0.0, 0.0, 32.0);
    Simulate(f, Params{T0, 1.0}, opt, &shorter);
    opt.periods = 40.0;
    Simulate(f, Params{T0, 1.0}, opt, &longer);
    ASSERT_GT(shorter.events.size(), 200u);
    ASSERT_GT(longer.events.size(), shorter.events.size());
    for (std::size_t i = 0; i < shorter.events.size(); ++i, ++compared) {
      const SimEvent &a = shorter.events[i], &b = longer.events[i];
      ASSERT_EQ(a.kind, b.kind) << i;
      ASSERT_EQ(a.after.phi, b.after.phi) << i;
      ASSERT_EQ(a.after.x, b.after.x) << i;
      ASSERT_EQ(a.after.u, b.after.u) << i;
      ASSERT_EQ(a.after.v, b.after.v) << i;
      ASSERT_EQ(a.after.y, b.after.y) << i;
    }
  }
  EXPECT_GT(compared, 600);
}

TEST(Simulator, NamesAreStable) {
  EXPECT_STREQ(EventKindName(EventKind::kImpactRight), "impact_right");
  EXPECT_STREQ(EventKindName(EventKind::kImpactLeft), "impact_left");
  EXPECT_STREQ(EventKindName(EventKind::kStop), "stop");
  EXPECT_STREQ(EventKindName(EventKind::kBreakaway), "breakaway");
  EXPECT_STREQ(EventKindName(EventKind::kStick), "stick");
  EXPECT_STREQ(EventKindName(EventKind::kRelease), "release");
  EXPECT_STREQ(SimStatusName(SimStatus::kEventLimit), "event_limit");
  EXPECT_STREQ(SimModeName(SimMode::kOnLeftWall), "on_left_wall");
}

}  // namespace
}  // namespace capsubot
