// The reports of one problem and of the reach problem of `capsubot optimize` (optimize_json,
// optimize_text) and its CSV tables (optimize_csv), on results built here by hand: the gain of
// a Fourier force over the harmonic optimum computed here, infinity written as null, the ladder's
// speeds against the sine's, the force table's rows and the from-rest table's.

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "capsubot/io/io.hpp"
#include "capsubot/report/optimize_csv.hpp"
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

// P3's optimum: I = 0.5 against the harmonic optimum's 0.4, a gain of 0.5 / 0.4 - 1 = 25 %.
ProblemJobResult FourierProblem() {
  ProblemJobResult pr;
  pr.problem = "fourier";
  pr.params.T0 = 0.8;
  pr.gait.margins = RobustMargins();
  pr.gait.rho_max = GaitRequirements::kInf;
  pr.result = HandMadeGait(0.5, 0.25, 0.5, 0.25);
  pr.result.solution.orbit.forcing = Forcing::Fourier(0.25, {0.125, 0.0}, {0.5, 0.0625}, -2.5);
  pr.result.baseline_I = 0.4;
  pr.result.active_constraints = {"left_wall", "force_bound"};
  pr.result.binding = {Margin::kClearanceStroke};
  return pr;
}

TEST(OptimizeJsonReport, ProblemHasItsGainCoefficientsAndRequirements) {
  const nlohmann::json j = Printed(json::OptimizeJobJson(FourierProblem()));
  EXPECT_EQ(j["problem"], "fourier");
  EXPECT_EQ(j["status"], "ok");  // the optimiser's status in place of the orbit's
  EXPECT_DOUBLE_EQ(j["gain"].get<double>(), 0.5 / 0.4 - 1.0);
  EXPECT_EQ(j["baseline_I"].get<double>(), 0.4);
  EXPECT_EQ(j["coefficients"]["c"].get<double>(), 0.25);
  EXPECT_EQ(j["coefficients"]["sin"][1].get<double>(), 0.0625);
  EXPECT_EQ(j["active_constraints"], nlohmann::json({"left_wall", "force_bound"}));
  EXPECT_EQ(j["binding"], nlohmann::json({"clearance_stroke"}));
  EXPECT_EQ(j["spectral_radius"].get<double>(), 0.5);
  EXPECT_TRUE(j["stable"].get<bool>());
  EXPECT_EQ(j["T0"].get<double>(), 0.8);
  EXPECT_EQ(j["margin_stroke"].get<double>(), 0.02);
  EXPECT_TRUE(j["rho_max"].is_null());    // infinity: no requirement
  EXPECT_TRUE(j["from_rest"].is_null());  // not checked
}

TEST(OptimizeJsonReport, ProblemWithoutAGaitHasNoGainNorStability) {
  ProblemJobResult pr = FourierProblem();
  pr.result.status = OptimizeStatus::kNoValidOrbit;
  pr.result.solution.validity.violations = 1U;
  pr.result.spectral_radius = kNaN;
  const nlohmann::json j = Printed(json::OptimizeJobJson(pr));
  EXPECT_EQ(j["status"], "no_valid_orbit");
  EXPECT_TRUE(j["gain"].is_null());
  EXPECT_FALSE(j.contains("spectral_radius"));
  EXPECT_FALSE(j["valid"].get<bool>());
}

TEST(OptimizeTextReport, ProblemWritesTheGaitInPlainTermsAndItsGain) {
  const std::string t = text::OptimizeJobText(FourierProblem());
  EXPECT_TRUE(Has(t,
                  "capsubot optimize --problem fourier: T0 = 0.8, e = 1, margins d = 0, d_s = "
                  "0.02, s = 0.02, spectral radius <= inf\n"));
  EXPECT_TRUE(Has(t, "  status           ok\n  hand-made gait\n"));
  EXPECT_TRUE(Has(t,
                  "    active           left_wall, force_bound\n"
                  "                     - the inner body just reaches the left wall\n"
                  "                     - the force uses its whole bound\n"));
  EXPECT_TRUE(Has(t, "    margins binding  clearance_stroke\n"));
  EXPECT_TRUE(Has(t, "    stability        spectral radius 0.5 -> stable: a real robot settles"));
  EXPECT_TRUE(Has(t, "    gain over P2     +25% (harmonic optimum I = 0.4)\n"));
}

TEST(OptimizeTextReport, ASpectralRadiusOnItsBoundIsSaid) {
  ProblemJobResult pr = FourierProblem();
  pr.gait.rho_max = 0.9;
  pr.result.spectral_radius = 0.9 + 1e-9;  // within the optimiser's tolerance of the bound
  EXPECT_TRUE(Has(text::OptimizeJobText(pr),
                  "spectral radius 0.9 -> on the required bound "
                  "rho_max = 0.9\n"));
  pr.result.spectral_radius = 1.25;
  EXPECT_TRUE(Has(text::OptimizeJobText(pr), "spectral radius 1.25 -> unstable"));
}

// The reach problem of a Fourier drive: its ladder K = 1 (the sine), 2, the winner K = 2.
ReachJobResult FourierReach() {
  ReachJobResult r;
  r.gait.margins = RobustMargins();
  r.gait.rho_max = 0.9;
  ReachResult sine = HandMadeReach(0.02);
  ReachResult two = HandMadeReach(0.03);
  two.drive = DriveFamily::Fourier(2);
  two.forcing = Forcing::Fourier(0.25, {0.125, 0.0}, {0.5, 0.0625}, -2.0);
  r.ladder = {sine, two};
  r.reach = two;
  return r;
}

