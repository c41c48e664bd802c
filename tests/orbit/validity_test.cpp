// Validity (docs/model.md section 5): exact extrema of x against dense sampling, and each
// condition reported by name on an orbit that breaks it.

#include "capsubot/orbit/validity.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::Near;

constexpr int kSamples = 400000;  // dense sampling: the independent reference for extrema

struct Sampled {
  double min = 1.0, max_interior = -INFINITY;
  double max_step = 0.0;  // largest |x'| * step: bounds the sampling error of the minimum
};

// Minimum and highest interior local maximum of x over (0, tau) on a uniform grid.
Sampled Sample(const Orbit& o) {
  Sampled s;
  const double h = kTau / kSamples;
  double prev = o.x(0.0), cur = o.x(h);
  for (int i = 2; i <= kSamples; ++i) {
    const double next = o.x(h * i);
    s.min = std::min(s.min, cur);
    if (cur >= prev && cur >= next) s.max_interior = std::max(s.max_interior, cur);
    prev = cur;
    cur = next;
  }
  return s;
}

using Case = testing::NamedCase;

// Existing orbits with and without interior maxima, both families (parameters from scans of
// `capsubot solve` over phi0).
const Case kCases[] = {
    {"valid_no_max", Forcing::Harmonic(0.05, 0.02, -2.5), Params{0.1, 0.5}},
    {"right_wall", Forcing::Harmonic(0.2, 0.03, -3.1), Params{1.0, 0.5}},
    {"right_and_left", Forcing::Harmonic(4.0, 0.6, -3.1), Params{20.0, 0.5}},
    {"plastic_e0", Forcing::Harmonic(0.08, 0.01, -2.4), Params{0.1, 0.0}},
    {"paper_example", Forcing::Harmonic(0.5, 0.5, -2.944899971002), Params{1.0, 1.0}},
    {"fourier_k3", Forcing::Fourier(0.02, {0.01, 0.0, 0.005}, {0.04, 0.01, 0.0}, -2.6),
     Params{0.1, 0.7}},
};

class ValidityCases : public ::testing::TestWithParam<Case> {};

TEST_P(ValidityCases, ExactMinimumAgreesWithDenseSampling) {
  const Solution s = Solve(GetParam().forcing, GetParam().params);
  ASSERT_TRUE(s.orbit.ok());
  const Sampled ref = Sample(s.orbit);
  // The exact minimum is never above a sample; a sample lies within h/2 of the minimiser,
  // where x' = 0, so it is at most max|x''| (h/2)^2 / 2 above it (< 1e-9 here).
  EXPECT_LE(s.validity.x_min, ref.min + 1e-14);
  EXPECT_TRUE(Near(s.validity.x_min, ref.min, 1e-9));
  // x at the minimiser is the minimum up to rounding (Phi there from its Taylor series at the
  // last iterate of the root search, or from the force at that phase: a few ulp apart).
  EXPECT_TRUE(testing::NearAbsBelowOne(s.orbit.x(s.validity.phi_x_min), s.validity.x_min, 1e-15));
}

TEST_P(ValidityCases, ExactMaximumAgreesWithDenseSampling) {
  const Solution s = Solve(GetParam().forcing, GetParam().params);
  ASSERT_TRUE(s.orbit.ok());
  const Sampled ref = Sample(s.orbit);
  if (std::isinf(ref.max_interior)) {
    EXPECT_TRUE(std::isnan(s.validity.x_max)) << "x_max " << s.validity.x_max;
  } else {
    EXPECT_TRUE(Near(s.validity.x_max, ref.max_interior, 1e-9));
    EXPECT_GE(s.validity.x_max, ref.max_interior - 1e-14);
  }
}

TEST_P(ValidityCases, WallConditionsFollowTheExtrema) {
  const Solution s = Solve(GetParam().forcing, GetParam().params);
  EXPECT_EQ(s.validity.violated(Condition::kLeftWall), s.validity.x_min < 0.0);
  EXPECT_EQ(s.validity.violated(Condition::kRightWall), s.validity.x_max > 1.0);
}

INSTANTIATE_TEST_SUITE_P(Orbits, ValidityCases, ::testing::ValuesIn(kCases),
                         [](const auto& info) { return std::string(info.param.name); });

TEST(Validity, ValidOrbitHasNoViolation) {
  const Solution s = Solve(Forcing::Harmonic(0.05, 0.02, -2.5), Params{0.1, 0.5});
  EXPECT_TRUE(s.validity.valid());
  EXPECT_TRUE(s.validity.ViolationNames().empty());
}

