// The report of the attractors from rest (attractors_text, attractors_json): attractors built
// here by hand (a periodic one on the analytic orbit, an irregular one), so that each share and
// speed printed is known; a shard has its one line; a gait not checked from rest is null.

#include <gtest/gtest.h>

#include <string>

#include "capsubot/report/attractors_json.hpp"
#include "capsubot/report/attractors_text.hpp"
#include "report/report_text.hpp"

namespace capsubot {
namespace {

using testing::Has;
using testing::Printed;

Attractor Periodic() {
  Attractor a;
  a.motion.status = MotionStatus::kPeriodic;
  a.motion.period = 1;
  a.motion.impacts_right = 1;
  a.motion.mean_velocity = 0.0125;
  a.example = RestStart(0.125, 0.5);
  a.starts = 12;
  a.fraction = 0.75;
  a.one_impact_orbit = true;
  a.mean_velocity = a.velocity_min = a.velocity_max = 0.0125;
  return a;
}

Attractor Irregular(double halves_difference) {
  Attractor a;
  a.motion.status = MotionStatus::kNoPeriod;
  a.motion.impacts_right = 250;
  a.motion.impacts_left = 40;
  a.motion.mean_velocity = 0.02;
  a.example = RestStart(0.875, 3.0);
  a.starts = 4;
  a.fraction = 0.25;
  a.mean_velocity = 0.021;
  a.velocity_min = 0.02;
  a.velocity_max = 0.0225;
  a.halves_difference = halves_difference;
  return a;
}

// 16 starts from rest (4 x 4): 12 on the orbit, 4 irregular; the mean over the starts is
// (12 * 0.0125 + 4 * 0.021) / 16 = 0.014625.
AttractorsJobResult HandMadeMap() {
  AttractorsJobResult r;
  r.options.robot.forcing = Forcing::Harmonic(0.5, 0.5, 0.0);
  r.options.robot.params = Params{0.75, 0.5};
  r.options.robot.alpha = 0.3;
  r.options.starts = StartGrid{4, 4};
  r.attractors.starts = 16;
  r.attractors.attractors = {Periodic(), Irregular(0.02)};
  r.attractors.mean_velocity = (12 * 0.0125 + 4 * 0.021) / 16;
  return r;
}

TEST(AttractorsTextReport, ListsEachAttractorWithItsShareAndExample) {
  const std::string t = text::AttractorsJobText(HandMadeMap());
  EXPECT_TRUE(Has(t, "attractors from rest: 16 starts (4 x0 x 4 phases), 200 + 100 periods\n"));
  EXPECT_TRUE(Has(t, "  model          T0 = 0.75, e = 0.5, alpha = 0.3\n"));
  EXPECT_TRUE(Has(t,
                  "   1.  75.0 % of starts  mean velocity 0.0125        period 1: 1 right + 0 "
                  "left impacts per period  (the analytic one-impact orbit)\n"));
  EXPECT_TRUE(Has(t, "      e.g. from x0 = 0.125, psi = 0.5\n"));
  EXPECT_TRUE(Has(t, "   2.  25.0 % of starts"));
  EXPECT_TRUE(Has(t, "  mean velocity over the starts: 0.014625 (omega L)\n"));
  EXPECT_EQ(t.find("work bound"), std::string::npos);
  EXPECT_EQ(t.find("written to"), std::string::npos);
}

TEST(AttractorsTextReport, StartsAtTheWorkBoundAndTheFileAreSaid) {
  AttractorsJobResult r = HandMadeMap();
  r.attractors.event_limit_starts = 3;
  r.options.run = WholeStartMap{"map.csv", ""};
  const std::string t = text::AttractorsJobText(r);
  EXPECT_TRUE(Has(t, "(omega L), 3 starts hit the work bound and are left out\n"));
  EXPECT_TRUE(Has(t, "  the motion of every start written to map.csv\n"));
}

TEST(AttractorsTextReport, AttractorWordsForEachStatus) {
  // Halves differing by 2 % (> 1 %): the record is too short; by 0.5 %: settled.
  EXPECT_EQ(text::AttractorWords(Irregular(0.02), 8),
            "irregular, no period up to 8 (mean velocity 0.02 to 0.0225 over its starts; the "
            "halves of a record differ by up to 2 %: a longer --record is needed for 1 %)");
  EXPECT_TRUE(Has(text::AttractorWords(Irregular(0.005), 8), "up to 0.5 %: settled)"));
  Attractor p = Periodic();
  p.motion.period = 3;
  p.motion.impacts_right = 4;
  p.motion.impacts_left = 2;
  EXPECT_EQ(text::AttractorWords(p, 8), "period 3: 4 right + 2 left impacts per 3 periods");
  Attractor limit;
  limit.motion.status = MotionStatus::kEventLimit;
  EXPECT_TRUE(Has(text::AttractorWords(limit, 8), "event_limit: the work bound was hit"));
  EXPECT_EQ(text::AttractorWords(Attractor{}, 8), "not run");
}

TEST(AttractorsTextReport, AShardHasItsLine) {
  AttractorsJobResult r = HandMadeMap();
  StartMapShard shard;
  shard.file.shard = 1;
  shard.file.shards = 3;
  shard.file.output = "part1.csv";
  r.options.run = shard;
  r.shard.starts = 5;
  r.shard.resumed = 2;
  EXPECT_EQ(text::AttractorsJobText(r),
            "attractors: shard 1/3: 5 of 16 starts written to part1.csv (2 resumed from the "
            "checkpoint)\n");
  r.shard.resumed = 0;
  EXPECT_EQ(text::StartShardText("basins", r),
            "basins: shard 1/3: 5 of 16 starts written to part1.csv\n");
}

TEST(AttractorsJsonReport, HoldsEachAttractorAndHalvesOnlyForAnIrregularOne) {
  const nlohmann::json j = Printed(json::AttractorsJobJson(HandMadeMap()));
  EXPECT_EQ(j["starts"], 16);
  EXPECT_DOUBLE_EQ(j["mean_velocity"].get<double>(), 0.014625);
  EXPECT_EQ(j["event_limit_starts"], 0);
  EXPECT_EQ(j["force"]["waveform"], "sine");
  ASSERT_EQ(j["attractors"].size(), 2U);
  const nlohmann::json& p = j["attractors"][0];
  EXPECT_EQ(p["status"], "periodic");
  EXPECT_EQ(p["fraction"].get<double>(), 0.75);
  EXPECT_EQ(p["starts"], 12);
  EXPECT_EQ(p["example_start"]["x0"].get<double>(), 0.125);
  EXPECT_TRUE(p["one_impact_orbit"].get<bool>());
  EXPECT_FALSE(p.contains("halves_difference"));
  const nlohmann::json& q = j["attractors"][1];
  EXPECT_EQ(q["status"], "no_period");
  EXPECT_EQ(q["mean_velocity"].get<double>(), 0.021);  // over its starts, not the example's
  EXPECT_EQ(q["velocity_max"].get<double>(), 0.0225);
  EXPECT_EQ(q["halves_difference"].get<double>(), 0.02);
}

TEST(AttractorsJsonReport, AMotionAtTheWorkBoundHasANullVelocity) {
  Motion m;
  m.status = MotionStatus::kEventLimit;
  const nlohmann::json j = Printed(json::MotionJson(m));
  EXPECT_EQ(j["status"], "event_limit");
  EXPECT_TRUE(j["mean_velocity"].is_null());
}

TEST(AttractorsJsonReport, FromRestIsNullUnlessChecked) {
  GaitFromRest fr;
  EXPECT_TRUE(json::FromRestJson(fr).is_null());
  fr.checked = true;
  fr.attractors = HandMadeMap().attractors;
  fr.reached = 12;
  fr.summary = "reached from rest in 12 of 16 starts";
  const nlohmann::json j = json::FromRestJson(fr);
  EXPECT_EQ(j["reached"], 12);
  EXPECT_EQ(j["summary"], fr.summary);
  EXPECT_EQ(j["attractors"].size(), 2U);
}

}  // namespace
}  // namespace capsubot
