// `capsubot solve` end to end: JSON keys, trajectory file, help, and every bad-input path
// (one line naming the parameter, its value and the rule; exit status 2; no file left).

#include <gtest/gtest.h>

#include <cstdio>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "capsubot/orbit/orbit_energy.hpp"
#include "capsubot/orbit/validity.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::RunCli;

const std::string kExample = "solve --A 0.5 --c 0.5 --phi0 -2.944899971002";

TEST(SolveCli, JsonHoldsEveryKeyAndMatchesTheLibrary) {
  const auto r = RunCli(kExample + " --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"A", "c", "phi0", "T0", "e", "phi1", "alpha", "u", "v_plus", "I",
                          "v_mean", "x_min", "x_max", "valid", "violations"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  const Solution s = Solve(Forcing::Harmonic(0.5, 0.5, -2.944899971002), Params{});
  EXPECT_DOUBLE_EQ(j["phi1"].get<double>(), s.orbit.phi1);  // JSON doubles round-trip
  EXPECT_DOUBLE_EQ(j["alpha"].get<double>(), s.orbit.alpha);
  EXPECT_DOUBLE_EQ(j["I"].get<double>(), s.orbit.I);
  EXPECT_FALSE(j["valid"].get<bool>());
  EXPECT_EQ(j["violations"], nlohmann::json::array({"left_wall"}));
  EXPECT_TRUE(j["x_max"].is_null());  // no interior maximum: the quantity does not exist
}

TEST(SolveCli, JsonHoldsTheEnergyBudgetOfTheLibrary) {
  const auto r = RunCli("solve --A 0.05 --c 0.02 --phi0 -2.5 --T0 0.1 --e 0.5 --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out).at("energy");
  const Energy en =
      OrbitEnergy(ComputeOrbit(Forcing::Harmonic(0.05, 0.02, -2.5), Params{0.1, 0.5}));
  EXPECT_DOUBLE_EQ(j.at("motor_work").get<double>(), en.motor_work);
  EXPECT_DOUBLE_EQ(j.at("motor_work_positive").get<double>(), en.motor_work_positive);
  EXPECT_DOUBLE_EQ(j.at("friction_loss").get<double>(), en.friction_loss);
  EXPECT_DOUBLE_EQ(j.at("impact_loss").get<double>(), en.impact_loss);
  const auto table = RunCli("solve --A 0.05 --c 0.02 --phi0 -2.5 --T0 0.1 --e 0.5");
  EXPECT_NE(table.out.find("motor work"), std::string::npos) << table.out;
  EXPECT_NE(table.out.find("friction"), std::string::npos) << table.out;
}

TEST(SolveCli, MissingOrbitIsNullAndStillExitsZero) {
  const auto r = RunCli("solve --A 0.2 --c 0.03 --phi0 0 --json");
  ASSERT_EQ(r.status, 0);
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["alpha"].is_null());
  EXPECT_TRUE(j["I"].is_null());
  EXPECT_EQ(j["violations"], nlohmann::json::array({"mass_ratio"}));
  EXPECT_TRUE(j["energy"]["motor_work"].is_null());
  EXPECT_TRUE(j["energy"]["impact_loss"].is_null());
}

TEST(SolveCli, FourierForceIsAccepted) {
  const auto r = RunCli(
      "solve --c 0.02 --cos 0.01,0,0.005 --sin 0.04,0.01,0 --phi0 -2.6 "
      "--T0 0.1 --e 0.7 --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_TRUE(j["A"].is_null());
  EXPECT_EQ(j["sin"], nlohmann::json::array({0.04, 0.01, 0.0}));
  EXPECT_TRUE(j["alpha"].is_number());
}

TEST(SolveCli, TableIsReadable) {
  const auto r = RunCli(kExample);
  ASSERT_EQ(r.status, 0);
  EXPECT_NE(r.out.find("phi1   = 2.748207288"), std::string::npos) << r.out;
  EXPECT_NE(r.out.find("violated left_wall"), std::string::npos) << r.out;
}

TEST(SolveCli, TrajectoryCsvCoversOnePeriod) {
  const auto path = testing::TempPath("capsubot_solve_traj.csv");
  const auto r = RunCli(
      "solve --A 0.05 --c 0.02 --phi0 -2.5 --T0 0.1 --e 0.5 --samples 11 "
      "--trajectory " +
      path.string());
  ASSERT_EQ(r.status, 0) << r.out;
  const testing::CsvLines csv = testing::ReadCsv(path);
  EXPECT_EQ(csv.comments.size(), 1U);  // the provenance (provenance_cli_test.cpp)
  EXPECT_EQ(csv.header, "phi,x,u,v");
  ASSERT_EQ(csv.rows.size(), 11U);
  const std::string& last = csv.rows.back();
  EXPECT_EQ(last.substr(0, last.find(',')), "6.283185307179586");  // tau, shortest round-trip
  std::filesystem::remove(path);
}

TEST(SolveCli, HelpExplainsEveryOption) {
  const auto r = RunCli("solve --help");
  ASSERT_EQ(r.status, 0);
  for (const char* opt : {"--A", "--c", "--phi0", "--sin", "--cos", "--T0", "--e", "--margin",
                          "--json", "--trajectory", "--samples"}) {
    EXPECT_NE(r.out.find(opt), std::string::npos) << opt;
  }
  EXPECT_NE(r.out.find("--T0 FLOAT=1"), std::string::npos);  // defaults are shown
}

struct BadInput {
  const char* args;
  const char* message;
  friend void PrintTo(const BadInput& b, std::ostream* os) { *os << b.args; }
};

class SolveCliBadInput : public ::testing::TestWithParam<BadInput> {};

TEST_P(SolveCliBadInput, OneLineNamingParameterValueAndRuleExitTwoNoFile) {
  const auto path = testing::TempPath("capsubot_bad_input.csv");
  const auto r = RunCli(std::string(GetParam().args) + " --trajectory " + path.string() + " 2>&1");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out, std::string(GetParam().message) + "\n");
  EXPECT_FALSE(std::filesystem::exists(path));
}

INSTANTIATE_TEST_SUITE_P(
    Inputs, SolveCliBadInput,
    ::testing::Values(
        BadInput{"solve --A 0.5 --c 0.5 --phi0 1 --e 1.3",
                 "capsubot solve: error: restitution e = 1.3 is invalid: expected 0 <= e <= 1"},
        BadInput{"solve --A 0.5 --c 0.5 --phi0 1 --e nan",
                 "capsubot solve: error: --e = nan is invalid: expected a finite number"},
        BadInput{"solve --A 0.5 --c 0.5 --phi0 1 --T0 0",
                 "capsubot solve: error: friction bound T0 = 0 is invalid: expected a finite "
                 "T0 > 0"},
        BadInput{"solve --A 0.5 --c 0.5 --phi0 1 --T0 inf",
                 "capsubot solve: error: --T0 = inf is invalid: expected a finite number"},
        BadInput{"solve --A -0.5 --c 0.5 --phi0 1",
                 "capsubot solve: error: A = -0.5 is invalid: expected A >= 0"},
        BadInput{"solve --A 0.5 --c nan --phi0 1",
                 "capsubot solve: error: --c = nan is invalid: expected a finite number"},
        BadInput{"solve --A 0.5 --c 0.5 --phi0 inf",
                 "capsubot solve: error: --phi0 = inf is invalid: expected a finite number"},
        BadInput{"solve --A 0.5 --c 0.5 --phi0 1 --margin 0.5",
                 "capsubot solve: error: margin d = 0.5 is invalid: expected 0 <= d < 0.5"},
        BadInput{"solve --A abc --c 0.5 --phi0 1",
                 "capsubot solve: error: --A = abc is invalid: expected a decimal number such as "
                 "0.5, -2 or 1e-3 (no spaces, no hex)"},
        BadInput{"solve --A 0.5 --c 0.5 --phi0 1 --frobnicate",
                 "capsubot solve: error: The following argument was not expected: --frobnicate "
                 "(see capsubot solve --help)"},
        BadInput{"solve --A 0.5 --c 0.5",
                 "capsubot solve: error: --phi0 is missing: give the impact phase phi0 "
                 "[rad]"},
        BadInput{"solve --A 0.5 --c 0.5 --phi0 1 --samples 1",
                 "capsubot solve: error: --samples = 1 is invalid: expected an integer 2 <= n <= "
                 "10000000"},
        BadInput{"solve --c 0.5 --sin 1,,2",
                 "capsubot solve: error: --sin = 1,,2 is invalid: expected comma-separated "
                 "numbers (element 2 is '')"},
        BadInput{"solve --c 0.5 --sin 0.1,0.2 --cos 0.1,x",
                 "capsubot solve: error: --cos = 0.1,x is invalid: expected comma-separated "
                 "numbers (element 2 is 'x')"},
        BadInput{"solve --c 0.5 --sin 0.1,0.2 --cos 0.1",
                 "capsubot solve: error: Fourier coefficients: 1 cosine and 2 sine terms given: "
                 "expected as many of each"}));

TEST(SolveCli, UnwritableTrajectoryIsAnError) {
  const auto r = RunCli(kExample + " --trajectory /nonexistent-dir/t.csv 2>&1");
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.out,
            "capsubot solve: error: --trajectory /nonexistent-dir/t.csv cannot be written: No "
            "such file or directory\n");
}

}  // namespace
}  // namespace capsubot

namespace capsubot {
namespace {

TEST(SolveCli, StabilityChecksTheOrbitFromRest) {
  // A stable orbit with clearance (spectral radius 0.16): reached from rest by some starts.
  const auto r = testing::RunCli(
      "solve --A 0.05 --c 0.02 --T0 0.1 --e 0.5 --phi0 -2.842 --stability --json "
      "--from-rest-starts 4x4");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  const auto& fr = j["from_rest"];
  EXPECT_EQ(fr["starts"], 16);
  EXPECT_GE(fr["reached"].get<int>(), 1);
  int on_orbit = 0;
  for (const auto& a : fr["attractors"]) {
    if (a["one_impact_orbit"].get<bool>()) on_orbit += a["starts"].get<int>();
  }
  EXPECT_EQ(fr["reached"].get<int>(), on_orbit);
  EXPECT_EQ(fr["summary"].get<std::string>().rfind("reached from rest in", 0), 0U);
}

}  // namespace
}  // namespace capsubot
