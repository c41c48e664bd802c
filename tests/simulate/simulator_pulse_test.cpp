// The simulator under a pulse force (docs/simulate.md "Pulse forces"): against an independent
// fixed-step integration with located events, the energy budget over a periodic motion
// (docs/model.md section 11), the pulse's Fourier series converging to the same long-run motion
// as its harmonics grow, chattering ended at its accumulation point whatever the rule's knobs,
// and the switches as the phases where the capsule breaks away and the body leaves a wall.

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

#include "capsubot/model/forcing.hpp"
#include "capsubot/simulate/simulator.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::Near;
using testing::StartAt;

// ---------------------------------------------------------------------------------------------
// The reference: fixed steps of h; in each, the force is held at its value at the step's
// middle, so the accelerations of docs/model.md section 3 are constant and x, u, v, y move as
// polynomials of degree 2 in the step; an impact (x reaching a wall moving towards it) or a
// stop (v reaching 0) inside a step ends the step there. An impact slower than kStickSpeed
// leaves the body on the wall (plastic: the momentum of the remaining impacts); it stays while
// the free relative acceleration pushes it into the wall. The only error is the force's value
// on the steps that hold a switch: O(h) per switch.
constexpr double kStickSpeed = 1e-10;

struct RefState {
  double x, u, v, y;
  int wall = 0;  // the body rests on the right (+1) or left (-1) wall; 0: free
};

// Smallest t in (0, dt] with x + u t + a t^2/2 = level, moving towards it (dir: +1 the right
// wall, -1 the left one); +inf if none.
double Reach(double x, double u, double a, double level, int dir, double dt) {
  double best = INFINITY;
  const double c = x - level;
  const auto consider = [&](double t) {
    if (t > 1e-15 && t <= dt && dir * (u + a * t) > 0.0) best = std::min(best, t);
  };
  if (a == 0.0) {
    if (u != 0.0) consider(-c / u);
    return best;
  }
  const double disc = u * u - 2.0 * a * c;
  if (disc < 0.0) return best;
  const double q = -(u + std::copysign(std::sqrt(disc), u == 0.0 ? 1.0 : u));
  consider(q / a);
  if (q != 0.0) consider(2.0 * c / q);
  return best;
}

RefState Reference(const Forcing& f, const Params& p, double alpha, RefState s, double periods,
                   double h) {
  const double T0 = p.T0, e = p.e, end = periods * kTau;
  double phi = 0.0;
  const auto impact = [&](int dir) {
    s.x = dir > 0 ? 1.0 : 0.0;
    if (e * std::abs(s.u) < kStickSpeed) {
      s.v += alpha * s.u;
      s.u = 0.0;
      s.wall = dir;
    } else {
      s.v += alpha * (1.0 + e) * s.u;
      s.u = -e * s.u;
    }
  };
  for (long guard = 0; phi < end && guard < 100000000; ++guard) {
    const double dt = std::min(h, end - phi);
    // A flight's end rounded onto or past the wall it returns to: the impact is now.
    if (s.wall == 0 && ((s.x >= 1.0 && s.u > 0.0) || (s.x <= 0.0 && s.u < 0.0))) {
      impact(s.x >= 1.0 ? 1 : -1);
      continue;
    }
    const double F = f.F(phi + 0.5 * dt);
    int sgn = s.v > 0.0 ? 1 : s.v < 0.0 ? -1 : 0;  // the capsule's slide
    const auto free_accel = [&](int slide) {
      return slide == 0 ? F / alpha : (F + slide * alpha * T0) / (alpha * (1.0 - alpha));
    };
    if (s.wall != 0 && s.wall * free_accel(sgn) <= 0.0) s.wall = 0;    // the body leaves the wall
    if (s.wall == 0 && sgn == 0) sgn = F > T0 ? -1 : F < -T0 ? 1 : 0;  // rest or break-away
    double au = s.wall != 0 ? 0.0 : free_accel(sgn);
    const int pressed = s.u != 0.0               ? 0
                        : s.x >= 1.0 && au > 0.0 ? 1
                        : s.x <= 0.0 && au < 0.0 ? -1
                                                 : 0;
    if (pressed != 0) {  // at a wall without velocity, pushed into it: it rests there
      s.wall = pressed;
      au = 0.0;
    }
    const double av = sgn == 0 ? 0.0 : s.wall != 0 ? -sgn * T0 : -(sgn * T0 + F) / (1.0 - alpha);
    double t = dt;
    const double stop = sgn != 0 && sgn * (s.v + av * dt) < 0.0 ? -s.v / av : INFINITY;
    const double right = s.wall != 0 ? INFINITY : Reach(s.x, s.u, au, 1.0, 1, dt);
    const double left = s.wall != 0 ? INFINITY : Reach(s.x, s.u, au, 0.0, -1, dt);
    t = std::min({t, stop, right, left});
    s.x += t * (s.u + 0.5 * au * t);
    s.u += au * t;
    s.y += t * (s.v + 0.5 * av * t);
    s.v = t == stop ? 0.0 : s.v + av * t;
    phi += t;
    if (t == right || t == left) impact(t == right ? 1 : -1);
  }
  return s;
}

