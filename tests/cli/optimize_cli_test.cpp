// `capsubot optimize`: the main job and the single problems through the built program.

#include <fmt/format.h>
#include <gtest/gtest.h>
#include <unistd.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
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

// The margins and stability requirement of today's optima: none.
constexpr const char* kNoMargins = " --margin 0 --margin-stroke 0 --stick-margin 0 --rho-max inf";

// Reduced from-rest settings so the main job and the reach problem run quickly.
const std::string kQuickReach =
    " --from-rest-starts 2x2 --reach-starts 2x2 --reach-evaluations 10 "
    "--reach-local-evaluations 5 --hops 2 --starts 3";

TEST(OptimizeCli, MainJobWritesTheOutputFileAndPrintsTheSameObject) {
  const std::string path = TempPath("optimum.json");
  const auto r = RunCli("optimize --json -o " + path + kQuickReach);
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
  EXPECT_EQ(written["fastest"]["status"], "ok");
  EXPECT_EQ(written["fastest_stable"]["status"], "ok");
  EXPECT_LE(written["fastest_stable"]["I"].get<double>(), written["fastest"]["I"].get<double>());
  EXPECT_LE(written["fastest_stable"]["spectral_radius"].get<double>(), 1.0);
  // The robust gait (defaults d_s = 0.02, s = 0.02, rho_max = 0.9) is slower than both, has
  // today's gait keys and its check from rest.
  const auto& robust = written["robust"];
  EXPECT_EQ(robust["status"], "ok");
  EXPECT_LE(robust["I"].get<double>(), written["fastest_stable"]["I"].get<double>());
  EXPECT_LE(robust["spectral_radius"].get<double>(), 0.9 * (1.0 + 1e-12));
  EXPECT_EQ(written["margin_stroke"], 0.02);
  EXPECT_EQ(written["stick_margin"], 0.02);
  EXPECT_EQ(written["rho_max"], 0.9);
  for (const char* key : {"A", "c", "phi0", "alpha", "I", "v_mean", "x_min", "x_max",
                          "spectral_radius", "binding", "from_rest"}) {
    EXPECT_TRUE(robust.contains(key)) << key;
  }
  const auto& from_rest = robust["from_rest"];
  EXPECT_EQ(from_rest["starts"], 4);
  for (const char* key :
       {"attractors", "mean_velocity", "event_limit_starts", "reached", "summary"}) {
    EXPECT_TRUE(from_rest.contains(key)) << key;
  }
  EXPECT_LE(from_rest["reached"].get<int>(), 4);
  // The fastest motion from rest: seeded with the robust gait, never slower from rest.
  const auto& reach = written["reach"];
  for (const char* key : {"A", "c", "alpha", "mean_velocity", "attractors", "spread", "seed"}) {
    EXPECT_TRUE(reach.contains(key)) << key;
  }
  EXPECT_EQ(reach["attractors"]["starts"], 4);
  EXPECT_GE(reach["mean_velocity"].get<double>(), from_rest["mean_velocity"].get<double>());
  EXPECT_EQ(reach["seed"]["mean_velocity_from_rest"], from_rest["mean_velocity"]);
  EXPECT_EQ(reach["seed"]["A"], robust["A"]);
  EXPECT_EQ(reach["seed"]["alpha"], robust["alpha"]);
  // How far T0, e and alpha can move: a limit each way, within the range searched
  // (tests/continue/gait_robustness_test.cpp checks that the limits are special points).
  for (const char* name : {"T0", "e", "alpha"}) {
    const auto& p = written["robustness"][name];
    EXPECT_EQ(p["status"], "ok") << name;
    for (const char* way : {"down", "up"}) {
      const double at = p[way][name].get<double>();
      EXPECT_GE(at, p["from"].get<double>()) << name << ' ' << way;
      EXPECT_LE(at, p["to"].get<double>()) << name << ' ' << way;
      EXPECT_TRUE(p[way].contains("type")) << name << ' ' << way;
    }
  }
  EXPECT_EQ(written["robustness"]["alpha"]["value"], robust["alpha"]);
}

