// `capsubot continue`: the branch as JSON and CSV, the summary, and bad input (one-line errors,
// exit 2, no file). The numbers themselves are checked in tests/continue/.

#include <gtest/gtest.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>

#include "capsubot/orbit/validity.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::Near;
using testing::RunCli;

// A stable one-impact orbit with clearance (`solve ... --stability`: spectral radius 0.16).
const std::string kSmallOrbit =
    "--A 0.05 --c 0.02 --phi0 -2.842 --T0 0.1 --e 0.5 --alpha 0.2792869076315278";
const std::string kAlphaBranch =
    "continue " + kSmallOrbit + " --from-orbit --param alpha --from 0.2 --to 0.3";

TEST(ContinueCli, JsonHasThePointsTheSpecialPointsAndTheProvenance) {
  const auto r = RunCli(kAlphaBranch + " --json");
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  EXPECT_EQ(j["status"], "ok");
  EXPECT_EQ(j["parameter"], "alpha");
  ASSERT_GE(j["points"].size(), 10U);
  // The start is the orbit of `solve` at the robot's phase: its mean velocity.
  Params params;
  params.T0 = 0.1;
  params.e = 0.5;
  const Solution s = Solve(Forcing::Harmonic(0.05, 0.02, -2.842), params);
  const auto& start = j["points"][j["start_index"].get<std::size_t>()];
  EXPECT_TRUE(Near(start["mean_velocity"].get<double>(), s.orbit.v_mean, 1e-9 * s.orbit.v_mean));
  EXPECT_EQ(start["impacts_right"], 1);
  bool fold = false;
  for (const auto& sp : j["special_points"]) {
    EXPECT_TRUE(sp.contains("alpha"));
    EXPECT_TRUE(sp.contains("mean_velocity"));
    if (sp["type"] == "fold") {
      fold = true;
      EXPECT_TRUE(Near(sp["alpha"].get<double>(), 0.29035, 1e-5));
    }
  }
  EXPECT_TRUE(fold);
  EXPECT_EQ(j["ends"]["lower"]["end"], "range_end");
  EXPECT_EQ(j["provenance"]["command"], "continue");
}

TEST(ContinueCli, CsvHasOneRowPerPointAfterItsProvenanceLine) {
  const auto path = testing::TempPath("branch.csv");
  const auto r = RunCli(kAlphaBranch + " -o " + path.string());
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("fold"), std::string::npos) << r.out;
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line.rfind("# capsubot ", 0), 0U) << line;
  EXPECT_NE(line.find("continue"), std::string::npos);
  std::getline(in, line);
  EXPECT_EQ(line,
            "alpha,x,u,v,psi,period,impacts_right,impacts_left,mean_velocity,spectral_radius,"
            "mu1_re,mu1_im,mu2_re,mu2_im,stable,label");
  int rows = 0, labelled = 0;
  while (std::getline(in, line)) {
    ++rows;
    if (line.back() != ',') ++labelled;
  }
  const auto j = nlohmann::json::parse(RunCli(kAlphaBranch + " --json").out);
  EXPECT_EQ(static_cast<std::size_t>(rows), j["points"].size());
  EXPECT_EQ(static_cast<std::size_t>(labelled), j["special_points"].size());
  std::filesystem::remove(path);
}

TEST(ContinueCli, CurveCsvHasBothParametersAndTheConditionPerPoint) {
  // The period doubling at alpha = 0.2229 followed in (alpha, A) (docs/continuation.md).
  const std::string curve =
      kAlphaBranch + " --param2 A --from2 0.04 --to2 0.06 --follow period_doubling";
  const auto path = testing::TempPath("curve.csv");
  const auto r = RunCli(curve + " -o " + path.string());
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("curve of the period_doubling at alpha = 0.2229"), std::string::npos)
      << r.out;
  std::ifstream in(path);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line.rfind("# capsubot ", 0), 0U) << line;
  EXPECT_NE(line.find("--param2 A --from2 0.04 --to2 0.06 --follow period_doubling"),
            std::string::npos)
      << line;
  std::getline(in, line);
  EXPECT_EQ(line,
            "alpha,A,x,u,v,psi,period,impacts_right,impacts_left,mean_velocity,spectral_radius,"
            "mu1_re,mu1_im,mu2_re,mu2_im,stable,condition");
  int rows = 0;
  while (std::getline(in, line)) ++rows;
  const auto j = nlohmann::json::parse(RunCli(curve + " --json").out);
  EXPECT_EQ(j["follow"]["status"], "ok");
  EXPECT_EQ(j["follow"]["type"], "period_doubling");
  ASSERT_GE(j["curve"].size(), 10U);
  EXPECT_EQ(static_cast<std::size_t>(rows), j["curve"].size());
  for (const auto& p : j["curve"]) {
    EXPECT_TRUE(p.contains("alpha") && p.contains("A") && p.contains("condition"));
    EXPECT_GE(p["A"].get<double>(), 0.04);
    EXPECT_LE(p["A"].get<double>(), 0.06);
  }
  std::filesystem::remove(path);
}