TEST(Validity, PaperExampleBreaksOnlyTheLeftWall) {
  // docs/model.md section 6: at T0 = 1 the worked example dips far below x = 0.
  const Solution s = Solve(Forcing::Harmonic(0.5, 0.5, -2.944899971002), Params{});
  EXPECT_EQ(s.validity.ViolationNames(), std::vector<std::string>{"left_wall"});
  EXPECT_LT(s.validity.x_min, -9.0);
}

TEST(Validity, EarlyRightWallContactIsReported) {
  // The condition the paper omits: x rises above 1 before the period ends.
  const Solution s = Solve(Forcing::Harmonic(0.2, 0.03, -3.1), Params{1.0, 0.5});
  EXPECT_EQ(s.validity.ViolationNames(), std::vector<std::string>{"right_wall"});
  EXPECT_GT(s.validity.x_max, 1.0);
}

TEST(Validity, MotorStrongerThanFrictionIsReported) {
  // A + c > T0: not an input error, a violated condition.
  const Solution s = Solve(Forcing::Harmonic(0.9, 0.3, -2.5), Params{});
  EXPECT_TRUE(s.validity.violated(Condition::kForceBelowFriction));
  EXPECT_TRUE(Near(s.validity.max_force, 1.2, 1e-15));
}

TEST(Validity, ForceExactlyAtTheFrictionBoundHolds) {
  // A + c = T0 (the boundary of the paper's A + c < T0): max |F| = T0 touches the bound, it
  // does not exceed it, at every impact phase (the extremum is evaluated with rounding).
  // c = T0 - A is how the optimiser puts a force on its bound.
  const Params params = Params{0.1, 1.0};
  for (double A = 0.005; A < 0.1; A += 0.005) {
    for (double phi0 = -3.1; phi0 < 3.2; phi0 += 0.1) {
      const Solution s = Solve(Forcing::Harmonic(A, params.T0 - A, phi0), params);
      EXPECT_FALSE(s.validity.violated(Condition::kForceBelowFriction)) << "A = " << A;
      EXPECT_FALSE(s.validity.violated(Condition::kStick)) << "A = " << A << " phi0 " << phi0;
    }
  }
}

TEST(Validity, CapsuleThatCannotStickIsReported) {
  // F reaches 1.35 > T0 = 1 in the rest phase (the maximum of F lies after phi1 here).
  const Solution s = Solve(Forcing::Harmonic(1.3, 0.05, -3.1), Params{});
  ASSERT_FALSE(std::isnan(s.orbit.phi1));
  EXPECT_GT(s.validity.rest_force, 1.0);
  EXPECT_TRUE(s.validity.violated(Condition::kStick));
}

TEST(Validity, NonPositiveMeanForceIsAViolationNotAnError) {
  const Solution s = Solve(Forcing::Harmonic(0.3, -0.1, 0.0), Params{});
  EXPECT_EQ(s.orbit.status, OrbitStatus::kNonPositiveMeanForce);
  EXPECT_EQ(s.validity.ViolationNames(), std::vector<std::string>{"positive_mean_force"});
  EXPECT_TRUE(std::isnan(s.validity.x_min));
}

TEST(Validity, MissingMassRatioIsReported) {
  const Solution s = Solve(Forcing::Harmonic(0.2, 0.03, 0.0), Params{});
  EXPECT_EQ(s.validity.ViolationNames(), std::vector<std::string>{"mass_ratio"});
}

TEST(Validity, PlasticImpactNeedsTheInnerBodyToMoveAway) {
  // e = 0: x'(0+) = 0, so x''(0+) = (F(0) + alpha T0)/(alpha (1 - alpha)) must be negative.
  const Solution ok = Solve(Forcing::Harmonic(0.08, 0.01, -2.4), Params{0.1, 0.0});
  ASSERT_TRUE(ok.orbit.ok());
  EXPECT_LT(ok.orbit.ddx(0.0), 0.0);
  EXPECT_FALSE(ok.validity.violated(Condition::kSeparation));
  // Pushed into the wall at the impact (F(0) > 0 here): found by scanning phi0 for e = 0.
  for (double phi0 = -3.1; phi0 < 3.2; phi0 += 0.05) {
    const Solution s = Solve(Forcing::Harmonic(0.08, 0.01, phi0), Params{0.1, 0.0});
    if (!s.orbit.ok()) continue;
    EXPECT_EQ(s.validity.violated(Condition::kSeparation), !(s.orbit.ddx(0.0) < 0.0))
        << "phi0 = " << phi0;
  }
}