TEST(OptimizeCli, MainJobSummarySaysWhatTheRobotReachesAndWhichToBuildAndWritesNothing) {
  const auto r = RunCli("optimize" + kQuickReach);
  ASSERT_EQ(r.status, 0) << r.out;
  for (const char* text : {"NO valid gait", "fastest robust gait", "fastest valid gait",
                           "fastest stable gait", "inner mass ratio", "gap lengths per period",
                           "left_wall", "margins binding  clearance_stroke, rho_max",
                           "reached from rest in", "fastest motion from rest", "Which to build"}) {
    EXPECT_NE(r.out.find(text), std::string::npos) << "missing \"" << text << "\" in\n" << r.out;
  }
  EXPECT_EQ(r.out.find("written:"), std::string::npos);
  // Run in an empty folder: without -o nothing is written (no results/optimum.json).
  const std::filesystem::path dir = TempPath("main_job_dir");
  std::filesystem::create_directories(dir);
  const std::string in_dir =
      "cd " + dir.string() + " && " + CAPSUBOT_CLI + " optimize" + kQuickReach + " > /dev/null";
  ASSERT_EQ(std::system(in_dir.c_str()), 0);
  EXPECT_TRUE(std::filesystem::is_empty(dir)) << "the main job wrote into " << dir;
  std::filesystem::remove_all(dir);
}

