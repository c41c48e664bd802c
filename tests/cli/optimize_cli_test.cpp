// `capsubot optimize`: the main job and the single problems through the built program.

#include <gtest/gtest.h>
#include <unistd.h>

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>

#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::RunCli;

std::string TempPath(const std::string& name) {
  return "/tmp/capsubot_optimize_cli_" + std::to_string(::getpid()) + "_" + name;
}

// Reduced from-rest settings so the main job and the reach problem run quickly.
const std::string kQuickReach =
    " --from-rest-starts 2x2 --reach-starts 2x2 --reach-evaluations 10 "
    "--reach-local-evaluations 5 --hops 2 --starts 3";

TEST(OptimizeCli, MainJobWritesTheOutputFileAndPrintsTheSameObject) {
  const std::string path = TempPath("optimum.json");
  const auto r = RunCli("optimize --json --output " + path + kQuickReach);
  ASSERT_EQ(r.status, 0) << r.out;
  const auto printed = nlohmann::json::parse(r.out);
  std::ifstream in(path);
  ASSERT_TRUE(in.good()) << path;
  const auto written = nlohmann::json::parse(in);
  std::remove(path.c_str());
  EXPECT_EQ(printed, written);
  // The paper's problem at the paper's T0 = 1 has no valid orbit (docs/model.md section 6).
  EXPECT_EQ(written["paper"]["status"], "no_valid_orbit");
  EXPECT_EQ(written["paper"]["violations"], nlohmann::json({"left_wall"}));
  // The robust gait: today's gait keys, spectral radius <= 0.9, and its check from rest.
  const auto& robust = written["robust"];
  EXPECT_EQ(robust["status"], "ok");
  for (const char* key : {"A", "c", "phi0", "alpha", "I", "v_mean", "x_min", "x_max",
                          "spectral_radius", "from_rest"}) {
    EXPECT_TRUE(robust.contains(key)) << key;
  }
  EXPECT_LE(robust["spectral_radius"].get<double>(), 0.9 + 1e-9);
  const auto& from_rest = robust["from_rest"];
  EXPECT_EQ(from_rest["starts"], 4);
  for (const char* key :
       {"attractors", "mean_velocity", "event_limit_starts", "reached", "summary"}) {
    EXPECT_TRUE(from_rest.contains(key)) << key;
  }
  EXPECT_LE(from_rest["reached"].get<int>(), 4);
  // The fastest motion from rest: never slower from rest than the robust gait.
  const auto& reach = written["reach"];
  for (const char* key : {"A", "c", "alpha", "mean_velocity", "attractors", "spread", "seed"}) {
    EXPECT_TRUE(reach.contains(key)) << key;
  }
  EXPECT_EQ(reach["attractors"]["starts"], 4);
  EXPECT_GE(reach["mean_velocity"].get<double>(), from_rest["mean_velocity"].get<double>());
  EXPECT_EQ(reach["seed"]["mean_velocity_from_rest"], from_rest["mean_velocity"]);
}

TEST(OptimizeCli, MainJobSummarySaysWhatTheRobotReachesAndWhichToBuild) {
  const std::string path = TempPath("summary.json");
  const auto r = RunCli("optimize --output " + path + kQuickReach);
  std::remove(path.c_str());
  ASSERT_EQ(r.status, 0) << r.out;
  for (const char* text : {"NO valid gait", "fastest robust one-impact gait", "inner mass ratio",
                           "shell lengths per period", "left_wall", "reached from rest in",
                           "fastest motion from rest", "Which to build"}) {
    EXPECT_NE(r.out.find(text), std::string::npos) << "missing \"" << text << "\" in\n" << r.out;
  }
}

TEST(OptimizeCli, ReachJsonHasEveryDocumentedKey) {
  const auto r = RunCli("optimize --problem reach --json" + kQuickReach);
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key :
       {"status", "message", "A", "c", "phi0", "alpha", "mean_velocity", "attractors", "summary",
        "spread", "seed_won", "robust_to_settings", "evaluations", "rejected_evaluations",
        "search_seconds", "algorithm", "seed"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  for (const char* key : {"chatter_small", "chatter_large", "e_0999", "max_relative_deviation",
                          "event_limit_starts"}) {
    EXPECT_TRUE(j["spread"].contains(key)) << key;
  }
  for (const char* key : {"A", "c", "phi0", "alpha", "I", "mean_velocity_from_rest", "reached"}) {
    EXPECT_TRUE(j["seed"].contains(key)) << key;
  }
  EXPECT_EQ(j["attractors"]["starts"], 4);
  EXPECT_GE(j["mean_velocity"].get<double>(), j["seed"]["mean_velocity_from_rest"].get<double>());
  EXPECT_LE(j["A"].get<double>() + j["c"].get<double>(), 1.0 + 1e-12);
}

TEST(OptimizeCli, ReachWithFixedAlphaKeepsIt) {
  const auto r = RunCli("optimize --problem reach --alpha 0.5 --json" + kQuickReach);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_EQ(nlohmann::json::parse(r.out)["alpha"], 0.5);
}

TEST(OptimizeCli, SingleProblemsReportTheirGaitFromRest) {
  const auto r = RunCli(
      "optimize --problem phase --A 0.05 --c 0.02 --T0 0.1 --e 0.5 --json "
      "--from-rest-starts 2x2");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j["from_rest"].is_object()) << r.out;
  EXPECT_EQ(j["from_rest"]["starts"], 4);
  EXPECT_TRUE(j["from_rest"].contains("reached"));
}

