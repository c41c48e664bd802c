// The command line of the long-run motions: `capsubot attractors` (and later periodic, basins,
// bifurcation). Reference numbers come from the library tests (tests/attract/), which check
// them against independent long simulations.

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::ReadFile;

using testing::Near;
using testing::RunCli;

// The exact stable P2 optimum at T0 = 1, e = 1 (`optimize --problem forcing --stable --json`).
const std::string kOptimum =
    "--A 0.34063197373861814 --c 0.06410131873607934 --phi0 -3.1181183398453047 --T0 1 --e 1 "
    "--alpha 0.6435592358295166";
// A stable one-impact orbit with clearance (`solve ... --stability`: spectral radius 0.16).
const std::string kSmallOrbit =
    "--A 0.05 --c 0.02 --phi0 -2.842 --T0 0.1 --e 0.5 --alpha 0.2792869076315278";

nlohmann::json Json(const std::string& args) {
  const auto r = RunCli(args);
  EXPECT_EQ(r.status, 0) << args << "\n" << r.out;
  return nlohmann::json::parse(r.out);
}

TEST(AttractorsCli, StableOptimumEndsInTheThreeImpactMotionFromEveryStart) {
  const auto j = Json("attractors " + kOptimum + " --starts 2x3 --json");
  EXPECT_EQ(j["starts"], 6);
  ASSERT_EQ(j["attractors"].size(), 1U);
  const auto& a = j["attractors"][0];
  EXPECT_EQ(a["status"], "periodic");
  EXPECT_EQ(a["period"], 1);
  EXPECT_EQ(a["impacts_right"], 3);
  EXPECT_EQ(a["impacts_left"], 1);
  EXPECT_EQ(a["fraction"], 1.0);
  EXPECT_EQ(a["one_impact_orbit"], false);
  EXPECT_TRUE(Near(a["mean_velocity"].get<double>(), 0.0244, 1e-4));
  EXPECT_TRUE(Near(j["mean_velocity"].get<double>(), a["mean_velocity"].get<double>(), 1e-12));
  EXPECT_EQ(a["example_start"]["x0"], 0.25);
  EXPECT_EQ(a["example_start"]["psi"], 0.0);
}

TEST(AttractorsCli, MarksTheAnalyticOrbitAndSortsByFraction) {
  const auto j = Json("attractors " + kSmallOrbit + " --json");
  ASSERT_GE(j["attractors"].size(), 1U);
  int marked = 0;
  double last = 2.0;
  for (const auto& a : j["attractors"]) {
    EXPECT_LE(a["fraction"].get<double>(), last);
    last = a["fraction"].get<double>();
    if (a["one_impact_orbit"].get<bool>()) {
      ++marked;
      EXPECT_EQ(a["period"], 1);
      EXPECT_TRUE(Near(a["mean_velocity"].get<double>(), 0.02017805287097631, 1e-9));  // solve
    }
  }
  EXPECT_EQ(marked, 1);
}

TEST(AttractorsCli, TextOutputNamesTheMotion) {
  const auto r = RunCli("attractors " + kOptimum + " --starts 1x2");
  EXPECT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("period 1: 3 right + 1 left impacts per period"), std::string::npos)
      << r.out;
}

TEST(AttractorsCli, BadInputIsOneLineNamingTheParameter) {
  auto r = RunCli("attractors " + kOptimum + " --starts 8by8 2>&1");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out,
            "capsubot attractors: error: --starts = 8by8 is invalid: expected NXxNPSI, two whole "
            "numbers from 1 to 100000 (e.g. 8x8)\n");
  for (const char* starts : {"' 2x2'", "+2x2", "2x-2", "2x2e0"}) {  // digits only
    r = RunCli("attractors " + kOptimum + " --starts " + starts + " 2>&1");
    EXPECT_EQ(r.status, 2) << starts;
    EXPECT_NE(r.out.find("is invalid: expected NXxNPSI, two whole numbers"), std::string::npos)
        << r.out;
  }
  r = RunCli("attractors " + kOptimum + " --record 3 2>&1");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out,
            "capsubot attractors: error: --record = 3 is invalid: expected 2 * max_period = 16 <= "
            "record <= 1e7 periods\n");
}