// The robust gait of results/optimum.json followed in alpha over the range of its robustness
// (docs/continuation.md): it grazes the left wall at alpha = 0.6319567436 with alpha falling,
// where the bisection on its existence of branch_edges_test.cpp ends it.
const std::string kGaitBranch =
    "continue --A 0.31611673290226067 --c 0.0623092212807503 --phi0 -3.089378590956282 --T0 1 "
    "--e 1 --alpha 0.6322584367241656 --from-orbit --param alpha --from 0.3161292183620828 --to "
    "0.8161292183620828";

// The JSON of a run without its provenance (times and versions differ between runs).
nlohmann::json WithoutProvenance(const std::string& args) {
  auto j = nlohmann::json::parse(RunCli(args + " --json").out);
  j.erase("provenance");
  return j;
}

TEST(ContinueCli, SwitchAtGrazingFollowsTheMotionBeyondIt) {
  const auto j = WithoutProvenance(kGaitBranch + " --switch-at grazing");
  double grazing = 0.0;
  for (const auto& sp : j["special_points"]) {
    if (sp["type"] == "grazing" && sp["wall"] == "left") grazing = sp["alpha"].get<double>();
  }
  EXPECT_TRUE(Near(grazing, 0.6319567436, 1e-10));
  const auto& b = j["switched"];
  ASSERT_EQ(b["status"], "ok") << b.dump();
  const auto& first = b["points"][b["start_index"].get<std::size_t>()];
  // Beyond the grazing (alpha below it), with other impacts per period than the gait's one
  // right-wall impact per period.
  EXPECT_LT(first["alpha"].get<double>(), grazing);
  const auto period = first["period"].get<std::int64_t>();
  EXPECT_TRUE(first["impacts_right"].get<std::int64_t>() != period ||
              first["impacts_left"].get<std::int64_t>() != 0)
      << first.dump();
  const auto text = RunCli(kGaitBranch + " --switch-at grazing").out;
  EXPECT_NE(text.find("branch switched at the grazing at alpha = 0.6319567436"), std::string::npos)
      << text;
}

TEST(ContinueCli, SwitchAtGrazingSaysWhenTheMotionEndsThere) {
  // The unstable one-impact orbit of the example robot in A (tests/continue/): its branch turns
  // back at the grazing at A = 0.0631462.
  const std::string unstable = "continue " + kSmallOrbit +
                               " --x0 1 --u0 -0.20810169637703732 --v0 0.17436023776205364 "
                               "--psi 5.7843183107095015 --param A --from 0.03 --to 0.079 "
                               "--switch-at grazing";
  const auto j = WithoutProvenance(unstable);
  EXPECT_EQ(j["switched"]["status"], "no_motion");
  EXPECT_NE(j["switched"]["message"].get<std::string>().find("the motion ends at the grazing"),
            std::string::npos);
  const auto r = RunCli(unstable);
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("no branch to switch to at the grazing at A = 0.0631462"), std::string::npos)
      << r.out;
  // Without a grazing on the branch there is nothing to switch to.
  const auto none = WithoutProvenance(kAlphaBranch + " --switch-at grazing");
  EXPECT_TRUE(none["switched"].is_null());
}

TEST(ContinueCli, SwitchIsSwitchAtPeriodDoubling) {
  const auto plain = WithoutProvenance(kAlphaBranch + " --switch");
  EXPECT_EQ(plain["switched"]["status"], "ok");
  EXPECT_EQ(plain, WithoutProvenance(kAlphaBranch + " --switch-at period_doubling"));
}

TEST(ContinueCli, SwitchStartsOnTheMotionBornAtThePeriodDoubling) {
  // The design example's gait in e: the period-2 motion born at its period doubling has the
  // doubling's impacts twice over and its speed (the one-impact motion there moves by
  // sqrt(offset) at most); another period-2 motion (3 right impacts, 30 % slower) is no switch.
  const auto j = WithoutProvenance(
      "continue --A 0.0038074066399391457 --c 0.0007614813279878292 --phi0 -2.5656425223467405 "
      "--T0 0.009318382608106253 --alpha 0.5190067541724127 --e 0.7 --from-orbit --param e "
      "--from 0 --to 1 --switch");
  const nlohmann::json* pd = nullptr;
  for (const auto& sp : j["special_points"]) {
    if (sp["type"] == "period_doubling" && sp["located"] == true) pd = &sp;
  }
  ASSERT_NE(pd, nullptr);
  const auto& b = j["switched"];
  ASSERT_EQ(b["status"], "ok") << b.dump();
  const auto& first = b["points"][b["start_index"].get<std::size_t>()];
  EXPECT_EQ(first["period"], 2);
  EXPECT_EQ(first["impacts_right"], 2 * (*pd)["impacts_right"].get<int>());
  EXPECT_EQ(first["impacts_left"], 2 * (*pd)["impacts_left"].get<int>());
  // The first trial lies 1e-5 from the doubling: within 10 sqrt(1e-5) of its state and speed.
  const double near = 10.0 * std::sqrt(1e-5);
  for (const char* k : {"x", "u", "v"}) {
    EXPECT_TRUE(Near(first[k].get<double>(), (*pd)["state"][k].get<double>(), near)) << k;
  }
  const double v = (*pd)["mean_velocity"].get<double>();
  EXPECT_TRUE(Near(first["mean_velocity"].get<double>(), v, near * v));
}