TEST(OptimizeJsonReport, ReachHasItsDriveAndTheLadderAgainstTheSine) {
  const nlohmann::json j = Printed(json::OptimizeJobJson(FourierReach()));
  EXPECT_FALSE(j.contains("A"));  // a Fourier winner: its drive instead
  EXPECT_EQ(j["drive"]["waveform"], "fourier");
  EXPECT_EQ(j["drive"]["harmonics"], 2);
  EXPECT_EQ(j["drive"]["cos"][0].get<double>(), 0.125);
  EXPECT_DOUBLE_EQ(j["speed_ratio_to_sine"].get<double>(), 0.03 / 0.02);
  ASSERT_EQ(j["ladder"].size(), 2U);
  EXPECT_EQ(j["ladder"][0]["harmonics"], 1);
  EXPECT_DOUBLE_EQ(j["ladder"][0]["speed_ratio_to_sine"].get<double>(), 1.0);
  EXPECT_DOUBLE_EQ(j["ladder"][1]["speed_ratio_to_sine"].get<double>(), 1.5);
  EXPECT_EQ(j["rho_max"].get<double>(), 0.9);
  EXPECT_TRUE(j["seed"].is_null());  // the seed was not checked from rest
  EXPECT_EQ(j["spread"]["event_limit_starts"], 0);
  EXPECT_TRUE(j["spread"]["e_0999"].is_null());
}

TEST(OptimizeJsonReport, ReachOfTheSineWithoutWinnerHasNulls) {
  ReachJobResult r;
  r.gait.rho_max = 0.9;
  r.reach.status = OptimizeStatus::kNoValidOrbit;
  const nlohmann::json j = Printed(json::OptimizeJobJson(r));
  EXPECT_EQ(j["status"], "no_valid_orbit");
  EXPECT_TRUE(j["A"].is_null());
  EXPECT_TRUE(j["drive"].is_null());
  EXPECT_TRUE(j["attractors"].is_null());
  EXPECT_FALSE(j.contains("ladder"));
  EXPECT_FALSE(j.contains("frequency"));
}

TEST(OptimizeTextReport, ReachListsTheLadderWithTheSpeedRatio) {
  const std::string t = text::OptimizeJobText(FourierReach());
  EXPECT_TRUE(Has(t, "capsubot optimize --problem reach: T0 = 1, e = 1"));
  EXPECT_TRUE(Has(t, "  best drive by number of harmonics (max |F| <= the same bound):\n"));
  EXPECT_TRUE(Has(t, "    K = 1           mean velocity 0.02 omega L, 1 times the sine; "));
  EXPECT_TRUE(Has(t, "    K = 2           mean velocity 0.03 omega L, 1.5 times the sine; "));
}

TEST(OptimizeCsvReport, ForceTableSamplesOnePeriodFromTheImpact) {
  const Forcing f = Forcing::Harmonic(0.5, 0.25, -2.0);
  std::ostringstream out;
  text::WriteForceCsv(f, out);
  std::vector<std::string> lines;
  std::istringstream in(out.str());
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), static_cast<std::size_t>(text::kForceCsvRows) + 1);  // and the header
  EXPECT_EQ(lines[0], "phi,F");
  // phi = 0, F(0) = 0.5 sin(-2) + 0.25; the last row at phi = 2 pi.
  EXPECT_EQ(lines[1], "0," + FormatNumber(0.5 * std::sin(-2.0) + 0.25));
  EXPECT_EQ(lines.back().substr(0, lines.back().find(',')), FormatNumber(kTau));
}

TEST(OptimizeCsvReport, FromRestTableHasThePromiseAndEachAttractor) {
  MainJobResult r;
  r.robust = HandMadeGait(0.5, 0.25, 0.0625, 0.25);
  r.reach = HandMadeReach(0.02);
  r.reach.seed.from_rest.attractors = r.reach.attractors;
  // An irregular attractor: its example start's mean velocity is not the attractor's mean over
  // its starts, which is what the column holds (as the JSON and the text).
  r.reach.attractors.attractors.front().motion.mean_velocity = 0.019;
  r.reach.attractors.attractors.front().mean_velocity = 0.021;
  std::ostringstream out;
  text::WriteFromRestCsv(r, out);
  EXPECT_EQ(out.str(),
            "gait,row,mean_velocity,fraction,period,impacts_right,impacts_left,one_impact_orbit\n"
            "robust,promised," +
                FormatNumber(0.0625 / kTau) +
                ",,1,1,0,1\n"
                "robust,attractor,0.02,0.75,1,1,0,0\n"
                "reach,attractor,0.021,0.75,1,1,0,0\n");
  std::ostringstream none;
  r.robust = OptimizeResult{};  // no robust gait: no promise, no rows of its own
  text::WriteFromRestCsv(r, none);
  EXPECT_EQ(none.str().find("robust"), std::string::npos);
  EXPECT_TRUE(Has(none.str(), "reach,attractor"));
}

}  // namespace
}  // namespace capsubot