TEST(OptimizeCli, ReachJsonHasEveryDocumentedKey) {
  const auto r = RunCli("optimize --problem reach --json" + kQuickReach);
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  for (const char* key : {"status", "message", "A", "c", "phi0", "alpha", "mean_velocity",
                          "attractors", "summary", "spread", "seed_won", "robust_to_settings",
                          "evaluations", "rejected_evaluations", "algorithm", "seed"}) {
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

// A time limit reached before the search evaluated anything of its own: the status says the
// limit stopped it, the message that only the starting drives were compared, and the seed
// (the first of them, re-checked as itself) wins; the text says the same.
TEST(OptimizeCli, ReachOutOfTimeBeforeItsFirstEvaluationSaysSo) {
  const std::string args = "optimize --problem reach --reach-seconds 1e-6" + kQuickReach;
  const auto r = RunCli(args + " --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "max_time");
  EXPECT_NE(j["message"].get<std::string>().find(
                "the time limit came before the search evaluated any drive: only the starting "
                "drives were compared"),
            std::string::npos)
      << j["message"];
  EXPECT_EQ(j["seed_won"], true);
  EXPECT_EQ(j["mean_velocity"], j["seed"]["mean_velocity_from_rest"]);
  const auto text = RunCli(args);
  ASSERT_EQ(text.status, 0) << text.out;
  EXPECT_NE(text.out.find("max_time"), std::string::npos) << text.out;
  EXPECT_NE(text.out.find("before the search evaluated any drive"), std::string::npos) << text.out;
}

TEST(OptimizeCli, ReachWithHarmonicsReportsTheDriveAndItsLadder) {
  const auto r = RunCli(
      "optimize --problem reach --harmonics 2 --json --drive-evaluations 12 --drive-polishes 2 "
      "--drive-local-evaluations 6" +
      kQuickReach);
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j["drive"].is_object()) << r.out;
  EXPECT_EQ(j["drive"]["waveform"], "fourier");
  ASSERT_EQ(j["drive"]["cos"].size(), 2u);
  ASSERT_EQ(j["drive"]["sin"].size(), 2u);
  EXPECT_EQ(j["drive"]["cos"][0], 0.0);  // the family's gauge: the first harmonic is a sine
  ASSERT_EQ(j["ladder"].size(), 2u);
  EXPECT_EQ(j["ladder"][0]["harmonics"], 1);
  EXPECT_EQ(j["ladder"][1]["harmonics"], 2);
  EXPECT_EQ(j["ladder"][1]["mean_velocity"], j["mean_velocity"]);
  EXPECT_EQ(j["speed_ratio_to_sine"].get<double>(),
            j["mean_velocity"].get<double>() / j["ladder"][0]["mean_velocity"].get<double>());
  // The bound, exactly: max |F| of the reported coefficients, recomputed here from a dense
  // sampling of the series, is the reported max_abs_force, at the bound T0 = 1.
  const double c = j["drive"]["c"];
  double sampled = 0.0;
  for (int i = 0; i < 100000; ++i) {
    const double t = 6.283185307179586 * i / 100000.0;
    double F = c;
    for (int k = 1; k <= 2; ++k) {
      F += j["drive"]["cos"][k - 1].get<double>() * std::cos(k * t) +
           j["drive"]["sin"][k - 1].get<double>() * std::sin(k * t);
    }
    sampled = std::max(sampled, std::abs(F));
  }
  EXPECT_NEAR(j["max_abs_force"].get<double>(), sampled, 1e-8);
  EXPECT_NEAR(j["max_abs_force"].get<double>(), 1.0, 1e-12);
  // The winner's numbers are those of `capsubot attractors` on the reported drive.
  const auto a = RunCli(fmt::format(
      "attractors --c {} --cos {},{} --sin {},{} --phi0 {} --alpha {} --starts 2x2 --json", c,
      j["drive"]["cos"][0].get<double>(), j["drive"]["cos"][1].get<double>(),
      j["drive"]["sin"][0].get<double>(), j["drive"]["sin"][1].get<double>(),
      j["drive"]["phi0"].get<double>(), j["alpha"].get<double>()));
  ASSERT_EQ(a.status, 0) << a.out;
  EXPECT_NEAR(nlohmann::json::parse(a.out)["mean_velocity"].get<double>(),
              j["mean_velocity"].get<double>(), 1e-12);
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
  const testing::CsvLines force = testing::ReadCsv(csv);
  std::remove(csv.c_str());
  EXPECT_EQ(force.comments.size(), 1U);  // the provenance of the JSON (provenance_cli_test.cpp)
  EXPECT_EQ(force.header, "phi,F");
  EXPECT_EQ(force.rows.size(), 1001U);
}

TEST(OptimizeCli, StableAloneMeansSpectralRadiusAtMostOne) {
  // At T0 = 1 every valid phase of this shape is unstable (spectral radius above 3).
  const std::string shape = std::string("optimize --problem phase --A 0.3 --c 0.1 --json") +
                            " --margin-stroke 0 --stick-margin 0";
  const auto any = RunCli(shape + " --rho-max inf");
  const auto stable = RunCli(shape + " --stable");
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
       {Case{"--problem forcing --bound nan", "--bound = nan is invalid: expected a finite number"},
        Case{"--problem fourier --bound 0",
             "--bound = 0 is invalid: expected a finite bound > 0 (at most T0)"},
        Case{"--bound -1", "--bound = -1 is invalid: expected a finite bound > 0 (at most T0)"},
        Case{"--problem forcing --starts 0",
             "--starts = 0 is invalid: expected 1 <= starts <= 1000"},
        Case{"--problem fourier --starts -2",
             "--starts = -2 is invalid: expected 1 <= starts <= 1000"},
        Case{"--starts 0", "--starts = 0 is invalid: expected 1 <= starts <= 1000"},
        Case{"--problem phase --A -1 --c 0.1",
             "--A = -1 is invalid: expected a finite amplitude A >= 0"},
        Case{"--problem phase --A 0.3 --c nan",
             "--c = nan is invalid: expected a finite number"}}) {
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
             "--local-algorithm = \"LN_NOPE\" is invalid: expected one of LN_COBYLA"},
        Case{"--problem forcing --global-algorithm GN_NOPE",
             "--global-algorithm = \"GN_NOPE\" is invalid: expected one of multistart, GN_ISRES"},
        Case{"--problem forcing --margin 0.5", "margin d = 0.5 is invalid"},
        Case{"--problem forcing --bound 2", "--bound = 2 is invalid"},
        Case{"--problem phase --A 0.3", "--problem phase needs the force shape"},
        Case{"--problem phase --A 0.3 --c 0.1 --rho-max 0", "--rho-max = 0 is invalid"},
        Case{"--problem phase --A 0.3 --c 0.1 --stable --rho-max 0.5", "--stable"},
        Case{"--problem forcing --margin-stroke 0.5",
             "stroke margin d_s = 0.5 is invalid: expected 0 <= d_s < 0.5"},
        Case{"--problem forcing --stick-margin 1",
             "stick margin s = 1 is invalid: expected 0 <= s < 1"},
        Case{"--problem forcing --max-time 0", "--max-time = 0 is invalid"},
        Case{"--problem speed", "--problem"},
        Case{"--problem reach --bound 2", "--bound = 2 is invalid"},
        Case{"--problem reach --alpha 2",
             "--alpha = 2 is invalid: expected 0 < alpha < 1 (not given: free)"},
        Case{"--problem reach --reach-evaluations 0",
             "--reach-evaluations = 0 is invalid: expected at least 1"},
        Case{"--from-rest-starts 0x3", "--from-rest-starts = 0x3 is invalid: expected NXxNPSI"},
        Case{"--alpha 0.5",
             "--alpha conflicts with the main job (no --problem): expected --alpha only with "
             "--problem reach"},
        Case{"--problem reach --harmonics 17",
             "--harmonics = 17 is invalid: expected 1 <= harmonics <= 16"},
        Case{"--problem reach --drive-polishes 3",
             "--drive-polishes conflicts with --problem reach without --harmonics K >= 2"},
        Case{"--problem phase --A 0.3 --c 0.1 --harmonics 2",
             "--harmonics conflicts with --problem phase"},
        Case{"--problem reach --harmonics 2 --drive-evaluations 0",
             "--drive-evaluations = 0 is invalid: expected 1 <= drive_evaluations <= 1000000"},
        Case{"--problem forcing --reach-seconds 5",
             "--reach-seconds conflicts with --problem forcing"},
        Case{"--problem fourier --from-rest-csv /tmp/x.csv",
             "--from-rest-csv conflicts with --problem fourier"},
        // Output paths are opened before any work: the main job fails at once.
        Case{"-o /nonexistent_dir/optimum.json", "/nonexistent_dir/optimum.json"},
        Case{"--from-rest-csv /nonexistent_dir/from_rest.csv", "/nonexistent_dir/from_rest.csv"}}) {
    const auto r = RunCli(std::string("optimize ") + c.args + " 2>&1");
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.out;
    EXPECT_NE(r.out.find(c.message), std::string::npos) << c.args << "\n" << r.out;
  }
}