TEST(Validity, ClearanceMarginIsCheckedOnlyWhenRequired) {
  const Forcing f = Forcing::Harmonic(0.05, 0.02, -2.5);  // x_min = 0.166 (valid_no_max)
  EXPECT_FALSE(Solve(f, Params{0.1, 0.5}, Margins{0.1}).validity.violated(Condition::kClearance));
  const Solution s = Solve(f, Params{0.1, 0.5}, Margins{0.2});
  EXPECT_EQ(s.validity.ViolationNames(), std::vector<std::string>{"clearance"});
}

TEST(Validity, ConditionNamesAreStable) {
  // These identifiers are the JSON and CSV interface.
  const char* expected[] = {"positive_mean_force",
                            "mass_ratio",
                            "force_below_friction",
                            "stick",
                            "left_wall",
                            "right_wall",
                            "separation",
                            "clearance",
                            "finite"};
  for (int i = 0; i < static_cast<int>(Condition::kCount); ++i) {
    EXPECT_STREQ(ConditionName(static_cast<Condition>(i)), expected[i]);
  }
}

// The margins of a robust gait (docs/model.md section 12) on the valid orbit "valid_no_max"
// (x from 0.166 to 1, no interior maximum): thresholds from the orbit's own extrema.
TEST(Validity, StrokeClearanceIsDsTimesTheRangeOfX) {
  const Case& k = kCases[0];
  const Solution plain = Solve(k.forcing, k.params);
  ASSERT_TRUE(plain.validity.valid());
  ASSERT_TRUE(std::isnan(plain.validity.x_max));
  const double x_min = plain.validity.x_min, stroke = 1.0 - x_min;  // x = 1 at the impact
  EXPECT_EQ(plain.validity.stroke, stroke);
  const double d_s = x_min / stroke;  // the clearance that x_min just meets
  Margins m;
  m.clearance_stroke = d_s * (1.0 - 1e-9);
  const Validity holds = Solve(k.forcing, k.params, m).validity;
  EXPECT_TRUE(holds.valid());
  EXPECT_EQ(holds.clearance, m.clearance_stroke * stroke);
  m.clearance_stroke = d_s * (1.0 + 1e-9);
  const Validity fails = Solve(k.forcing, k.params, m).validity;
  EXPECT_EQ(fails.ViolationNames(), std::vector<std::string>{"clearance"});
  // The absolute clearance d wins when it is the larger.
  m.clearance = 0.5 * x_min;
  m.clearance_stroke = 0.1 * d_s;
  EXPECT_EQ(Solve(k.forcing, k.params, m).validity.clearance, 0.5 * x_min);
  // The same check on the orbit alone.
  EXPECT_EQ(CheckValidity(plain.orbit, m).clearance, 0.5 * x_min);
}

TEST(Validity, StickMarginLowersTheForceAllowedAtRest) {
  const Case& k = kCases[0];
  const Solution plain = Solve(k.forcing, k.params);
  ASSERT_TRUE(plain.validity.valid());
  const double s = 1.0 - plain.validity.rest_force / k.params.T0;  // the margin it just meets
  ASSERT_GT(s, 0.0);
  Margins m;
  m.stick = s * (1.0 - 1e-6);
  EXPECT_TRUE(Solve(k.forcing, k.params, m).validity.valid());
  m.stick = s * (1.0 + 1e-6);
  EXPECT_EQ(Solve(k.forcing, k.params, m).validity.ViolationNames(),
            std::vector<std::string>{"stick"});
}

TEST(Validity, MarginsOutsideTheirRangeAreRejectedWithTheRule) {
  struct Bad {
    Margins margins;
    const char* message;
  };
  const Bad cases[] = {
      {Margins{0.5, 0.0, 0.0}, "margin d = 0.5 is invalid: expected 0 <= d < 0.5"},
      {Margins{-0.1, 0.0, 0.0}, "margin d = -0.1 is invalid: expected 0 <= d < 0.5"},
      {Margins{0.0, 0.5, 0.0}, "stroke margin d_s = 0.5 is invalid: expected 0 <= d_s < 0.5"},
      {Margins{0.0, -0.1, 0.0}, "stroke margin d_s = -0.1 is invalid: expected 0 <= d_s < 0.5"},
      {Margins{0.0, 0.0, 1.0}, "stick margin s = 1 is invalid: expected 0 <= s < 1"},
      {Margins{0.0, 0.0, NAN}, "stick margin s = nan is invalid: expected 0 <= s < 1"},
  };
  int checked = 0;
  for (const Bad& b : cases) {
    try {
      b.margins.Validate();
      ADD_FAILURE() << "accepted: " << b.message;
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()), b.message);
    }
    ++checked;
  }
  EXPECT_EQ(checked, 6);
}

}  // namespace
}  // namespace capsubot