struct PulseCase {
  const char* name;
  std::vector<double> levels, switches;
  double phi0;
  Params params;
  double alpha;
  RefState start;
};

std::vector<PulseCase> Cases() {
  return {
      // Three levels beyond T0 both ways: break-aways at switches, impacts on both walls.
      {"three_levels",
       {1.6, -0.3, -1.4},
       {0.0, 2.0, 4.2},
       0.3,
       Params{1.0, 0.5},
       0.4,
       {0.5, 0.0, 0.0, 0.0}},
      // Two levels inside T0 with e = 0: the body stays on a wall between pushes.
      {"plastic", {0.3, -0.25}, {1.0, 4.0}, 0.0, Params{0.5, 0.0}, 0.3, {0.2, 0.1, 0.0, 0.0}},
      // A short strong pulse, sliding start, e = 0.8.
      {"short_pulse", {-2.0, 0.4}, {0.5, 1.2}, -1.0, Params{1.0, 0.8}, 0.6, {0.7, -0.2, 0.3, 0.0}},
  };
}

// The reference's error is O(h) (the force held over the steps that hold a switch; the events
// are exact within a step): at h = 2.5e-5 it is about 1e-5 in x, v, y after three periods of
// these cases, so the simulator must agree to ten times that, and the error must shrink by at
// least kConvergence from h = 4e-4 to h = 2.5e-5 (16 times smaller: first order gives 16).
constexpr double kReferenceTol = 1e-4;
constexpr double kConvergence = 4.0;

TEST(SimulatorPulse, MatchesAFineFixedStepIntegration) {
  const std::vector<PulseCase> cases = Cases();
  ASSERT_FALSE(cases.empty());
  for (const PulseCase& c : cases) {
    const Forcing f = Forcing::Pulse(c.levels, c.switches, c.phi0);
    const double periods = 3.0;
    const SimResult r =
        Simulate(f, c.params, StartAt(c.alpha, c.start.x, c.start.u, c.start.v, periods));
    ASSERT_EQ(r.status, SimStatus::kOk) << c.name << ": " << r.message;
    EXPECT_GT(r.impacts_right + r.impacts_left, 0) << c.name;
    const auto error = [&](double h) {
      const RefState ref = Reference(f, c.params, c.alpha, c.start, periods, h);
      return std::max({std::abs(ref.x - r.final_state.x), std::abs(ref.v - r.final_state.v),
                       std::abs(ref.y - r.final_state.y)});
    };
    const double coarse = error(4e-4), fine = error(2.5e-5);
    EXPECT_LT(fine, kReferenceTol) << c.name;
    EXPECT_LT(kConvergence * fine, coarse) << c.name;
  }
}