TEST(OptimizeCli, ZeroMarginsReproduceTheOptimaOfValidAndOfStableOrbits) {
  // References: the optima this program printed before it had margins (P2 at T0 = 1, e = 1:
  // every valid orbit; spectral radius <= 1), to the last digit.
  constexpr double kValidI = 0.31228817482875976, kStableI = 0.22510921192914857;
  constexpr double kSameOptimumTol = 1e-12;
  const auto valid = RunCli(std::string("optimize --problem forcing --json") + kNoMargins);
  const auto stable = RunCli(
      "optimize --problem forcing --json --margin 0 --margin-stroke 0 --stick-margin 0 "
      "--rho-max 1");
  ASSERT_EQ(valid.status, 0) << valid.out;
  ASSERT_EQ(stable.status, 0) << stable.out;
  const auto v = nlohmann::json::parse(valid.out), s = nlohmann::json::parse(stable.out);
  EXPECT_TRUE(testing::NearAbsBelowOne(v["I"].get<double>(), kValidI, kSameOptimumTol));
  EXPECT_TRUE(testing::NearAbsBelowOne(s["I"].get<double>(), kStableI, kSameOptimumTol));
  EXPECT_EQ(v["active_constraints"], nlohmann::json({"left_wall", "right_wall"}));
  EXPECT_EQ(v["binding"], nlohmann::json::array());
  EXPECT_EQ(s["binding"], nlohmann::json({"rho_max"}));
}

