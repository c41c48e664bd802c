// The continuation at its edges (docs/continuation.md, Limits): steps near the ends of the
// doubles, states out of the robot's scale, a branch of constant speed, a branch that ends at a
// wall. References: the analytic one-impact orbit (one_impact_family.hpp) and Newton shooting
// (periodic.hpp).

#include <gtest/gtest.h>

#include <cmath>

#include "capsubot/attract/periodic.hpp"
#include "capsubot/continue/continuation.hpp"
#include "capsubot/continue/parameter_branch.hpp"
#include "continue/one_impact_family.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::AfterImpact;
using testing::kA;
using testing::kPhi0;
using testing::OrbitAt;
using testing::Range;
using testing::Robot;

// The example's branch in alpha over [0.2, 0.3] with the given steps (docs/continuation.md).
Branch AlphaBranchWithSteps(double min_step, double max_step) {
  const Orbit o = OrbitAt(kA, kPhi0);
  ContinuationOptions opt = Range(0.2, 0.3, o.alpha);
  opt.min_step = min_step;
  opt.max_step = max_step;
  return ContinueBranch([](double alpha) { return Robot(alpha); }, AfterImpact(o, kPhi0), opt);
}

TEST(ContinuationEdges, StepsNearTheEndsOfTheDoublesStillFollowTheBranch) {
  // The ratio max_step / min_step overflows a double for both: the walk's bound on its attempts
  // must not (a one-point branch "the most points were reached" was the symptom).
  for (const auto& [lo, hi] : {std::pair{1e-7, 1e302}, std::pair{1e-310, 0.05}}) {
    const Branch b = AlphaBranchWithSteps(lo, hi);
    ASSERT_EQ(b.status, ContinuationStatus::kOk) << lo << " " << hi;
    EXPECT_GE(b.points.size(), 10u) << lo << " " << hi;
    EXPECT_NE(b.backward_end, BranchEnd::kMaxPoints) << lo << " " << hi;
    EXPECT_NE(b.forward_end, BranchEnd::kMaxPoints) << lo << " " << hi;
  }
}

TEST(ContinuationEdges, StatesOutOfTheRobotsScaleAreNoPeriodicMotion) {
  // At v = 1e16 the friction's change of one period (about 1) is below the state's rounding
  // (2): the map returns the state exactly, which is no periodic motion.
  const RobotModel r = Robot(OrbitAt(kA, kPhi0).alpha);
  ShootingOptions so;
  const PeriodicMotion m =
      FindPeriodicMotion(r.forcing, r.params, r.alpha, {0.5, 0.0, 1e16, 1.0}, so);
  EXPECT_NE(m.status, ShootingStatus::kConverged) << m.mean_velocity;
  // The continuation from the largest doubles: no motion, not a branch at infinity.
  const Branch b = ContinueBranch([](double alpha) { return Robot(alpha); },
                                  {0.5, 0.0, 1.7e308, 1.0}, Range(0.2, 0.3, r.alpha));
  EXPECT_EQ(b.status, ContinuationStatus::kNoMotion);
  EXPECT_TRUE(b.points.empty());
}

TEST(ContinuationEdges, BranchOfConstantSpeedHasNoSpeedExtremum) {
  // In phi0 the robot's motion is the same motion shifted in time: its mean velocity is the
  // same at every phi0 (docs/model.md section 6), so d V/ds is rounding of random sign.
  const Orbit o = OrbitAt(kA, kPhi0);
  ContinuationOptions opt = Range(-20.0, 20.0, kPhi0);
  opt.max_points = 400;
  const Branch b = ContinueParameter(Forcing::Harmonic(kA, testing::kC, kPhi0),
                                     testing::OrbitParams(), o.alpha, "phi0",
                                     AfterImpact(o, kPhi0), opt);
  ASSERT_EQ(b.status, ContinuationStatus::kOk);
  ASSERT_GE(b.points.size(), 100u);
  for (const BranchPoint& p : b.points) {
    ASSERT_TRUE(testing::RelNear(p.motion.mean_velocity, o.v_mean, 1e-9)) << p.parameter;
  }
  for (const SpecialPoint& sp : b.special_points) {
    EXPECT_NE(sp.type, SpecialPointType::kSpeedExtremum) << sp.parameter;
  }
}

}  // namespace
}  // namespace capsubot
