// The report of an event-driven simulation (simulate_text, simulation_json, simulate_csv): a run
// built here by hand, so that each figure printed is known; the transient, the chattering and
// the analytic orbit appear only when the run has them; its notes; its CSV rows.

#include <gtest/gtest.h>

#include <sstream>
#include <string>
#include <vector>

#include "capsubot/report/simulate_csv.hpp"
#include "capsubot/report/simulate_text.hpp"
#include "capsubot/report/simulation_json.hpp"
#include "report/report_text.hpp"

namespace capsubot {
namespace {

using testing::Has;
using testing::Printed;

// 10 periods from a given state, stopped by nothing.
SimulateJobResult HandMadeRun() {
  SimulateJobResult r;
  r.options.forcing = Forcing::Harmonic(0.5, 0.5, 0.0);
  r.options.params = Params{0.75, 0.5};
  r.sim.alpha = 0.25;
  r.sim.x0 = 0.5;
  r.sim.u0 = 0.0;
  r.sim.v0 = 0.0;
  r.sim.periods = 10.0;
  SimResult& run = r.run;
  run.status = SimStatus::kOk;
  run.final_state = SimState{10.0 * kTau, 0.75, -0.5, 0.0, 0.625, SimMode::kRest};
  run.displacement = 0.625;
  run.v_mean = 0.625 / (10.0 * kTau);
  run.impacts_right = 10;
  run.impacts_left = 2;
  run.stops = 10;
  run.breakaways = 10;
  run.events = 32;
  run.energy = Energy{0.5, 0.75, 0.375, 0.125};
  return r;
}

TEST(SimulateTextReport, WritesTheStartStatusFiguresAndEnergy) {
  const std::string t = text::SimulateJobText(HandMadeRun());
  EXPECT_TRUE(Has(t, "  model            T0 = 0.75, e = 0.5, alpha = 0.25\n"));
  EXPECT_TRUE(Has(t, "  start            x = 0.5, u = 0, v = 0\n"));
  // The end phase 10 tau = 62.83185307 (10 digits) is 10 periods.
  EXPECT_TRUE(Has(t, "  status           ok   (phase 62.83185307 = 10 periods)\n"));
  EXPECT_TRUE(Has(t, "  final state      x = 0.75, u = -0.5, v = 0, y = 0.625 (rest)\n"));
  EXPECT_TRUE(Has(t, "  displacement     0.625   (L)\n"));
  // 0.625 / (20 pi) = 0.009947183943 to 10 digits.
  EXPECT_TRUE(Has(t, "  mean velocity    0.009947183943   (omega L)\n"));
  EXPECT_TRUE(Has(t,
                  "  events           10 right impacts, 2 left impacts, 10 stops, 10 "
                  "break-aways\n"));
  EXPECT_TRUE(Has(t,
                  "motor work 0.5 (positive part 0.75); losses: friction 0.375, impacts "
                  "0.125"));
  EXPECT_EQ(t.find("transient"), std::string::npos);
  EXPECT_EQ(t.find("chattering"), std::string::npos);
  EXPECT_EQ(t.find("analytic"), std::string::npos);
}

TEST(SimulateTextReport, TransientChatterAndTheOrbitWhenTheRunHasThem) {
  SimulateJobResult r = HandMadeRun();
  r.sim.transient = 5.0;
  r.run.transient.displacement = 0.25;
  r.run.transient.v_mean = 0.125;
  r.run.transient.impacts_right = 4;
  r.run.transient.impacts_left = 1;
  r.run.sticks = 3;
  r.run.releases = 2;
  r.orbit = Solution{};
  r.orbit->orbit.v_mean = 0.01;
  r.sim.alpha = kNaN;
  const std::string t = text::SimulateJobText(r);
  EXPECT_TRUE(Has(t,
                  "  transient        5 periods: displacement 0.25, mean velocity 0.125, 4 "
                  "right and 1 left impacts"));
  EXPECT_TRUE(Has(t, ", 3 sticks on a wall (chattering), 2 releases\n"));
  EXPECT_TRUE(Has(t, "(right after the analytic orbit's impact)"));
  EXPECT_TRUE(Has(t, "(omega L)   analytic: 0.01\n"));
  EXPECT_TRUE(Has(t, "alpha = -\n"));
}

TEST(SimulationJsonReport, HoldsTheFinalStateFiguresAndForce) {
  const nlohmann::json j = Printed(json::SimulateJobJson(HandMadeRun()));
  EXPECT_EQ(j["status"], "ok");
  EXPECT_EQ(j["message"], "");
  EXPECT_EQ(j["alpha"].get<double>(), 0.25);
  EXPECT_EQ(j["phi"].get<double>(), 10.0 * kTau);
  EXPECT_EQ(j["y"].get<double>(), 0.625);
  EXPECT_EQ(j["mode"], "rest");
  EXPECT_EQ(j["impacts_left"], 2);
  EXPECT_EQ(j["events"], 32);
  EXPECT_EQ(j["energy"]["friction_loss"].get<double>(), 0.375);
  EXPECT_EQ(j["force"]["A"].get<double>(), 0.5);
  EXPECT_FALSE(j.contains("transient"));
  EXPECT_FALSE(j.contains("orbit"));
}

TEST(SimulationJsonReport, TransientAndOrbitWhenGivenAndNullForNaN) {
  SimulateJobResult r = HandMadeRun();
  r.sim.transient = 5.0;
  r.run.transient.impacts_right = 4;
  r.run.status = SimStatus::kEventLimit;
  r.run.message = "the work bound was hit";
  r.run.v_mean = kNaN;
  r.orbit = Solution{};
  const nlohmann::json j = Printed(json::SimulateJobJson(r));
  EXPECT_EQ(j["status"], "event_limit");
  EXPECT_EQ(j["message"], "the work bound was hit");
  EXPECT_TRUE(j["v_mean"].is_null());
  EXPECT_EQ(j["transient"]["periods"].get<double>(), 5.0);
  EXPECT_EQ(j["transient"]["impacts_right"], 4);
  EXPECT_TRUE(j["transient"]["displacement"].is_null());  // not computed: NaN
  EXPECT_EQ(j["orbit"]["status"], "not_run");
}

TEST(SimulateNotes, SayAnInvalidOrbitAndAnEarlyStopAndNothingElse) {
  SimulateJobResult r = HandMadeRun();
  EXPECT_TRUE(text::SimulateJobNotes(r).empty());
  r.orbit = Solution{};
  r.orbit->validity.checked = true;
  EXPECT_TRUE(text::SimulateJobNotes(r).empty());  // a valid orbit is no news
  r.orbit->validity.violations = (1U << static_cast<unsigned>(Condition::kLeftWall)) |
                                 (1U << static_cast<unsigned>(Condition::kRightWall));
  r.run.status = SimStatus::kEventLimit;
  r.run.message = "more than 10 events per period";
  const std::vector<std::string> expected = {
      "the analytic orbit is not valid (left_wall, right_wall)",
      "stopped early: more than 10 events per period"};
  EXPECT_EQ(text::SimulateJobNotes(r), expected);
}

// One row per event and per sample, in the order told, after the header of each file; a file
// not asked (null) is not written.
TEST(SimulateCsvReport, WritesARowPerEventAndPerSample) {
  std::ostringstream events, trajectory;
  text::SimulateCsv csv(&events, &trajectory);
  SimEvent impact;
  impact.kind = EventKind::kImpactRight;
  impact.after = SimState{1.5, 1.0, -0.25, 0.125, 0.5, SimMode::kSlideForward};
  impact.u_before = 0.5;
  impact.v_before = -0.0625;
  csv.OnEvent(impact);
  SimEvent stop;
  stop.kind = EventKind::kStop;
  stop.after = SimState{2.0, 0.75, 0.25, 0.0, 0.625, SimMode::kRest};
  stop.u_before = 0.25;
  stop.v_before = 0.0;
  csv.OnEvent(stop);
  csv.OnSample(SimState{0.0, 0.5, 0.0, 0.0, 0.0, SimMode::kRest});
  EXPECT_EQ(events.str(),
            "phase,kind,x,u,v,y,u_before,v_before,mode\n"
            "1.5,impact_right,1,-0.25,0.125,0.5,0.5,-0.0625,slide_forward\n"
            "2,stop,0.75,0.25,0,0.625,0.25,0,rest\n");
  EXPECT_EQ(trajectory.str(), "phi,x,u,v,y,mode\n0,0.5,0,0,0,rest\n");

  std::ostringstream only_events;
  text::SimulateCsv events_only(&only_events, nullptr);
  events_only.OnSample(SimState{0.0, 0.5, 0.0, 0.0, 0.0, SimMode::kRest});
  events_only.OnEvent(stop);
  EXPECT_EQ(only_events.str(),
            "phase,kind,x,u,v,y,u_before,v_before,mode\n2,stop,0.75,0.25,0,0.625,0.25,0,rest\n");
}

}  // namespace
}  // namespace capsubot