// Kinetic energy of the two bodies in units of (m1+m2) omega^2 L^2: shell v, inner body v + u.
double Kinetic(double alpha, const SimState& s) {
  return 0.5 * ((1.0 - alpha) * s.v * s.v + alpha * (s.v + s.u) * (s.v + s.u));
}

// docs/model.md section 11: the budget is a sum of closed forms at events located to a few ulp.
constexpr double kBalanceTol = 1e-10;
// A converged periodic motion returns to its state after its period (rounding).
constexpr double kReturnTol = 1e-9;

TEST(SimulatorPulse, MotorWorkEqualsTheLossesOverAPeriodicMotion) {
  int periodic = 0;
  for (const PulseCase& c : Cases()) {
    const Forcing f = Forcing::Pulse(c.levels, c.switches, c.phi0);
    SimOptions opt = StartAt(c.alpha, c.start.x, c.start.u, c.start.v, 1.0);
    opt.transient = 300.0;
    opt.energy = true;
    // The state after the transient, then one and two more periods: the motion's period is one
    // or two forcing periods in these cases.
    const SimResult first = Simulate(f, c.params, opt);
    ASSERT_EQ(first.status, SimStatus::kOk) << c.name;
    SimOptions again = opt;
    again.transient = 0.0;
    again.x0 = first.final_state.x;
    again.u0 = first.final_state.u;
    again.v0 = first.final_state.v;
    for (double p : {1.0, 2.0}) {
      again.periods = p;
      const SimResult r = Simulate(f, c.params, again);
      const SimState& end = r.final_state;
      if (std::abs(end.x - again.x0) > kReturnTol || std::abs(end.u - again.u0) > kReturnTol ||
          std::abs(end.v - again.v0) > kReturnTol) {
        continue;
      }
      ++periodic;
      const Energy& en = r.energy;
      const double scale = std::max({std::abs(en.motor_work), en.friction_loss, en.impact_loss});
      EXPECT_GT(en.friction_loss, 0.0) << c.name;
      EXPECT_GT(en.motor_work, 0.0) << c.name;
      EXPECT_TRUE(Near(en.motor_work, en.friction_loss + en.impact_loss, kBalanceTol * scale))
          << c.name << " over " << p << " periods";
      break;
    }
  }
  EXPECT_EQ(periodic, static_cast<int>(Cases().size()));
}

// The energy theorem over a span that is not periodic: motor work = losses + change of the
// kinetic energy, through switches, break-aways, chattering and sticks.
TEST(SimulatorPulse, EnergyBudgetHoldsOverAnySpan) {
  for (const PulseCase& c : Cases()) {
    const Forcing f = Forcing::Pulse(c.levels, c.switches, c.phi0);
    SimOptions opt = StartAt(c.alpha, c.start.x, c.start.u, c.start.v, 7.3);
    opt.energy = true;
    const SimResult r = Simulate(f, c.params, opt);
    SimState start;
    start.u = c.start.u;
    start.v = c.start.v;
    const double dK = Kinetic(c.alpha, r.final_state) - Kinetic(c.alpha, start);
    const Energy& en = r.energy;
    const double scale =
        std::max({std::abs(en.motor_work), en.friction_loss, en.impact_loss, std::abs(dK)});
    EXPECT_TRUE(Near(en.motor_work, en.friction_loss + en.impact_loss + dK, kBalanceTol * scale))
        << c.name;
  }
}

// The Fourier series of G, sum c + a_k cos ks + b_k sin ks with
// a_k = (1/(pi k)) sum_j L_j (sin k s_{j+1} - sin k s_j), b_k = (1/(pi k)) sum_j L_j (cos k s_j -
// cos k s_{j+1}) (integrals of cos ks, sin ks over each piece), truncated at K.
Forcing SeriesOf(const std::vector<double>& levels, const std::vector<double>& switches,
                 double phi0, int K) {
  const std::size_t n = levels.size();
  double mean = 0.0;
  std::vector<double> a(K, 0.0), b(K, 0.0);
  for (std::size_t j = 0; j < n; ++j) {
    const double lo = switches[j], hi = j + 1 < n ? switches[j + 1] : switches[0] + kTau;
    mean += levels[j] * (hi - lo) / kTau;
    for (int k = 1; k <= K; ++k) {
      a[k - 1] += levels[j] * (std::sin(k * hi) - std::sin(k * lo)) / (M_PI * k);
      b[k - 1] += levels[j] * (std::cos(k * lo) - std::cos(k * hi)) / (M_PI * k);
    }
  }
  return Forcing::Fourier(mean, a, b, phi0);
}

