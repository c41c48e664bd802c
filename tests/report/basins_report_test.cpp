// The basins of attraction as text and as a gnuplot figure (basins_text, basins_plot): a map
// built here by hand, so that each share and speed printed is known; the figure colours the
// first ten attractors, names them in its key, and types the force and plane in its title.

#include <fmt/format.h>
#include <gtest/gtest.h>

#include <string>

#include "capsubot/report/attractors_json.hpp"
#include "capsubot/report/basins_text.hpp"
#include "report/report_text.hpp"

namespace capsubot {
namespace {

using testing::Has;

Attractor PeriodOne(double fraction, double mean_velocity) {
  Attractor a;
  a.motion.status = MotionStatus::kPeriodic;
  a.motion.period = 1;
  a.motion.impacts_right = 1;
  a.fraction = fraction;
  a.mean_velocity = mean_velocity;
  return a;
}

// `n` attractors over a 10 x 10 map written to basins.csv, the first on the analytic orbit.
BasinsJobResult HandMadeMap(int n) {
  BasinsJobResult r;
  AttractorsJobOptions& o = r.map.options;
  o.robot.forcing = Forcing::Harmonic(0.5, 0.5, -2.5);
  o.robot.params = Params{0.75, 0.5};
  o.robot.alpha = 0.3;
  o.starts = StartGrid{10, 10};
  o.run = WholeStartMap{"basins.csv", ""};
  r.map.attractors.starts = 100;
  for (int k = 0; k < n; ++k) {
    r.map.attractors.attractors.push_back(PeriodOne(0.01 * (n - k), 0.001 * (k + 1)));
  }
  r.map.attractors.attractors.front().one_impact_orbit = true;
  return r;
}

TEST(BasinsTextReport, LegendWritesTheShareWithOneDecimalAndTheSpeedWithFourDigits) {
  Attractor a = PeriodOne(0.567, 0.0103449);
  a.motion.period = 12;
  a.motion.impacts_right = 25;
  EXPECT_EQ(text::BasinLegend(a, 12),
            "56.7 %: period 12: 25 right + 0 left impacts per 12 periods, mean velocity 0.01034");
}

TEST(BasinsTextReport, ListsTheMapAndItsAttractors) {
  const std::string t = text::BasinsJobText(HandMadeMap(2));
  EXPECT_TRUE(Has(t, "basins: 100 starts (10 x 10, plane x0-psi) written to basins.csv\n"));
  // Shares 2 % and 1 %, speeds 0.001 and 0.002 (PeriodOne above).
  EXPECT_TRUE(Has(t,
                  "   1. 2.0 %: period 1: 1 right + 0 left impacts per period, mean velocity "
                  "0.001 (the analytic one-impact orbit)\n"));
  EXPECT_TRUE(Has(t, "   2. 1.0 %: period 1"));
}

TEST(BasinsTextReport, AShardHasItsLine) {
  BasinsJobResult r = HandMadeMap(1);
  StartMapShard shard;
  shard.file.shards = 2;
  shard.file.output = "half.csv";
  r.map.options.run = shard;
  r.map.shard.starts = 50;
  EXPECT_EQ(text::BasinsJobText(r), "basins: shard 0/2: 50 of 100 starts written to half.csv\n");
}

TEST(BasinsJsonReport, HoldsTheAttractorsOfTheMapAndItsForce) {
  const BasinsJobResult r = HandMadeMap(2);
  const nlohmann::json j = testing::Printed(json::BasinsJobJson(r));
  EXPECT_EQ(j["starts"], 100);
  ASSERT_EQ(j["attractors"].size(), 2U);
  EXPECT_EQ(j["attractors"][1]["fraction"].get<double>(), 0.01);
  EXPECT_EQ(j["attractors"][1]["mean_velocity"].get<double>(), 0.002);
  EXPECT_TRUE(j["attractors"][0]["one_impact_orbit"].get<bool>());
  EXPECT_EQ(j["force"]["phi0"].get<double>(), -2.5);
}

TEST(BasinsPlotReport, ColoursTheFirstTenAttractorsAndGreysTheRest) {
  const std::string s = text::BasinsPlotScript(HandMadeMap(12), "map.png");
  EXPECT_TRUE(Has(s, "set output 'map.png'\n"));
  EXPECT_TRUE(Has(s,
                  "plot 'basins.csv' using 1:2:(column('attractor') > 10 ? 11 : "
                  "column('attractor')) with image notitle"));
  EXPECT_TRUE(Has(s, "set ylabel 'start forcing phase {/Symbol y} [rad]'\n"));
  EXPECT_TRUE(Has(s, "set yrange [0:2*pi]\n"));
  // The key: attractors 1..10 each in its colour with its legend, then one grey entry.
  EXPECT_TRUE(Has(s, "NaN with boxes fs solid fc rgb '#1f77b4' title \"1: 12.0 %: period 1"));
  EXPECT_TRUE(Has(s, "title \"10: 3.0 %: period 1"));
  EXPECT_EQ(s.find("title \"11:"), std::string::npos);
  EXPECT_TRUE(Has(s, ", NaN with boxes fs solid fc rgb '#cccccc' title 'other attractors'\n"));
}

TEST(BasinsPlotReport, FewAttractorsLeaveTheOtherColoursGrey) {
  const std::string s = text::BasinsPlotScript(HandMadeMap(2), "map.png");
  EXPECT_TRUE(Has(s, "1 '#1f77b4', 2 '#ff7f0e', 3 '#cccccc', "));
  EXPECT_EQ(s.find("other attractors"), std::string::npos);
}

TEST(BasinsPlotReport, TitleTypesetsThePhaseAndTheVelocityPlaneHasItsRange) {
  BasinsJobResult r = HandMadeMap(1);
  r.plane = VelocityPlane{1.5, -0.25, 0.75};
  const std::string s = text::BasinsPlotScript(r, "v.png");
  EXPECT_TRUE(Has(s,
                  "set title \"Basins of attraction: F({/Symbol f}) = 0.5 sin({/Symbol f} - "
                  "2.5) + 0.5\\nT_0 = 0.75, e = 0.5, {/Symbol a} = 0.3, start phase "
                  "{/Symbol y} = 1.5\"\n"));
  EXPECT_TRUE(Has(s, "set ylabel 'start relative velocity u_0 [{/Symbol w}L]'\n"));
  EXPECT_TRUE(Has(s, "set yrange [-0.25:0.75]\n"));
}

}  // namespace
}  // namespace capsubot
