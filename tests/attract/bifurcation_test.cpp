// Bifurcation diagrams (docs/model.md section 13). The coexistence below was seen in a sweep of
// alpha with `capsubot bifurcation` and is checked here against the classification of each
// motion (attractors_test, periodic_test validate those against independent simulations).

#include "capsubot/bifurcation.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>

#include "test_utils.hpp"

namespace capsubot {
namespace {

const Forcing kOptimumForce =
    Forcing::Harmonic(0.34063197373861814, 0.06410131873607934, -3.1181183398453047);

const BifurcationPoint* Find(const BifurcationDiagram& d, SweepDirection dir, double param) {
  for (const BifurcationPoint& p : d.summary) {
    if (p.direction == dir && std::abs(p.param - param) < 1e-12) return &p;
  }
  return nullptr;
}

TEST(Bifurcation, UpAndDownSweepsDifferWhereTwoAttractorsCoexist) {
  // T0 = 0.5 with the stable optimum's force: for alpha in about (0.670, 0.681) a stable
  // 3-right/1-left period-1 motion (carried up from alpha = 0.66) coexists with a stable
  // period-2 motion of 4 right and 2 left impacts (carried down from alpha = 0.70, born from
  // the flip of the 2-right/1-left motion at alpha = 0.6822, periodic_test).
  Params params;
  params.T0 = 0.5;
  BifurcationOptions o;
  o.param = BifurcationParam::kAlpha;
  o.from = 0.66;
  o.to = 0.70;
  o.steps = 21;
  o.start = RestStart(0.5, 1.0);
  o.analytic = false;
  const BifurcationDiagram d = ComputeBifurcation(kOptimumForce, params, 0.66, o);
  ASSERT_EQ(d.summary.size(), 42U);
  const BifurcationPoint* up = Find(d, SweepDirection::kUp, 0.676);
  const BifurcationPoint* down = Find(d, SweepDirection::kDown, 0.676);
  ASSERT_NE(up, nullptr);
  ASSERT_NE(down, nullptr);
  EXPECT_EQ(up->motion.period, 1);
  EXPECT_EQ(up->motion.impacts_right, 3);
  EXPECT_EQ(up->motion.impacts_left, 1);
  EXPECT_LT(up->spectral_radius, 1.0);
  EXPECT_EQ(down->motion.period, 2);
  EXPECT_EQ(down->motion.impacts_right, 4);
  EXPECT_EQ(down->motion.impacts_left, 2);
  EXPECT_LT(down->spectral_radius, 1.0);
  EXPECT_GT(down->motion.mean_velocity, 2.0 * up->motion.mean_velocity);
  // At both ends the sweeps agree (one attractor there).
  for (double end : {0.66, 0.70}) {
    const BifurcationPoint* a = Find(d, SweepDirection::kUp, end);
    const BifurcationPoint* b = Find(d, SweepDirection::kDown, end);
    ASSERT_NE(a, nullptr);
    ASSERT_NE(b, nullptr);
    EXPECT_EQ(a->motion.period, b->motion.period);
    EXPECT_TRUE(testing::Near(a->motion.mean_velocity, b->motion.mean_velocity, 1e-9));
  }
  // Every recorded impact belongs to a value of the range and a record period; a periodic
  // motion found early contributes the impacts of one of its periods, so every value and
  // direction contributes at least one.
  std::size_t impacts = 0;
  for (const ImpactPoint& p : d.impacts) {
    EXPECT_GE(p.param, 0.66 - 1e-12);
    EXPECT_LE(p.param, 0.70 + 1e-12);
    EXPECT_GE(p.period_index, 0);
    EXPECT_LT(p.period_index, o.motion.record);
    ++impacts;
  }
  EXPECT_GE(impacts, 42U);
}

TEST(Bifurcation, AnalyticRowsAreTheValidOneImpactOrbits) {
  // The small stable orbit's robot (solve --A 0.05 --c 0.02 --phi0 -2.842 --T0 0.1 --e 0.5):
  // at its own alpha it has this valid orbit, mean velocity 0.02017805287097631.
  Params params;
  params.T0 = 0.1;
  params.e = 0.5;
  BifurcationOptions o;
  o.param = BifurcationParam::kAlpha;
  o.from = 0.2792869076315278;
  o.to = 0.29;
  o.steps = 2;
  o.up = true;
  o.down = false;
  const BifurcationDiagram d =
      ComputeBifurcation(Forcing::Harmonic(0.05, 0.02, -2.842), params, o.from, o);
  int analytic = 0, matching = 0;
  for (const BifurcationPoint& p : d.summary) {
    if (p.direction != SweepDirection::kAnalytic) continue;
    ++analytic;
    if (p.param == o.from && testing::Near(p.motion.mean_velocity, 0.02017805287097631, 1e-12)) {
      ++matching;
      EXPECT_TRUE(testing::Near(p.spectral_radius, 0.15993637396395888, 1e-12));
    }
  }
  EXPECT_GE(analytic, 1);
  EXPECT_EQ(matching, 1);
}

TEST(BifurcationInput, BadParameterAndRangeAreNamed) {
  const auto message = [](const std::function<void()>& f) -> std::string {
    try {
      f();
    } catch (const std::invalid_argument& e) {
      return e.what();
    }
    return "no exception";
  };
  EXPECT_EQ(message([] { ParseBifurcationParam("mu"); }),
            "parameter = mu is invalid: expected one of A, c, alpha, T0, e, phi0");
  BifurcationOptions o;
  o.param = BifurcationParam::kE;
  o.from = 0.5;
  o.to = 1.5;
  EXPECT_EQ(message([&] { ComputeBifurcation(kOptimumForce, Params{}, 0.5, o); }),
            "e = 1.5 makes the robot invalid: restitution e = 1.5 is invalid: expected 0 <= e "
            "<= 1");
  o.to = 1.0;
  o.steps = 1;
  EXPECT_EQ(message([&] { ComputeBifurcation(kOptimumForce, Params{}, 0.5, o); }),
            "steps = 1 is invalid: expected 2 <= steps <= 10000000");
}

}  // namespace
}  // namespace capsubot
