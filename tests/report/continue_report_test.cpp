// The report of a continuation (continuation_json, continue_csv, continue_text): a branch and a
// curve built here by hand, so that each number written is known; the CSV has one column pair
// per multiplier of the point with the most, a row per point, and nothing without a branch;
// what was not found is said (text) or null (JSON).

#include <gtest/gtest.h>

#include <complex>
#include <sstream>
#include <string>
#include <vector>

#include "capsubot/report/continuation_json.hpp"
#include "capsubot/report/continue_csv.hpp"
#include "capsubot/report/continue_text.hpp"
#include "report/report_text.hpp"

namespace capsubot {
namespace {

using testing::Has;
using testing::Printed;

PeriodicMotion MotionWith(std::vector<std::complex<double>> multipliers) {
  PeriodicMotion m;
  m.status = ShootingStatus::kConverged;
  m.period = 1;
  m.impacts_right = 1;
  m.mean_velocity = 0.0125;
  m.state = PhaseState{0.5, 0.25, 0.0, 1.0};
  m.multipliers = std::move(multipliers);
  m.spectral_radius = m.multipliers.empty() ? 0.0 : std::abs(m.multipliers[0]);
  m.stable = m.spectral_radius < 1.0;
  return m;
}

// Three points in T0: the middle one (the start) with two multipliers, the others with one; a
// located fold between the last two.
ContinueJobResult HandMadeBranch() {
  ContinueJobResult r;
  r.param = "T0";
  Branch& b = r.branch;
  b.status = ContinuationStatus::kOk;
  const double T0[] = {0.5, 0.75, 1.0};
  for (int k = 0; k < 3; ++k) {
    BranchPoint p;
    p.parameter = T0[k];
    p.arclength = 0.25 * k;
    p.motion = k == 1 ? MotionWith({{0.5, 0.0}, {-0.25, 0.0}}) : MotionWith({{0.5, 0.0}});
    b.points.push_back(p);
  }
  b.points[2].label = "fold";
  b.start_index = 1;
  b.backward_end = BranchEnd::kRangeEnd;
  b.forward_end = BranchEnd::kLost;
  b.backward_parameter = 0.5;
  b.forward_parameter = 1.0;
  SpecialPoint fold;
  fold.type = SpecialPointType::kFold;
  fold.parameter = 0.875;
  fold.located = true;
  fold.accuracy = 1e-9;
  fold.motion = MotionWith({{1.0, 0.0}});
  b.special_points.push_back(fold);
  return r;
}

TEST(ContinueCsvReport, BranchHasAColumnPairPerMultiplierAndARowPerPoint) {
  const text::CsvTable csv = text::ContinueJobCsv(HandMadeBranch());
  EXPECT_EQ(csv.rows, 3U);
  std::vector<std::string> lines;
  std::istringstream in(csv.text);
  for (std::string line; std::getline(in, line);) lines.push_back(line);
  ASSERT_EQ(lines.size(), 4U);  // the header and three rows
  EXPECT_EQ(lines[0],
            "T0,x,u,v,psi,period,impacts_right,impacts_left,mean_velocity,spectral_radius,mu1_re,"
            "mu1_im,mu2_re,mu2_im,stable,label");
  // The first point has one multiplier: its second pair is empty.
  EXPECT_EQ(lines[1], "0.5,0.5,0.25,0,1,1,1,0,0.0125,0.5,0.5,0,,,1,");
  EXPECT_EQ(lines[2], "0.75,0.5,0.25,0,1,1,1,0,0.0125,0.5,0.5,0,-0.25,0,1,");
  EXPECT_EQ(lines[3], "1,0.5,0.25,0,1,1,1,0,0.0125,0.5,0.5,0,,,1,fold");
}

TEST(ContinueCsvReport, NoBranchNoTable) {
  ContinueJobResult r = HandMadeBranch();
  r.branch.status = ContinuationStatus::kNoMotion;
  const text::CsvTable csv = text::ContinueJobCsv(r);
  EXPECT_EQ(csv.rows, 0U);
  EXPECT_EQ(csv.text, "");
}

// The branch with the curve of its fold (T0 = 0.875 at e = 0.5) followed in (T0, e): two points.
ContinueJobResult WithCurve() {
  ContinueJobResult r = HandMadeBranch();
  FollowResult f;
  f.param2 = "e";
  f.value2 = 0.5;
  f.type = SpecialPointType::kFold;
  f.at = r.branch.special_points.front();
  f.curve.status = ContinuationStatus::kOk;
  for (const auto& [T0, e] : {std::pair{0.875, 0.5}, std::pair{0.625, 0.75}}) {
    CurvePoint p;
    p.parameter = T0;
    p.parameter2 = e;
    p.condition = 1e-12;
    p.motion = MotionWith({{1.0, 0.0}});
    f.curve.points.push_back(p);
  }
  f.curve.start_index = 0;
  f.curve.backward_end = BranchEnd::kEventChange;
  f.curve.forward_end = BranchEnd::kRangeEnd;
  r.follow = f;
  return r;
}

TEST(ContinueCsvReport, FollowedCurveHasBothParametersAndItsCondition) {
  const text::CsvTable csv = text::ContinueJobCsv(WithCurve());
  EXPECT_EQ(csv.rows, 2U);
  EXPECT_TRUE(Has(csv.text,
                  "T0,e,x,u,v,psi,period,impacts_right,impacts_left,mean_velocity,"
                  "spectral_radius,mu1_re,mu1_im,stable,condition\n"));
  EXPECT_TRUE(Has(csv.text, "\n0.625,0.75,0.5,0.25,0,1,1,1,0,0.0125,1,1,0,0,1e-12\n"));
}

// The note of the file written counts the table's rows, and says when they are a curve's.
TEST(ContinueCsvReport, WrittenNoteCountsTheRowsOfTheBranchOrOfTheCurve) {
  const ContinueJobResult branch = HandMadeBranch();
  EXPECT_EQ(text::ContinueCsvWritten(branch, text::ContinueJobCsv(branch), "b.csv"),
            "  written        3 points to b.csv\n");
  const ContinueJobResult curve = WithCurve();
  EXPECT_EQ(text::ContinueCsvWritten(curve, text::ContinueJobCsv(curve), "c.csv"),
            "  written        2 curve points to c.csv\n");
}

TEST(ContinuationJsonReport, BranchHasItsEndsPointsAndSpecialPoints) {
  const nlohmann::json j = Printed(json::ContinueJobJson(HandMadeBranch()));
  EXPECT_EQ(j["parameter"], "T0");
  EXPECT_EQ(j["status"], "ok");
  EXPECT_EQ(j["start_index"], 1);
  EXPECT_EQ(j["ends"]["lower"], nlohmann::json({{"end", "range_end"}, {"T0", 0.5}}));
  EXPECT_EQ(j["ends"]["upper"]["end"], "lost");
  ASSERT_EQ(j["points"].size(), 3U);
  EXPECT_EQ(j["points"][2]["T0"].get<double>(), 1.0);
  EXPECT_EQ(j["points"][2]["label"], "fold");
  EXPECT_EQ(j["points"][1]["multipliers"], nlohmann::json({{0.5, 0.0}, {-0.25, 0.0}}));
  ASSERT_EQ(j["special_points"].size(), 1U);
  const nlohmann::json& fold = j["special_points"][0];
  EXPECT_EQ(fold["type"], "fold");
  EXPECT_EQ(fold["T0"].get<double>(), 0.875);
  EXPECT_TRUE(fold["located"].get<bool>());
  EXPECT_EQ(fold["wall"], "none");
  EXPECT_FALSE(j.contains("switched"));
  EXPECT_FALSE(j.contains("follow"));
}

TEST(ContinuationJsonReport, NoPointToSwitchAtIsNullAndACurveWithoutStartIsNull) {
  ContinueJobResult r = HandMadeBranch();
  r.switched = SwitchResult{};
  r.follow = FollowResult{};
  r.follow->param2 = "e";
  r.follow->value2 = 0.5;
  r.follow->curve.message = "no fold to follow";
  const nlohmann::json j = Printed(json::ContinueJobJson(r));
  EXPECT_TRUE(j["switched"].is_null());
  EXPECT_EQ(j["follow"]["status"], "not_run");
  EXPECT_TRUE(j["follow"]["start"]["T0"].is_null());
  EXPECT_EQ(j["follow"]["start"]["e"].get<double>(), 0.5);
  EXPECT_TRUE(j["follow"]["ends"]["forward"]["T0"].is_null());  // no point: no last one
  EXPECT_TRUE(j["curve"].empty());
}

TEST(ContinuationJsonReport, CurveHasItsStartEndsAndPoints) {
  const nlohmann::json j = Printed(json::ContinueJobJson(WithCurve()));
  EXPECT_EQ(j["follow"]["type"], "fold");
  EXPECT_EQ(j["follow"]["start"]["T0"].get<double>(), 0.875);
  EXPECT_EQ(j["follow"]["ends"]["backward"],
            nlohmann::json({{"end", "event_change"}, {"T0", 0.875}, {"e", 0.5}}));
  EXPECT_EQ(j["follow"]["ends"]["forward"]["e"].get<double>(), 0.75);
  ASSERT_EQ(j["curve"].size(), 2U);
  EXPECT_EQ(j["curve"][1]["condition"].get<double>(), 1e-12);
}

TEST(ContinuationJsonReport, RobustnessHasEachLimitAndNoBandWhenNotRun) {
  GaitRobustness g;
  ParameterRobustness p;
  p.name = "e";
  p.value = 0.5;
  p.from = 0.0;
  p.to = 1.0;
  p.status = ContinuationStatus::kOk;
  p.down.special = true;
  p.down.type = SpecialPointType::kPeriodDoubling;
  p.down.parameter = 0.25;
  p.down.located = true;
  p.down.accuracy = 1e-8;
  p.down.motion = MotionWith({{-1.0, 0.0}});
  p.up.end = BranchEnd::kRangeEnd;
  p.up.parameter = 1.0;
  g.parameters.push_back(p);
  const nlohmann::json j = Printed(json::RobustnessJson(g));
  EXPECT_EQ(j["e"]["value"].get<double>(), 0.5);
  EXPECT_EQ(j["e"]["down"]["type"], "period_doubling");
  EXPECT_EQ(j["e"]["down"]["e"].get<double>(), 0.25);
  EXPECT_EQ(j["e"]["down"]["multipliers"], nlohmann::json({{-1.0, 0.0}}));
  EXPECT_EQ(j["e"]["up"]["type"], "range_end");
  EXPECT_FALSE(j["e"]["up"].contains("accuracy"));  // an end, not a special point
  EXPECT_TRUE(j["e"]["band"].is_null());
}

TEST(ContinueTextReport, SwitchAndFollowSayWhatWasNotFound) {
  ContinueJobResult r = HandMadeBranch();
  r.switched = SwitchResult{};
  const std::string summary = r.branch.Summary("T0");
  EXPECT_EQ(text::ContinueJobText(r),
            summary + "no located period doubling: no branch to switch to\n");
  r.switched->point = SwitchPoint::kGrazing;
  r.switched->at = r.branch.special_points.front();
  r.switched->branch.status = ContinuationStatus::kNoMotion;
  r.switched->branch.message = "the motion ends at the grazing";
  EXPECT_TRUE(Has(text::ContinueJobText(r),
                  "no branch to switch to at the grazing at T0 = 0.875: no_motion (the motion "
                  "ends at the grazing)\n"));
}

TEST(ContinueTextReport, CurveWritesItsRangesAndHowEachDirectionEnded) {
  const std::string t = text::ContinueJobText(WithCurve());
  EXPECT_TRUE(Has(t, "curve of the fold at T0 = 0.875, e = 0.5, in (T0, e)\n"));
  // The ranges over the two points: T0 0.625 .. 0.875, e 0.5 .. 0.75.
  EXPECT_TRUE(Has(t, "  curve          2 points over T0 = 0.625 .. 0.875, e = 0.5 .. 0.75\n"));
  EXPECT_TRUE(Has(t,
                  "  e falling      stopped at T0 = 0.875, e = 0.5: the motion's events "
                  "change there\n"));
  EXPECT_TRUE(Has(t, "  e rising       reached the edge of the range at T0 = 0.625, e = 0.75\n"));
}

}  // namespace
}  // namespace capsubot