TEST(PeriodicCli, FromRestFindsTheThreeImpactMotionWithItsMultipliers) {
  const auto j = Json("periodic " + kOptimum + " --from-rest 0.5,1 --json");
  EXPECT_EQ(j["status"], "converged");
  EXPECT_EQ(j["period"], 1);
  EXPECT_EQ(j["impacts_right"], 3);
  EXPECT_EQ(j["impacts_left"], 1);
  EXPECT_LE(j["residual"].get<double>(), 1e-12);
  EXPECT_TRUE(Near(j["mean_velocity"].get<double>(), 0.0244, 1e-4));
  ASSERT_EQ(j["multipliers"].size(), 2U);
  EXPECT_EQ(j["multipliers"][0].size(), 2U);  // [re, im]
  EXPECT_EQ(j["stable"], true);
  for (const char* key : {"x", "u", "v", "psi"}) EXPECT_TRUE(j["state"].contains(key)) << key;
}

TEST(PeriodicCli, FromAStateNearTheOneImpactOrbitConvergesToIt) {
  // Near the post-impact state of the orbit (solve: u = 0.41620, v_plus = 0.17436, e = 0.5).
  const auto j = Json("periodic " + kSmallOrbit + " --x0 1 --u0 -0.2 --v0 0.17 --psi 0 --json");
  EXPECT_EQ(j["status"], "converged");
  EXPECT_EQ(j["period"], 1);
  EXPECT_EQ(j["impacts_right"], 1);
  EXPECT_TRUE(Near(j["mean_velocity"].get<double>(), 0.02017805287097631, 1e-10));
  // solve --stability: 0.152295106379941 +- 0.0488451050716622 i
  EXPECT_TRUE(Near(j["multipliers"][0][0].get<double>(), 0.152295106379941, 1e-8));
}

TEST(PeriodicCli, StateOutOfTheRobotsScaleIsSaidSo) {
  // At v = 1e16 a period's change of the state is below its rounding: the map returns the state
  // exactly, which is no periodic motion and no residual worth printing.
  const auto r = RunCli("periodic " + kSmallOrbit + " --x0 0.5 --u0 0 --v0 1e16 --psi 1 2>&1");
  EXPECT_NE(r.out.find("  status         no_convergence (the state is out of the robot's scale"),
            std::string::npos)
      << r.out;
  EXPECT_EQ(r.out.find("residual"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("verdict        none"), std::string::npos) << r.out;
}

TEST(PeriodicCli, StartMustBeComplete) {
  auto r = RunCli("periodic " + kSmallOrbit + " --x0 1 2>&1");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out,
            "capsubot periodic: error: the start is missing: give all of --x0, --u0, --v0, --psi "
            "(or --from-rest X0,PSI)\n");
  r = RunCli("periodic " + kSmallOrbit + " --from-rest 0.5 2>&1");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out,
            "capsubot periodic: error: --from-rest = 0.5 is invalid: expected X0,PSI (two "
            "numbers, e.g. 0.5,1)\n");
}

TEST(BasinsCli, LabelsEveryStartByItsAttractorTheSameForAnyThreadCount) {
  // The small orbit's robot has two attractors from rest: a period-12 motion (25 right impacts
  // per 12 periods) and the one-impact orbit (`attractors --max-period 30 --transient 2000`).
  const std::string a = testing::TempPath("basins_1.csv");
  const std::string b = testing::TempPath("basins_2.csv");
  const std::string common =
      "basins " + kSmallOrbit + " --max-period 16 --transient 1000 --starts 8x6 --json";
  const auto j = Json(common + " --threads 1 -o " + a);
  Json(common + " --threads 2 -o " + b);
  const std::string text = ReadFile(a);
  EXPECT_EQ(text, ReadFile(b));
  const testing::CsvLines csv = testing::SplitCsv(text);
  EXPECT_EQ(csv.comments.size(), 1U);  // the provenance (provenance_cli_test.cpp)
  EXPECT_EQ(csv.header, "x0,psi,attractor,period,impacts_right,impacts_left,mean_velocity,status");
  int rows = 0, periods[2] = {0, 0};
  for (const std::string& line : csv.rows) {
    ++rows;
    if (line.find(",1,1,0,") != std::string::npos) ++periods[0];    // period 1, 1 right, 0 left
    if (line.find(",12,25,0,") != std::string::npos) ++periods[1];  // period 12
  }
  EXPECT_EQ(rows, 48);
  EXPECT_GT(periods[0], 0);
  EXPECT_GT(periods[1], 0);
  EXPECT_EQ(periods[0] + periods[1], 48);
  ASSERT_EQ(j["attractors"].size(), 2U);
  EXPECT_EQ(j["starts"], 48);
}

