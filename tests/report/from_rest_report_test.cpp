// What the robot reaches from rest in the text reports (from_rest_text): a gait's check in one
// line, and the fastest motion from rest on a search result built here by hand, so that each
// number printed is known; the lines of a Fourier drive and of a free T0 only when they apply.

#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "capsubot/report/from_rest_text.hpp"
#include "report/report_text.hpp"

namespace capsubot {
namespace {

using testing::Has;

ReachResult HandMadeReach() {
  ReachResult r;
  r.status = OptimizeStatus::kOk;
  r.forcing = Forcing::Harmonic(0.5, 0.25, -2.0);
  r.alpha = 0.123456789;
  r.mean_velocity = 0.0123456789;
  r.attractors.starts = 64;
  r.summary = "64 starts: 64 end in a motion with 1 right + 0 left impacts per period";
  r.spread.chatter_small = 0.0125;
  r.spread.e_0999 = 0.012;
  r.spread.max_relative_deviation = 0.0275;
  r.algorithm = "GN_DIRECT_L+LN_SBPLX";
  r.evaluations = 120;
  r.search_seconds = 1.54;
  return r;
}

TEST(FromRestTextReport, GaitCheckIsOneIndentedLine) {
  GaitFromRest fr;
  fr.summary = "reached from rest in 3 of 4 starts";
  EXPECT_EQ(text::FromRestText(fr), "    from rest        reached from rest in 3 of 4 starts\n");
  EXPECT_EQ(text::FromRestText(fr, 1), " from rest        reached from rest in 3 of 4 starts\n");
}

TEST(FromRestTextReport, ReachWritesTheWinnerAndHowItDependsOnTheSettings) {
  const std::string t = text::ReachText(HandMadeReach());
  EXPECT_TRUE(Has(t, "    force            F(phi) = 0.5 sin(phi - 2) + 0.25\n"));
  EXPECT_TRUE(Has(t, "    inner mass ratio alpha = m2/(m1+m2) = 0.12346\n"));  // 5 digits
  EXPECT_TRUE(Has(t, "    speed from rest  mean velocity 0.0123457 omega L (over 64 starts)\n"));
  EXPECT_TRUE(Has(t, "    from rest        64 starts: 64 end in a motion"));
  // The re-runs computed (chatter*100 is NaN: left out) and the largest change to 2 digits.
  EXPECT_TRUE(Has(t,
                  "    settings         chatter/100 0.0125, e = 0.999 0.012 (largest relative "
                  "change 0.028)\n"));
  EXPECT_TRUE(Has(t,
                  "    solver           GN_DIRECT_L+LN_SBPLX (120 from-rest evaluations, 1.5 s "
                  "search, status ok)\n"));
  EXPECT_EQ(t.find("force bound"), std::string::npos);  // a sine: A + c is its bound
  EXPECT_EQ(t.find("frequency"), std::string::npos);    // T0 fixed
}

TEST(FromRestTextReport, ReachOfAFourierDriveWithFreeT0HasItsBoundAndSpeed) {
  ReachResult r = HandMadeReach();
  r.drive = DriveFamily::Fourier(2);
  r.forcing = Forcing::Fourier(0.25, {0.0, 0.125}, {0.5, 0.0}, 0.0);
  r.max_abs_force = 0.75;
  r.force_bound = 0.8;
  r.T0 = 0.25;
  r.physical_speed = r.mean_velocity / std::sqrt(r.T0);  // 0.0246913578
  const std::string t = text::ReachText(r);
  EXPECT_TRUE(Has(t, "    force bound      max |F| = 0.75 <= 0.8 (exact: F at the zeros of F')\n"));
  EXPECT_TRUE(Has(t, "    frequency        T0 = 0.25: speed 0.0246914 sqrt(mu g L)"));
}

TEST(FromRestTextReport, ReachSaysNoReRunAndTheStartsAtTheWorkBound) {
  ReachResult r = HandMadeReach();
  r.spread = ReachSpread{};
  // No re-run: no change to name, "-" as every missing number of the text.
  EXPECT_TRUE(Has(text::ReachText(r),
                  "    settings         no re-run (largest relative change "
                  "-)\n"));
  r.spread.chatter_large = 0.0125;
  r.spread.event_limit_starts = 3;
  r.spread.max_relative_deviation = HUGE_VAL;  // a re-run at the work bound
  EXPECT_TRUE(Has(text::ReachText(r),
                  "chatter*100 0.0125; 3 starts of the re-runs hit the work "
                  "bound (null above) (largest relative change inf)"));
}

TEST(FromRestTextReport, ReachWithoutAWinnerGivesItsMessage) {
  ReachResult r;
  r.message = "every candidate had an event_limit start";
  EXPECT_EQ(text::ReachText(r), "    none: every candidate had an event_limit start\n");
}

}  // namespace
}  // namespace capsubot
