// The report of a periodic motion found by Newton shooting (periodic_text, periodic_json): a
// motion built here by hand (a period-2 motion with a complex pair of multipliers), so that each
// number printed is known; a motion Newton did not converge to has no verdict.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "capsubot/report/periodic_json.hpp"
#include "capsubot/report/periodic_text.hpp"
#include "report/report_text.hpp"

namespace capsubot {
namespace {

using testing::Has;
using testing::Printed;

PeriodicJobResult HandMadeMotion() {
  PeriodicJobResult r;
  r.options.robot.forcing = Forcing::Harmonic(0.5, 0.5, 1.0);
  r.options.robot.params = Params{0.75, 0.5};
  r.options.robot.alpha = 0.3;
  PeriodicMotion& m = r.motion;
  m.status = ShootingStatus::kConverged;
  m.period = 2;
  m.impacts_right = 3;
  m.impacts_left = 1;
  m.mean_velocity = 0.0125;
  m.state = PhaseState{0.5, -0.25, 0.0, 1.5};
  m.mode = SimMode::kSlideForward;
  m.dimension = 2;
  m.multipliers = {{-0.5, 0.25}, {-0.5, -0.25}};
  m.spectral_radius = std::abs(m.multipliers[0]);  // sqrt(0.3125)
  m.stable = true;
  m.distance_to_plus_one = std::abs(m.multipliers[0] - 1.0);
  m.distance_to_minus_one = std::abs(m.multipliers[0] + 1.0);
  m.distance_to_unit_circle = 1.0 - m.spectral_radius;
  m.residual = 1e-13;
  m.iterations = 4;
  return r;
}

TEST(PeriodicJsonReport, HoldsTheMotionItsMultipliersAndForce) {
  const nlohmann::json j = Printed(json::PeriodicJobJson(HandMadeMotion()));
  EXPECT_EQ(j["status"], "converged");
  EXPECT_EQ(j["period"], 2);
  EXPECT_EQ(j["impacts_right"], 3);
  EXPECT_EQ(j["impacts_left"], 1);
  EXPECT_EQ(j["mean_velocity"].get<double>(), 0.0125);
  EXPECT_EQ(j["state"]["u"].get<double>(), -0.25);
  EXPECT_EQ(j["state"]["psi"].get<double>(), 1.5);
  EXPECT_EQ(j["mode"], "slide_forward");
  ASSERT_EQ(j["multipliers"].size(), 2U);
  EXPECT_EQ(j["multipliers"][1], nlohmann::json({-0.5, -0.25}));
  EXPECT_DOUBLE_EQ(j["spectral_radius"].get<double>(), std::sqrt(0.3125));
  EXPECT_TRUE(j["stable"].get<bool>());
  EXPECT_EQ(j["iterations"], 4);
  EXPECT_EQ(j["force"]["waveform"], "sine");
  EXPECT_EQ(j["force"]["phi0"].get<double>(), 1.0);
}

TEST(PeriodicJsonReport, AMotionNotFoundHasNullNumbers) {
  PeriodicJobResult r;
  r.motion.status = ShootingStatus::kEventLimit;
  const nlohmann::json j = Printed(json::PeriodicJobJson(r));
  EXPECT_EQ(j["status"], "event_limit");
  EXPECT_TRUE(j["mean_velocity"].is_null());
  EXPECT_TRUE(j["spectral_radius"].is_null());
  EXPECT_TRUE(j["residual"].is_null());
  EXPECT_TRUE(j["multipliers"].empty());
}

TEST(PeriodicTextReport, WritesTheMotionAndTheVerdict) {
  const std::string t = text::PeriodicJobText(HandMadeMotion());
  EXPECT_TRUE(Has(t, "  force          F(phi) = 0.5 sin(phi + 1) + 0.5\n"));
  EXPECT_TRUE(Has(t, "  model          T0 = 0.75, e = 0.5, alpha = 0.3\n"));
  EXPECT_TRUE(Has(t, "  status         converged (residual 1e-13 after 4 Newton iterations)\n"));
  EXPECT_TRUE(Has(t, "  period         2: 3 right + 1 left impacts per 2 periods\n"));
  EXPECT_TRUE(Has(t, "  mean velocity  0.0125 (omega L)\n"));
  EXPECT_TRUE(Has(t, "x = 0.5, u = -0.25, v = 0 at psi = 1.5 (slide_forward)\n"));
  EXPECT_TRUE(Has(t, "  multipliers    -0.5+0.25i -0.5-0.25i   (2 free coordinates"));
  // sqrt(0.3125) = 0.55901699437 to 10 digits; |-0.5 + 0.25i - 1| = sqrt(2.3125) = 1.52 to 3
  // digits and |-0.5 + 0.25i + 1| = sqrt(0.3125) = 0.559.
  EXPECT_TRUE(Has(t,
                  "  verdict        stable (spectral radius 0.5590169944 < 1); the largest "
                  "multiplier lies 1.52 from +1 (0: a fold) and 0.559 from -1"));
}

TEST(PeriodicTextReport, OnePeriodIsSingularAndARealMultiplierHasNoImaginaryPart) {
  PeriodicJobResult r = HandMadeMotion();
  r.motion.period = 1;
  r.motion.dimension = 1;
  r.motion.multipliers = {{1.5, 0.0}};
  r.motion.spectral_radius = 1.5;
  r.motion.stable = false;
  const std::string t = text::PeriodicJobText(r);
  EXPECT_TRUE(Has(t, "impacts per 1 period\n"));
  EXPECT_TRUE(Has(t, "  multipliers    1.5   (1 free coordinates"));
  EXPECT_TRUE(Has(t, "  verdict        unstable (spectral radius 1.5 >= 1)"));
}

TEST(PeriodicTextReport, NoVerdictWithoutConvergenceAndTheScaleSaidWhenOut) {
  PeriodicJobResult r = HandMadeMotion();
  r.motion.status = ShootingStatus::kNoConvergence;
  const std::string t = text::PeriodicJobText(r);
  EXPECT_TRUE(Has(t, "  status         no_convergence (residual"));
  EXPECT_TRUE(Has(t, "  verdict        none: Newton did not converge"));
  EXPECT_EQ(t.find("stable"), std::string::npos);
  r.motion.out_of_scale = true;
  EXPECT_TRUE(Has(text::PeriodicJobText(r),
                  "  status         no_convergence (the state is out of the robot's scale"));
}

}  // namespace
}  // namespace capsubot
