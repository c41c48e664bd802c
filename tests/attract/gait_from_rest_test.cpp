// A one-impact gait checked from rest (docs/model.md section 12). Reference numbers: the
// attractors of the exact stable optimum were checked against 10,000-period simulations in
// attractors_test.cpp; the orbits come from the analytic code (Solve), the motions from the
// simulator; `reached` (starts whose state at the section is the orbit's) is checked against the
// starts whose motion has the orbit's shape and closed-form mean velocity.

#include "capsubot/attract/gait_from_rest.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "capsubot/orbit/stability.hpp"
#include "capsubot/orbit/validity.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::Near;

// The 3-right/1-left motion of the exact stable optimum: 0.02440 to 4 digits (its long-run
// velocity is checked to 1e-9 in attractors_test.cpp).
constexpr double kThreeImpactVelocity = 0.0244;
constexpr double kFourDigits = 1e-4;
// A start ends on the analytic orbit when its long-run motion has the orbit's shape (period 1,
// one right impact) and mean velocity: Newton's method puts the motion within 1e-12 of its fixed
// point, and the closed form's I/tau agrees with the simulated one to about 1e-12 (orbit_test);
// another one-impact orbit of the same robot differs in speed by far more.
constexpr double kOnOrbitRelTol = 1e-8;

// The starts whose long-run motion is the analytic orbit, told by its speed (the code under test
// tells it by the state at the section: two independent criteria).
std::int64_t StartsOnOrbit(const Attractors& a, const Orbit& orbit) {
  std::int64_t n = 0;
  for (const Motion& m : a.motions) {
    n += m.status == MotionStatus::kPeriodic && m.period == 1 && m.impacts_right == 1 &&
                 m.impacts_left == 0 &&
                 std::abs(m.mean_velocity - orbit.v_mean) <= kOnOrbitRelTol * orbit.v_mean
             ? 1
             : 0;
  }
  return n;
}

bool Contains(const std::string& text, const std::string& part) {
  return text.find(part) != std::string::npos;
}

TEST(GaitFromRest, ExactStableOptimumIsHonest) {
  // The exact stable P2 optimum at T0 = 1, e = 1, margins 0: it grazes both walls and sits on
  // the fold (`capsubot optimize --problem forcing --stable --json`).
  const Params params;
  const Solution s = Solve(
      Forcing::Harmonic(0.34063197373861814, 0.06410131873607934, -3.1181183398453047), params);
  ASSERT_TRUE(s.orbit.ok());
  const GaitFromRest r = CheckGaitFromRest(s.orbit, params);
  ASSERT_TRUE(r.checked);
  ASSERT_EQ(r.attractors.starts, 64);
  // Most starts end in the 3-impact motion; the analytic orbit is reached from few or none.
  const Attractor& top = r.attractors.attractors.front();
  EXPECT_GE(top.fraction, 0.5);
  EXPECT_EQ(top.motion.impacts_right, 3);
  EXPECT_EQ(top.motion.impacts_left, 1);
  EXPECT_TRUE(Near(top.motion.mean_velocity, kThreeImpactVelocity, kFourDigits));
  EXPECT_FALSE(top.one_impact_orbit);
  EXPECT_LE(r.reached, 64 - top.starts);
  ASSERT_EQ(r.attractors.motions.size(), 64U);
  EXPECT_EQ(r.reached, StartsOnOrbit(r.attractors, s.orbit));
  EXPECT_TRUE(
      Contains(r.summary, "reached from rest in " + std::to_string(r.reached) + " of 64 starts"))
      << r.summary;
  EXPECT_TRUE(Contains(r.summary, std::to_string(top.starts) +
                                      " starts end in a motion with 3 right + 1 left impacts "
                                      "per period at mean velocity 0.0244"))
      << r.summary;
}

TEST(GaitFromRest, StableGaitWithClearanceIsReachedAndCounted) {
  // A stable valid orbit with clearance from both walls (x_min = 0.41, spectral radius 0.16):
  // the starts that end on it are exactly those of the attractor flagged as the orbit.
  Params params;
  params.T0 = 0.1;
  params.e = 0.5;
  const Solution s = Solve(Forcing::Harmonic(0.05, 0.02, -2.842), params);
  ASSERT_TRUE(s.validity.valid());
  ASSERT_TRUE(ComputeStability(s.orbit).stable);
  const GaitFromRest r = CheckGaitFromRest(s.orbit, params);
  ASSERT_TRUE(r.checked);
  ASSERT_FALSE(r.attractors.attractors.empty());
  std::int64_t flagged = 0;
  for (const Attractor& a : r.attractors.attractors) flagged += a.one_impact_orbit ? a.starts : 0;
  EXPECT_GE(r.reached, 1);
  EXPECT_EQ(r.reached, flagged);
  ASSERT_EQ(r.attractors.motions.size(), 64U);
  EXPECT_EQ(r.reached, StartsOnOrbit(r.attractors, s.orbit));
  const std::string head =
      r.reached == 64 ? "reached from rest in all 64 starts"
                      : "reached from rest in " + std::to_string(r.reached) + " of 64 starts";
  EXPECT_EQ(r.summary.rfind(head, 0), 0U) << r.summary;
}

TEST(GaitFromRest, NoOrbitIsNotChecked) {
  const Params params;
  const GaitFromRest r = CheckGaitFromRest(Orbit{}, params);
  EXPECT_FALSE(r.checked);
  EXPECT_EQ(r.reached, 0);
  EXPECT_EQ(r.attractors.starts, 0);
  EXPECT_TRUE(Contains(r.summary, "not checked")) << r.summary;
}

TEST(GaitFromRest, SummaryNamesAtMostThreeOtherMotionsAndSumsTheRest) {
  // Five one-start classes with made-up motions (the sentence is built from the numbers only).
  Attractors a;
  a.starts = 6;
  for (int k = 0; k < 5; ++k) {
    Attractor at;
    at.motion.status = MotionStatus::kPeriodic;
    at.motion.period = 1;
    at.motion.impacts_right = k + 1;
    at.motion.mean_velocity = 0.01 * (k + 1);
    at.starts = k == 0 ? 2 : 1;
    a.attractors.push_back(at);
  }
  a.labels = {0, 0, 1, 2, 3, 4};
  EXPECT_EQ(AttractorsSummary(a, 8),
            "6 starts from rest: 2 starts end in a motion with 1 right + 0 left impacts per "
            "period at mean velocity 0.01; 1 start ends in a motion with 2 right + 0 left impacts "
            "per period at mean velocity 0.02; 1 start ends in a motion with 3 right + 0 left "
            "impacts per period at mean velocity 0.03; 2 starts end in other motions");
  const std::vector<bool> on_gait = {true, true, false, false, false, false};
  EXPECT_EQ(AttractorsSummary(a, 8, on_gait)
                .rfind("reached from rest in 2 of 6 starts; 1 start "
                       "ends in a motion with 2 right",
                       0),
            0U)
      << AttractorsSummary(a, 8, on_gait);
}

}  // namespace
}  // namespace capsubot