TEST(OptimizeCli, RobustDefaultsHoldEveryMarginAndReportWhichBind) {
  const auto r = RunCli("optimize --problem forcing --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_EQ(j["status"], "ok") << j["message"];
  const double x_min = j["x_min"], x_max = j["x_max"], stroke = j["stroke"];
  EXPECT_DOUBLE_EQ(stroke, 1.0 - x_min);  // x_max < 1: the stroke ends at the impact, x = 1
  EXPECT_GE(x_min, 0.02 * stroke);
  EXPECT_LE(x_max, 1.0 - 0.02 * stroke);
  EXPECT_LE(j["spectral_radius"].get<double>(), 0.9);
  EXPECT_EQ(j["binding"], nlohmann::json({"clearance_stroke", "rho_max"}));
  EXPECT_EQ(j["valid"], true);
}

TEST(OptimizeCli, TinyT0ReturnsAValidGaitScaledFromTheReference) {
  // Once an endless NLopt search (T0 from about 1e-12 to 3e-8). docs/model.md section 6: the
  // robust gait is scale-free at small T0, so I/T0 is the same at T0 = 1e-9 and 1e-3.
  for (const char* extra : {"", kNoMargins}) {
    const auto tiny = RunCli(std::string("optimize --problem forcing --T0 1e-9 --json") + extra);
    const auto ref = RunCli(std::string("optimize --problem forcing --T0 1e-3 --json") + extra);
    ASSERT_EQ(tiny.status, 0) << tiny.out;
    ASSERT_EQ(ref.status, 0) << ref.out;
    const auto t = nlohmann::json::parse(tiny.out), r = nlohmann::json::parse(ref.out);
    EXPECT_EQ(t["status"], "ok") << t["message"];
    EXPECT_EQ(t["valid"], true);
    EXPECT_TRUE(
        testing::NearAbsBelowOne(t["I"].get<double>() / 1e-9, r["I"].get<double>() / 1e-3, 1e-9))
        << extra;
  }
}

TEST(OptimizeCli, HugeT0FindsTheValidGaitsThatExist) {
  // Once "no valid gait": at T0 = 1e6 valid gaits need forces of order 1e-6 of the bound.
  const auto r = RunCli(std::string("optimize --problem forcing --T0 1e6 --json") + kNoMargins);
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "ok") << j["message"];
  EXPECT_EQ(j["valid"], true);
  EXPECT_GT(j["I"].get<double>(), 0.0);
}

TEST(OptimizeCli, TimeLimitStopsTheSearchWithItsStatus) {
  const auto r = RunCli("optimize --problem forcing --max-time 0.005 --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "max_time");
  EXPECT_NE(j["message"].get<std::string>().find("time limit of 0.005 s reached"),
            std::string::npos)
      << j["message"];
}

TEST(OptimizeCli, InfiniteTimeLimitMeansNoLimit) {
  // The help says "inf: none"; the limit is then never reached and the answer is the default's.
  const std::string args =
      "optimize --problem phase --A 0.2 --c 0.03 --from-rest-starts 1x1 --json";
  const auto limited = RunCli(args);
  const auto unlimited = RunCli(args + " --max-time inf");
  ASSERT_EQ(unlimited.status, 0) << unlimited.out;
  ASSERT_EQ(limited.status, 0) << limited.out;
  const auto a = nlohmann::json::parse(limited.out);
  const auto b = nlohmann::json::parse(unlimited.out);
  EXPECT_EQ(b["status"], "ok") << b["message"];
  EXPECT_EQ(b["phi0"], a["phi0"]);
  EXPECT_EQ(b["I"], a["I"]);
}

TEST(OptimizeCli, SizeOptionsAreBoundedBeforeAnyWork) {
  // Each of these once ran for ever or allocated until the process died.
  struct Case {
    const char* args;
    const char* message;
  };
  const Case cases[] = {
      {"optimize --problem forcing --hops 2000000000",
       "--hops = 2000000000 is invalid: expected 0 <= hops <= 1000"},
      {"optimize --problem fourier --starts 2000000000",
       "--starts = 2000000000 is invalid: expected 1 <= starts <= 1000"},
      {"optimize --problem forcing --global-algorithm GN_ISRES --global-evaluations 2000000000",
       "--global-evaluations = 2000000000 is invalid: expected 10 <= global-evaluations <= "
       "10000000"},
      {"sweep --grid A=0:1:2 --c 0.1 --optimize phi0 --scan-points 2000000000 -o -",
       "--scan-points = 2000000000 is invalid: expected 16 <= scan_points <= 1000000"},
  };
  int checked = 0;
  for (const Case& c : cases) {
    const auto r = RunCli(std::string(c.args) + " 2>&1");
    EXPECT_EQ(r.status, 2) << c.args << "\n" << r.out;
    EXPECT_NE(r.out.find(c.message), std::string::npos) << c.args << "\n" << r.out;
    EXPECT_EQ(std::count(r.out.begin(), r.out.end(), '\n'), 1) << r.out;
    ++checked;
  }
  EXPECT_EQ(checked, 4);
}

}  // namespace
}  // namespace capsubot