TEST(OptimizeCli, ForcingJsonHasEveryDocumentedKey) {
  const auto r = RunCli("optimize --problem forcing --T0 0.1 --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key :
       {"status", "I", "v_mean", "A", "c", "phi0", "phi1", "alpha", "u", "v_plus", "x_min", "x_max",
        "active_constraints", "evaluations", "algorithm", "spectral_radius"}) {
    EXPECT_TRUE(j.contains(key)) << key;
  }
  EXPECT_EQ(j["status"], "ok");
  EXPECT_FALSE(j.contains("coefficients"));
}

TEST(OptimizeCli, FourierJsonHasCoefficientsAndTheForceCsvOnePeriod) {
  const std::string csv = TempPath("force.csv");
  const auto r =
      RunCli("optimize --problem fourier --harmonics 2 --starts 2 --json --force-csv " + csv);
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("coefficients"));
  EXPECT_EQ(j["coefficients"]["cos"].size(), 2U);
  EXPECT_EQ(j["coefficients"]["sin"].size(), 2U);
  EXPECT_TRUE(j["A"].is_null());
  EXPECT_GE(j["gain"].get<double>(), 0.0);
  std::ifstream in(csv);
  std::string header, line;
  std::getline(in, header);
  EXPECT_EQ(header, "phi,F");
  int rows = 0;
  while (std::getline(in, line)) ++rows;
  std::remove(csv.c_str());
  EXPECT_EQ(rows, 1001);
}

TEST(OptimizeCli, StableAloneMeansSpectralRadiusAtMostOne) {
  // At T0 = 1 every valid phase of this shape is unstable (spectral radius above 3).
  const auto any = RunCli("optimize --problem phase --A 0.3 --c 0.1 --json");
  const auto stable = RunCli("optimize --problem phase --A 0.3 --c 0.1 --stable --json");
  ASSERT_EQ(any.status, 0) << any.out;
  ASSERT_EQ(stable.status, 0) << stable.out;
  EXPECT_EQ(nlohmann::json::parse(any.out)["status"], "ok");
  EXPECT_EQ(nlohmann::json::parse(stable.out)["status"], "no_valid_orbit");
}

TEST(OptimizeCli, GivenNumbersOutsideTheirRangeAreRejectedNotTakenAsDefaults) {
  // NaN is the library's "use T0" for the bound and 0 was the CLI's "use the default" for
  // --starts: a value given on the command line must be a real, admissible one.
  struct Case {
    const char* args;
    const char* message;
  };
  for (const Case& c :
       {Case{"--problem forcing --bound nan",
             "--bound = nan is invalid: expected a finite bound > 0 (at most T0)"},
        Case{"--problem fourier --bound inf",
             "--bound = inf is invalid: expected a finite bound > 0 (at most T0)"},
        Case{"--bound nan", "--bound = nan is invalid: expected a finite bound > 0 (at most T0)"},
        Case{"--problem forcing --starts 0", "--starts = 0 is invalid: expected starts >= 1"},
        Case{"--problem fourier --starts -2", "--starts = -2 is invalid: expected starts >= 1"},
        Case{"--starts 0", "--starts = 0 is invalid: expected starts >= 1"},
        Case{"--problem phase --A nan --c 0.1",
             "--A = nan is invalid: expected a finite amplitude A >= 0"},
        Case{"--problem phase --A 0.3 --c nan",
             "--c = nan is invalid: expected a finite mean force c"}}) {
    const auto r = RunCli(std::string("optimize ") + c.args + " 2>&1");
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.out;
    EXPECT_NE(r.out.find(c.message), std::string::npos) << c.args << "\n" << r.out;
  }
}

TEST(OptimizeCli, BadInputExitsTwoWithOneLineNamingTheRule) {
  struct Case {
    const char* args;
    const char* message;
  };
  for (const Case& c :
       {Case{"--problem forcing --local-algorithm LN_NOPE",
             "local_algorithm = \"LN_NOPE\" is invalid: expected one of LN_COBYLA"},
        Case{"--problem forcing --global-algorithm GN_NOPE",
             "global_algorithm = \"GN_NOPE\" is invalid: expected one of multistart, GN_ISRES"},
        Case{"--problem forcing --margin 0.5", "margin d = 0.5 is invalid"},
        Case{"--problem forcing --bound 2", "force_bound = 2 is invalid"},
        Case{"--problem phase --A 0.3", "--problem phase needs the force shape"},
        Case{"--problem phase --A 0.3 --c 0.1 --stable 0", "--stable = 0 is invalid"},
        Case{"--problem speed", "--problem"},
        Case{"--output /nonexistent_dir/optimum.json", "/nonexistent_dir/optimum.json"}}) {
    const auto r = RunCli(std::string("optimize ") + c.args + " 2>&1");
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.out;
    EXPECT_NE(r.out.find(c.message), std::string::npos) << c.args << "\n" << r.out;
  }
}

}  // namespace
}  // namespace capsubot
