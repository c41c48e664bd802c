// Speed bands (speed_band.hpp, docs/optimize.md "Robustness"): where the mean speed from rest
// falls below a fraction of the nominal one. References: direct simulations from rest of every
// start (the simulator alone, no attractor classification), and the same band with its
// numerical knobs moved by orders of magnitude.

#include "capsubot/continue/speed_band.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "capsubot/continue/gait_robustness.hpp"
#include "capsubot/continue/parameter_branch.hpp"
#include "capsubot/simulate/simulator.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::InvalidArgumentMessage;

// The main job's fastest motion from rest at T0 = 1, e = 1 (`capsubot optimize`, results/
// optimum.json, key reach): a chattering motion with 73 right + 5 left impacts per period.
RobotModel ReachWinner() {
  Params p;
  p.T0 = 1.0;
  p.e = 1.0;
  return {Forcing::Harmonic(0.676979732510288, 0.3230202674897121, -3.089378590956282), p,
          0.9431003086419751};
}

// A small grid of starts keeps the test fast; the band is the same function of it.
SpeedBandOptions Small() {
  SpeedBandOptions o;
  o.from_rest.n_x = 3;
  o.from_rest.n_psi = 3;
  return o;
}

// The direct simulation from rest: each start of the grid simulated for kTransient periods,
// then its mean velocity over kRecord periods, averaged over the starts.
constexpr double kTransient = 300.0;
constexpr double kRecord = 2000.0;
// Its error: the motions from rest here are periodic with period 1 and settle within the
// transient, so a record of whole periods gives their mean speed up to the transient's remnant
// (Newton's mean velocity and this one agree to 1e-6 at the nominal robot); 3e-4 is well above
// that and below the distance of the speeds at a final bracket's ends from the level (5e-4).
constexpr double kDirectTol = 3e-4;

double DirectSpeed(const RobotModel& r, const FromRestOptions& grid) {
  double sum = 0.0;
  const std::vector<PhaseState> starts = GridStarts(grid.n_x, grid.n_psi);
  for (const PhaseState& s : starts) {
    SimOptions o = testing::StartAt(r.alpha, s.x, 0.0, 0.0, kRecord);
    o.transient = kTransient;
    const SimResult run = Simulate(r.forcing.WithPhase(r.forcing.phi0() + s.psi), r.params, o);
    EXPECT_EQ(run.status, SimStatus::kOk) << run.message;
    sum += run.v_mean;
  }
  return sum / static_cast<double>(starts.size());
}

RobotFamily Along(const std::string& name) {
  const RobotModel r = ReachWinner();
  return NamedParameterFamily(r, name);
}

// The parameters of the reach winner whose bands are checked, with their ranges (those of
// ComputeMotionRobustness).
struct Case {
  const char* name;
  double from, to;
};

TEST(SpeedBand, EdgesBracketTheLevelByDirectSimulationFromRest) {
  const SpeedBandOptions o = Small();
  const double alpha = ReachWinner().alpha;
  int within = 0;
  for (const Case& c : {Case{"T0", 0.5, 2.0}, Case{"alpha", 0.5 * alpha, 0.5 * (1 + alpha)}}) {
    SCOPED_TRACE(c.name);
    const RobotFamily family = Along(c.name);
    const double value = c.name == std::string("T0") ? 1.0 : alpha;
    const SpeedBand b = ComputeSpeedBand(family, c.name, value, c.from, c.to, o);
    ASSERT_EQ(b.status, SpeedBandStatus::kOk);
    const double nominal = DirectSpeed(family(value), o.from_rest);
    EXPECT_TRUE(testing::RelNear(b.nominal_speed, nominal, kDirectTol));
    for (const BandEdge* e : {&b.down.front(), &b.up.front()}) {
      if (!e->within) continue;
      ++within;
      // A little inside and outside the final bracket.
      const double little = e->accuracy;
      const double sign = e->outside > e->inside ? 1.0 : -1.0;
      const double in = DirectSpeed(family(e->inside - sign * little), o.from_rest) / nominal;
      const double out = DirectSpeed(family(e->outside + sign * little), o.from_rest) / nominal;
      EXPECT_GE(in, e->level - kDirectTol) << "at " << e->inside;
      EXPECT_LT(out, e->level + kDirectTol) << "at " << e->outside;
    }
  }
  ASSERT_GE(within, 2);
}

// Edges of the alpha band of `o` (down, up: the first level).
std::pair<BandEdge, BandEdge> AlphaEdges(const SpeedBandOptions& o) {
  const double alpha = ReachWinner().alpha;
  const SpeedBand b =
      ComputeSpeedBand(Along("alpha"), "alpha", alpha, 0.5 * alpha, 0.5 * (1 + alpha), o);
  EXPECT_EQ(b.status, SpeedBandStatus::kOk);
  return {b.down.front(), b.up.front()};
}

// Two findings of one edge agree when their brackets overlap: each holds a crossing of the level.
::testing::AssertionResult SameEdge(const BandEdge& a, const BandEdge& b) {
  if (a.within != b.within) return ::testing::AssertionFailure() << "within differs";
  if (!a.within) return testing::Near(a.parameter, b.parameter, 0.0);
  return testing::Near(a.parameter, b.parameter, 0.5 * (a.accuracy + b.accuracy));
}