// A drive whose motion chatters on the left wall every period (the robot of
// tests/cli/pulse_cli_test.cpp: 1 right and 6 left impacts a period): the long-run mean
// velocity from rest against the fixed-step reference over the same 300 + 100 periods. Its
// O(h) error, accumulated over the chattering sequences, is 6e-5 of the mean velocity at
// h = 2e-4 and 1.5e-4 at h = 5e-5 (measured); the Fourier series of this pulse with 16 harmonics
// is still 50 % off (0.0118 against 0.0077), so only the pulse itself answers here.
constexpr double kLongRunReferenceTol = 1e-3;

TEST(SimulatorPulse, ChatteringLongRunMatchesTheFixedStepIntegration) {
  const Forcing f = Forcing::Pulse({0.3, -0.05}, {0.0, 1.5}, 0.0);
  const Params params{0.1, 0.5};
  constexpr double kAlpha = 0.3, kTransient = 300.0, kRecord = 100.0, kStep = 2e-4;
  SimOptions opt = StartAt(kAlpha, 0.5, 0.0, 0.0, kRecord);
  opt.transient = kTransient;
  const SimResult r = Simulate(f, params, opt);
  ASSERT_EQ(r.status, SimStatus::kOk) << r.message;
  EXPECT_GT(r.sticks, 0);  // the body rests on a wall at the end of a chattering sequence
  const RefState settled = Reference(f, params, kAlpha, {0.5, 0.0, 0.0, 0.0}, kTransient, kStep);
  const RefState end = Reference(f, params, kAlpha, settled, kRecord, kStep);
  const double reference = (end.y - settled.y) / (kRecord * kTau);
  EXPECT_GT(std::abs(reference), 1e-3);  // a directed motion
  EXPECT_TRUE(testing::Near(r.v_mean, reference, kLongRunReferenceTol * std::abs(reference)));
}

TEST(SimulatorPulse, FourierSeriesOfThePulseConvergesToItsLongRunMotion) {
  // A two-level drive with both levels inside T0 and e = 0.5: the capsule rests between the
  // impacts, so the motion is robust (the Gibbs overshoot of the series near the jumps stays
  // below T0).
  const std::vector<double> levels = {0.45, -0.3}, switches = {0.0, 2.6};
  const Params params{0.6, 0.5};
  SimOptions opt = StartAt(0.5, 0.5, 0.0, 0.0, 100.0);
  opt.transient = 300.0;
  const double pulse = Simulate(Forcing::Pulse(levels, switches, 0.0), params, opt).v_mean;
  ASSERT_TRUE(std::isfinite(pulse));
  ASSERT_GT(std::abs(pulse), 1e-3);  // a directed motion, not a standstill
  std::vector<double> gaps;
  for (int K : {4, 8, 16}) {
    const SimResult r = Simulate(SeriesOf(levels, switches, 0.0, K), params, opt);
    ASSERT_EQ(r.status, SimStatus::kOk);
    gaps.push_back(std::abs(r.v_mean - pulse));
  }
  EXPECT_LT(gaps[1], gaps[0]);
  EXPECT_LT(gaps[2], gaps[1]);
  EXPECT_LT(gaps[2], 0.05 * std::abs(pulse));
}

// The chattering rule under a pulse force: a sequence inside one constant piece ends at its
// accumulation point, and the long-run mean velocity does not move when the rule's knobs move
// by orders of magnitude (docs/model.md section 14). The accumulation point depends on the
// knobs only through its extrapolation error (at most the tolerance, in phase).
constexpr double kKnobTol = 1e-7;

