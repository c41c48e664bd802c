// The report of the main job of `capsubot optimize` (optimize_text, optimize_json): its parts on
// results built here by hand, so that each number printed is known: the paper's problem without
// a valid gait and the T0 at which its orbit would fit (computed here), the robust gait against
// the wall-grazing optimum, which gait to build, and the notes and nulls of the JSON.

#include <gtest/gtest.h>

#include <string>

#include "capsubot/report/optimize_json.hpp"
#include "capsubot/report/optimize_text.hpp"
#include "report/optimize_results.hpp"
#include "report/report_text.hpp"

namespace capsubot {
namespace {

using testing::HandMadeGait;
using testing::HandMadeReach;
using testing::Has;
using testing::Printed;

// P1 without a valid gait (only the left wall broken: the inner body would reach x = -0.25), the
// robust gait (I = 0.0625) checked from rest, the reach winner, the exact optimum (I = 0.125).
MainJobResult HandMadeMainJob() {
  MainJobResult r;
  r.params.T0 = 0.8;
  r.gait.margins = RobustMargins();
  r.gait.force_bound = 0.8;
  r.gait.rho_max = 0.9;
  r.paper = HandMadeGait(0.4, 0.4, 0.25, 0.5);
  r.paper.status = OptimizeStatus::kNoValidOrbit;
  r.paper.solution.validity.violations = 1U << static_cast<unsigned>(Condition::kLeftWall);
  r.paper.solution.validity.x_min = -0.25;
  r.robust = HandMadeGait(0.5, 0.25, 0.0625, 0.25);
  r.reach = HandMadeReach(0.02);
  r.reach.robust_to_settings = false;
  r.reach.seed.from_rest.checked = true;
  r.reach.seed.from_rest.attractors = r.reach.attractors;
  r.reach.seed.from_rest.attractors.mean_velocity = 0.005;
  r.reach.seed.from_rest.reached = 16;
  r.reach.seed.from_rest.summary = "reached from rest in 16 of 64 starts";
  r.fastest = HandMadeGait(0.6, 0.2, 0.125, 0.3);
  r.stable = OptimizeResult{};
  r.stable.message = "no stable gait";
  return r;
}

TEST(OptimizeMainTextReport, PaperWithoutAGaitSaysUpToWhichT0ItsOrbitFits) {
  const std::string t = text::OptimizeJobText(HandMadeMainJob());
  EXPECT_TRUE(Has(t, "model: T0 = 0.8 (friction bound mu g/(omega^2 L)), e = 1 (restitution)\n"));
  EXPECT_TRUE(
      Has(t,
          "clearance >= max(d = 0, d_s = 0.02 x stroke), stick margin s = 0.02, spectral radius "
          "<= 0.9\n"));
  EXPECT_TRUE(Has(t, "c = A = T0/2 = 0.4,\n"));
  EXPECT_TRUE(Has(t, "   Result: NO valid gait (status no_valid_orbit)."));
  EXPECT_TRUE(Has(t, "Nearest to valid: phi0 = -2.5, I = 0.25, violating\n   left_wall.\n"));
  // x_min = -0.25: the orbit scaled by k fits when k (1 - x_min) <= 1, T0 <= 0.8 / 1.25 = 0.64.
  EXPECT_TRUE(Has(t, "would have to reach x = -0.25 (the shell spans 0..1)"));
  EXPECT_TRUE(Has(t, "orbit would fit for T0 <= 0.64 (a shorter shell"));
}

TEST(OptimizeMainTextReport, ComparesTheRobustGaitWithTheExactOptimum) {
  const std::string t = text::OptimizeJobText(HandMadeMainJob());
  EXPECT_TRUE(
      Has(t, "A + c <= 0.8, with the margins\n   above; checked from rest on 64 starts.\n"));
  EXPECT_TRUE(Has(t, "    from rest        reached from rest in 16 of 64 starts\n"));
  EXPECT_TRUE(Has(t,
                  "   The fastest stable gait (spectral radius <= 1, docs/model.md section "
                  "8):\n   Result: none found (no stable gait)\n"));
  // 0.0625 / 0.125 = 50.0 %.
  EXPECT_TRUE(Has(t,
                  "In short: the fastest robust gait moves 0.0625 L per period with inner mass "
                  "ratio 0.25\n(50.0% of the exact, wall-grazing optimum 0.125 L per period; "
                  "margins binding: none).\n"));
  EXPECT_EQ(t.find("\n4. "), std::string::npos);  // no drive ladder
}

TEST(OptimizeMainTextReport, AdviceNamesTheReachWinnerAndItsOdds) {
  const std::string t = text::OptimizeJobText(HandMadeMainJob());
  EXPECT_TRUE(Has(t,
                  "\nWhich to build:\n  the motion of 3 (A = 0.5, c = 0.25, alpha = 0.25): from "
                  "rest the robot moves at 0.02 omega L\n  on average over the starts; 75 % of "
                  "the starts from rest end in its most common motion.\n"));
  EXPECT_TRUE(Has(t, "  Caution: under other numerical settings"));
  // The robust gait's promise v_mean = 0.0625 / 2 pi = 0.009947 (4 digits), from rest 0.005.
  EXPECT_TRUE(Has(t,
                  "  The robust gait (2) promises 0.009947 omega L, but from rest the robot "
                  "averages\n  0.005 omega L with it (16 of 64 starts end on it).\n"));
  MainJobResult seed = HandMadeMainJob();
  seed.reach.seed_won = true;
  EXPECT_TRUE(Has(text::OptimizeJobText(seed), "  the robust gait (2): it is also the fastest"));
  MainJobResult none = HandMadeMainJob();
  none.reach = ReachResult{};
  EXPECT_TRUE(Has(text::OptimizeJobText(none),
                  "  no motion from rest could be checked: see the messages above.\n"));
}

TEST(OptimizeMainJsonReport, HoldsEachResultWithItsNoteAndNullsForWhatDidNotRun) {
  const nlohmann::json j = Printed(json::OptimizeJobJson(HandMadeMainJob()));
  EXPECT_EQ(j["T0"].get<double>(), 0.8);
  EXPECT_EQ(j["rho_max"].get<double>(), 0.9);
  EXPECT_EQ(j["force_bound"].get<double>(), 0.8);
  EXPECT_EQ(j["paper"]["problem"], "phase");
  EXPECT_EQ(j["paper"]["status"], "no_valid_orbit");
  EXPECT_EQ(j["paper"]["violations"], nlohmann::json({"left_wall"}));
  EXPECT_TRUE(Has(j["paper"]["note"].get<std::string>(), "P1:"));
  EXPECT_EQ(j["robust"]["I"].get<double>(), 0.0625);
  EXPECT_EQ(j["robust"]["from_rest"]["reached"], 16);
  EXPECT_EQ(j["reach"]["mean_velocity"].get<double>(), 0.02);
  EXPECT_EQ(j["reach"]["A"].get<double>(), 0.5);
  EXPECT_TRUE(j["reach"]["robustness"].is_null());  // not continued
  EXPECT_TRUE(j["robustness"].is_null());
  EXPECT_TRUE(j["drives"].empty());
  EXPECT_EQ(j["pulse"]["status"], "not_run");
  EXPECT_EQ(j["fastest"]["I"].get<double>(), 0.125);
  EXPECT_EQ(j["fastest_stable"]["status"], "not_run");
  EXPECT_FALSE(j["fastest_stable"]["valid"].get<bool>());
}

}  // namespace
}  // namespace capsubot