TEST(SpeedBand, EdgesDoNotDependOnTheToleranceTheWalkOrTheChatterCutOff) {
  const auto [down, up] = AlphaEdges(Small());
  ASSERT_TRUE(down.within);  // the edge below; above, the band reaches beyond the range
  for (double tolerance : {1e-2, 1e-5}) {
    SpeedBandOptions o = Small();
    o.tolerance = tolerance;
    const auto [d, u] = AlphaEdges(o);
    EXPECT_TRUE(SameEdge(d, down)) << "tolerance " << tolerance;
    EXPECT_TRUE(SameEdge(u, up)) << "tolerance " << tolerance;
  }
  for (double first_step : {1.0 / 8, 1.0 / 1024}) {
    SpeedBandOptions o = Small();
    o.first_step = first_step;
    const auto [d, u] = AlphaEdges(o);
    EXPECT_TRUE(SameEdge(d, down)) << "first step " << first_step;
    EXPECT_TRUE(SameEdge(u, up)) << "first step " << first_step;
  }
  for (double cut_off : {1e-8, 1e-4}) {
    SpeedBandOptions o = Small();
    o.from_rest.attractor.motion.chatter_velocity = cut_off;
    const auto [d, u] = AlphaEdges(o);
    EXPECT_TRUE(SameEdge(d, down)) << "chatter cut-off " << cut_off;
    EXPECT_TRUE(SameEdge(u, up)) << "chatter cut-off " << cut_off;
  }
}

TEST(SpeedBand, LowerLevelsLieFartherOutAndARangeEndIsNoEdge) {
  SpeedBandOptions o = Small();
  o.levels = {0.95, 0.9};
  const SpeedBand b = ComputeSpeedBand(Along("T0"), "T0", 1.0, 0.5, 2.0, o);
  ASSERT_EQ(b.status, SpeedBandStatus::kOk);
  ASSERT_EQ(b.down.size(), 2U);
  ASSERT_EQ(b.up.size(), 2U);
  EXPECT_LE(b.down[1].inside, b.down[0].inside);
  EXPECT_GE(b.up[1].inside, b.up[0].inside);
  // e = 1 is the top of its range: the band reaches beyond it, with no edge there.
  const SpeedBand e = ComputeSpeedBand(Along("e"), "e", 1.0, 0.0, 1.0, Small());
  ASSERT_EQ(e.status, SpeedBandStatus::kOk);
  EXPECT_FALSE(e.up.front().within);
  EXPECT_EQ(e.up.front().parameter, 1.0);
  EXPECT_TRUE(std::isnan(e.up.front().accuracy));
}

TEST(SpeedBand, EvaluationsAreBounded) {
  SpeedBandOptions o = Small();
  o.levels = {0.99, 0.95, 0.5};
  o.tolerance = 1e-4;
  const SpeedBand b = ComputeSpeedBand(Along("T0"), "T0", 1.0, 0.5, 2.0, o);
  // The nominal, then each way the walk (1 + log2(1/first_step) points) and a bisection of
  // log2(1/tolerance) steps per level (speed_band.hpp).
  const double walk = 1.0 + std::log2(1.0 / o.first_step);
  const double bisections = std::ceil(std::log2(1.0 / o.tolerance)) * o.levels.size();
  EXPECT_GT(b.evaluations, 1);
  EXPECT_LE(b.evaluations, 1.0 + 2.0 * (walk + bisections));
}

TEST(SpeedBand, ARobotThatDoesNotMoveHasNoBand) {
  RobotModel still = ReachWinner();
  still.forcing = Forcing::Harmonic(0.0, 0.0, 0.0);
  const SpeedBand b = ComputeSpeedBand([&](double) { return still; }, "T0", 1.0, 0.5, 2.0, Small());
  EXPECT_EQ(b.status, SpeedBandStatus::kNoSpeed);
  EXPECT_TRUE(b.down.empty());
  EXPECT_EQ(b.nominal_speed, 0.0);
}

TEST(SpeedBand, RefusesBadOptionsNamingThem) {
  const auto message = [](const SpeedBandOptions& o, double value = 1.0) {
    return InvalidArgumentMessage([&] { ComputeSpeedBand(Along("T0"), "T0", value, 0.5, 2.0, o); });
  };
  SpeedBandOptions o;
  o.levels = {1.5};
  EXPECT_EQ(message(o), "band_levels = 1.5 is invalid: expected fractions of the speed in (0, 1)");
  o.levels = {0.9, 0.9};
  EXPECT_EQ(message(o), "band_levels = 0.9 is invalid: expected distinct levels");
  o.levels = {};
  EXPECT_EQ(message(o), "band_levels = 0 levels is invalid: expected 1 to 8 levels");
  o = SpeedBandOptions{};
  o.tolerance = 0.0;
  EXPECT_EQ(message(o), "tolerance = 0 is invalid: expected 1e-9 <= tolerance <= 0.1");
  o = SpeedBandOptions{};
  o.first_step = 2.0;
  EXPECT_EQ(message(o), "first_step = 2 is invalid: expected 1e-6 <= first_step <= 1");
  EXPECT_EQ(message(SpeedBandOptions{}, 3.0),
            "T0 = 3 is invalid: expected a finite range 0.5 <= T0 <= 2");
}

}  // namespace
}  // namespace capsubot