TEST(SimulatorPulse, ChatteringEndsAtItsAccumulationPointWhateverTheKnobs) {
  const PulseCase c = Cases()[2];  // short_pulse: the body chatters on the right wall
  const Forcing f = Forcing::Pulse(c.levels, c.switches, c.phi0);
  SimOptions opt = StartAt(c.alpha, c.start.x, c.start.u, c.start.v, 50.0);
  opt.transient = 20.0;
  const SimResult base = Simulate(f, c.params, opt);
  ASSERT_EQ(base.status, SimStatus::kOk);
  EXPECT_GT(base.sticks, 0);
  for (const auto& [tolerance, velocity] :
       std::vector<std::pair<double, double>>{{1e-8, 1e-4}, {1e-12, 1e-9}, {1e-10, 1e-9}}) {
    SimOptions moved = opt;
    moved.chatter_tolerance = tolerance;
    moved.chatter_velocity = velocity;
    const SimResult r = Simulate(f, c.params, moved);
    EXPECT_TRUE(Near(r.v_mean, base.v_mean, kKnobTol)) << tolerance << " " << velocity;
    EXPECT_EQ(r.sticks, base.sticks);
  }
}

// Records the phases of one kind of event.
struct EventPhases : SimObserver {
  EventKind kind;
  std::vector<double> phi;
  explicit EventPhases(EventKind k) : kind(k) {}
  void OnEvent(const SimEvent& e) override {
    if (e.kind == kind) phi.push_back(e.after.phi);
  }
};

// Phases of events at a switch: its phase to a few ulp of the period's phase.
constexpr double kSwitchPhaseTol = 1e-13;

TEST(SimulatorPulse, TheCapsuleBreaksAwayAtTheSwitchToALevelAboveT0) {
  // F = 0.05 until motor phase 3 moves the body from the left wall (x = 0.05 t^2/(2 alpha) =
  // 0.56 at t = 2.6: still free); then F = 1.5 > T0 = 1: the capsule slides backward from
  // phi = 3 - phi0 on.
  const double phi0 = 0.4;
  const Forcing f = Forcing::Pulse({0.05, 1.5}, {0.0, 3.0}, phi0);
  EventPhases breakaways(EventKind::kBreakaway);
  const SimResult r = Simulate(f, Params{1.0, 0.5}, StartAt(0.3, 0.0, 0.0, 0.0, 1.0), &breakaways);
  ASSERT_EQ(r.status, SimStatus::kOk);
  ASSERT_FALSE(breakaways.phi.empty());
  EXPECT_TRUE(Near(breakaways.phi[0], 3.0 - phi0, kSwitchPhaseTol));
}

TEST(SimulatorPulse, TheBodyLeavesAWallAtTheSwitchThatPullsItAway) {
  // Resting on the right wall under F = 0.3 (into it, below T0); at motor phase 2 F = -0.3
  // pulls it away, it chatters onto the left wall and rests there until F = 0.3 again at
  // 2 pi: every release is at a switch.
  const Forcing f = Forcing::Pulse({0.3, -0.3}, {0.0, 2.0}, 0.0);
  EventPhases releases(EventKind::kRelease);
  const SimResult r = Simulate(f, Params{1.0, 0.5}, StartAt(0.3, 1.0, 0.0, 0.0, 3.0), &releases);
  ASSERT_EQ(r.status, SimStatus::kOk);
  ASSERT_GE(releases.phi.size(), 2u);
  EXPECT_TRUE(Near(releases.phi[0], 2.0, kSwitchPhaseTol));
  for (double phi : releases.phi) {
    // The nearest switch: 2 or 0 plus whole periods.
    const double t = phi - kTau * std::floor(phi / kTau + 1e-9);
    const double gap = std::min({std::abs(t - 2.0), std::abs(t), std::abs(t - kTau)});
    EXPECT_LT(gap, 10 * kSwitchPhaseTol) << phi;
  }
}

}  // namespace
}  // namespace capsubot