TEST(ContinueCli, BadInputIsOneLineAndWritesNoFile) {
  const auto path = testing::TempPath("bad_branch.csv");
  const std::string o = " -o " + path.string() + " 2>&1";
  const struct {
    std::string args, message;
  } cases[] = {
      {"continue " + kSmallOrbit + " --from-orbit --param b2 --from 0.2 --to 0.3",
       "capsubot continue: error: parameter = b2 is invalid for this force: expected a_k or b_k "
       "with 1 <= k <= K = 1, its harmonics\n"},
      {"continue " + kSmallOrbit + " --from-orbit --param alpha --from 0.3 --to 0.2",
       "capsubot continue: error: --to = 0.2 is invalid: expected a finite number > --from = "
       "0.3\n"},
      {"continue " + kSmallOrbit + " --from-orbit --param alpha --from 0.2 --to 0.25",
       "capsubot continue: error: the robot's alpha = 0.2792869076315278 is outside the range: "
       "expected --from = 0.2 <= alpha <= --to = 0.25 (the branch starts at the robot's value)\n"},
      {kAlphaBranch + " --max-points 1",
       "capsubot continue: error: --max-points = 1 is invalid: expected 2 <= max_points <= "
       "100000\n"},
      {kAlphaBranch + " --max-points 1000000",
       "capsubot continue: error: --max-points = 1000000 is invalid: expected 2 <= max_points <= "
       "100000\n"},
      {"continue " + kSmallOrbit + " --param alpha --from 0.2 --to 0.3 --x0 0.5",
       "capsubot continue: error: the start is missing: give all of --x0, --u0, --v0, --psi (or "
       "--from-orbit)\n"},
      {kAlphaBranch + " --x0 0.5",
       "capsubot continue: error: --from-orbit gives the start: do not give --x0, --u0, --v0 or "
       "--psi with it\n"},
      {"continue " + kSmallOrbit + " --from-orbit --param mu --from 0.2 --to 0.3",
       "capsubot continue: error: parameter = mu is invalid: expected one of A, c, alpha, T0, e, "
       "phi0, or a Fourier coefficient a1..a16, b1..b16\n"},
      {kAlphaBranch + " --param2 A --to2 0.06 --follow fold",
       "capsubot continue: error: --param2 requires --from2 (see capsubot continue --help)\n"},
      {kAlphaBranch + " --param2 A --from2 0.04 --to2 0.06 --follow hopf",
       "capsubot continue: error: --follow = hopf is invalid: expected one of fold, "
       "period_doubling, grazing, speed_extremum\n"},
      {kAlphaBranch + " --param2 alpha --from2 0.2 --to2 0.3 --follow fold",
       "capsubot continue: error: --param2 = alpha is invalid: expected a parameter other than "
       "--param = alpha\n"},
      {kAlphaBranch + " --param2 A --from2 0.06 --to2 0.04 --follow fold",
       "capsubot continue: error: --to2 = 0.04 is invalid: expected a finite number > --from2 = "
       "0.06\n"},
      {kAlphaBranch + " --switch --switch-at grazing",
       "capsubot continue: error: --switch excludes --switch-at (see capsubot continue --help)\n"},
      {kAlphaBranch + " --switch-at fold",
       "capsubot continue: error: --switch-at = fold is invalid: expected period_doubling or "
       "grazing\n"},
      {kAlphaBranch + " --param2 A --from2 0.06 --to2 0.07 --follow fold",
       "capsubot continue: error: the robot's A = 0.05 is outside the range: expected --from2 = "
       "0.06 <= A <= --to2 = 0.07 (the curve starts at the robot's value)\n"},
  };
  for (const auto& c : cases) {
    const auto r = RunCli(c.args + o);
    EXPECT_EQ(r.status, 2) << c.args;
    EXPECT_EQ(r.out, c.message) << c.args;
    EXPECT_FALSE(std::filesystem::exists(path)) << c.args;
  }
}

}  // namespace
}  // namespace capsubot