TEST(BasinsCli, BadPlaneIsNamedAndNoFileIsWritten) {
  const std::string path = testing::TempPath("basins_bad.csv");
  const auto r = RunCli("basins " + kSmallOrbit + " --plane x0-v0 -o " + path + " 2>&1");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out,
            "capsubot basins: error: --plane = x0-v0 is invalid: expected x0-psi or x0-u0\n");
  EXPECT_FALSE(std::ifstream(path).good());
}

TEST(BifurcationCli, StepsAFourierCoefficientAndNamesOneTheForceDoesNotHave) {
  // The optimum's force as a two-harmonic series (b_1 = A, b_2 = 0.02), a_2 stepped over three
  // values up and down: one summary row per value and direction, every one a classified motion
  // (the library test checks such rows against direct simulations of the same force).
  const std::string force =
      "--c 0.06410131873607934 --sin 0.34063197373861814,0.02 --cos 0,0 --phi0 "
      "-3.1181183398453047 --T0 1 --e 1 --alpha 0.6435592358295166";
  const std::string impacts = testing::TempPath("bifurcation_a2.csv");
  const std::string summary = testing::TempPath("bifurcation_a2_summary.csv");
  const auto r =
      RunCli("bifurcation " + force + " --param a2 --from -0.03 --to 0.03 --steps 3 -o " + impacts +
             " --summary " + summary + " --no-analytic");
  EXPECT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("bifurcation diagram over a2 = -0.03 .. 0.03 (3 values, both)"),
            std::string::npos)
      << r.out;
  const testing::CsvLines csv = testing::ReadCsv(summary);
  EXPECT_EQ(csv.comments.size(), 1U);  // the provenance (provenance_cli_test.cpp)
  EXPECT_EQ(csv.header.rfind("param,direction,period,", 0), 0U) << csv.header;
  int rows = 0;
  for (const std::string& line : csv.rows) {
    ++rows;
    EXPECT_TRUE(line.rfind("-0.03,", 0) == 0 || line.rfind("0,", 0) == 0 ||
                line.rfind("0.03,", 0) == 0)
        << line;
  }
  EXPECT_EQ(rows, 6);
  const std::string bad = testing::TempPath("bifurcation_a3.csv");
  const auto e =
      RunCli("bifurcation " + force + " --param a3 --from 0 --to 0.1 -o " + bad + " 2>&1");
  EXPECT_EQ(e.status, 2);
  EXPECT_EQ(e.out,
            "capsubot bifurcation: error: parameter = a3 is invalid for this force: expected a_k "
            "or b_k with 1 <= k <= K = 2, its harmonics\n");
  EXPECT_FALSE(std::ifstream(bad).good());
}

// The values stepped are the decimals asked for: 0.1 + 0.4 x 2/4 is 0.30000000000000004 in
// doubles, the grid's middle value is 0.3 (capsubot::GridValue, the one rule of every grid).
TEST(BifurcationCli, SteppedValuesAreTheDecimalsAsked) {
  const std::string summary = testing::TempPath("bifurcation_values_summary.csv");
  const std::string impacts = testing::TempPath("bifurcation_values.csv");
  const auto r = RunCli("bifurcation " + kSmallOrbit +
                        " --param T0 --from 0.1 --to 0.5 --steps 5 --direction up --transient 20 "
                        "--record 20 --no-analytic -o " +
                        impacts + " --summary " + summary);
  ASSERT_EQ(r.status, 0) << r.out;
  std::vector<std::string> values;
  for (const std::string& line : testing::ReadCsv(summary).rows) {
    values.push_back(line.substr(0, line.find(',')));
  }
  ASSERT_FALSE(values.empty());
  values.erase(std::unique(values.begin(), values.end()), values.end());
  EXPECT_EQ(values, (std::vector<std::string>{"0.1", "0.2", "0.3", "0.4", "0.5"}));
}

}  // namespace
}  // namespace capsubot
