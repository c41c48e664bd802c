// What a sweep and a bifurcation study report (sweep_text, sweep_plot, bifurcation_text): the
// line each prints on results built here by hand, and the gnuplot script of a sweep's file:
// a curve for one axis, a map for two, log scales, quoting, the marker size, and a message
// naming the rule for each plot it refuses.

#include <gtest/gtest.h>

#include <string>

#include "capsubot/report/bifurcation_text.hpp"
#include "capsubot/report/sweep_plot.hpp"
#include "capsubot/report/sweep_text.hpp"
#include "report/report_text.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::Has;
using testing::InvalidArgumentMessage;

TEST(SweepTextReport, SaysWhatWasWrittenAndWhatWasResumed) {
  SweepJobResult r;
  r.summary = SweepSummary{5, 3, 0, 4, 0.01234};
  r.output = "f.csv";
  // Seconds with 3 decimals: 0.01234 -> 0.012.
  EXPECT_EQ(text::SweepJobText(r), "5 points, 3 rows written to f.csv in 0.012 s on 4 threads\n");
  r.summary.points_resumed = 2;
  EXPECT_EQ(text::SweepJobText(r),
            "5 points, 3 rows written to f.csv in 0.012 s on 4 threads (2 "
            "points resumed from the checkpoint)\n");
}

GridAxis Axis(ModelParameter parameter, double lo, double hi, int n, GridSpacing spacing) {
  GridAxis a;
  a.parameter = parameter;
  a.lo = lo;
  a.hi = hi;
  a.n = n;
  a.spacing = spacing;
  return a;
}

SweepOptions SweepOver(std::vector<GridAxis> axes) {
  SweepOptions s;
  s.grid.axes = std::move(axes);
  s.output = "it's.csv";
  return s;
}

TEST(SweepPlotReport, OneAxisIsACurveOfTheColumn) {
  const SweepOptions s = SweepOver({Axis(ModelParameter::kT0, 0.1, 10.0, 5, GridSpacing::kLog)});
  const std::string p = text::SweepPlotScript(s, "v_mean", "out.png");
  EXPECT_TRUE(Has(p, "set output 'out.png'\n"));
  EXPECT_TRUE(Has(p, "set xlabel 'T0'\nset logscale x\n"));
  EXPECT_TRUE(Has(p, "set title 'capsubot sweep: v_mean against T0'\n"));
  // A quote in the file name is doubled inside gnuplot's single quotes.
  EXPECT_TRUE(Has(p, "plot 'it''s.csv' using 'T0':'v_mean' with linespoints"));
  EXPECT_EQ(p.find("palette"), std::string::npos);
}

TEST(SweepPlotReport, TwoAxesAreAMapWithTheFirstAxisUpwards) {
  // 60 markers per side fill the plot: 20 x 5 points give 60 / 20 = 3.
  const SweepOptions s =
      SweepOver({Axis(ModelParameter::kRestitution, 0.0, 1.0, 5, GridSpacing::kLinear),
                 Axis(ModelParameter::kT0, 0.5, 1.0, 20, GridSpacing::kLinear)});
  const std::string p = text::SweepPlotScript(s, "I", "map.png");
  EXPECT_TRUE(Has(p, "set xlabel 'T0'\n"));
  EXPECT_TRUE(Has(p, "set ylabel 'e'\nset cblabel 'I'\n"));
  EXPECT_TRUE(Has(p, "set title 'capsubot sweep: I over T0 and e'\n"));
  EXPECT_TRUE(Has(p, "using 'T0':'e':'I' with points pt 5 ps 3 palette\n"));
  EXPECT_EQ(p.find("logscale"), std::string::npos);
}

TEST(SweepPlotReport, MarkerSizeFollowsTheLongerSideWithinItsBounds) {
  // 40 points: 60 / 40 = 1.5; 400 points: 60 / 400 = 0.15, raised to the smallest, 0.3.
  const auto size_for = [](int n) {
    return text::SweepPlotScript(
        SweepOver({Axis(ModelParameter::kRestitution, 0.0, 1.0, 2, GridSpacing::kLinear),
                   Axis(ModelParameter::kT0, 0.5, 1.0, n, GridSpacing::kLog)}),
        "I", "m.png");
  };
  EXPECT_TRUE(Has(size_for(40), " ps 1.5 palette"));
  EXPECT_TRUE(Has(size_for(400), " ps 0.3 palette"));
  EXPECT_TRUE(Has(size_for(40), "set logscale x\n"));
}

TEST(SweepPlotReport, DefaultColumnIsTheSpeedTheSweepWrites) {
  // An orbit sweep writes v_mean (the speed of the orbit), not a speed from rest.
  const SweepOptions s = SweepOver({Axis(ModelParameter::kT0, 0.5, 1.0, 3, GridSpacing::kLinear)});
  EXPECT_EQ(text::SweepPlotColumn(s, ""), "v_mean");
  EXPECT_EQ(text::SweepPlotColumn(s, "x_min"), "x_min");
}

TEST(SweepPlotReport, RefusedPlotsNameTheRule) {
  const GridAxis T0 = Axis(ModelParameter::kT0, 0.5, 1.0, 3, GridSpacing::kLinear);
  SweepOptions s = SweepOver({T0});
  EXPECT_EQ(InvalidArgumentMessage([&] { text::SweepPlotColumn(s, "status"); }),
            "plot_column = status is invalid: expected a numeric column of this sweep: T0, phi1, "
            "alpha, u, v_plus, I, v_mean, x_min, x_max, valid");
  s.output = "-";
  EXPECT_EQ(InvalidArgumentMessage([&] { text::SweepPlotColumn(s, ""); }),
            "plot with output = - is invalid: expected a file (-o FILE), which the plot reads");
  s = SweepOver({T0});
  s.shard = 1;
  s.shards = 3;
  EXPECT_EQ(InvalidArgumentMessage([&] { text::SweepPlotColumn(s, ""); }),
            "plot with shard = 1/3 is invalid: expected the whole grid (draw the merged file)");
  s = SweepOver({T0, Axis(ModelParameter::kRestitution, 0.0, 1.0, 2, GridSpacing::kLinear),
                 Axis(ModelParameter::kMean, 0.1, 0.2, 2, GridSpacing::kLinear)});
  EXPECT_EQ(InvalidArgumentMessage([&] { text::SweepPlotColumn(s, ""); }),
            "plot over a grid of 3 axes is invalid: expected one axis (a curve) or two (a map)");
}

BifurcationJobResult HandMadeStudy() {
  BifurcationJobResult r;
  r.diagram.param = ModelParameter::kT0;
  r.diagram.from = 0.08;
  r.diagram.to = 0.12;
  r.diagram.steps = 4;
  r.impacts = "imp.csv";
  r.impact_rows = 558;
  return r;
}

TEST(BifurcationTextReport, WholeStudySaysItsRangeAndFiles) {
  BifurcationJobResult r = HandMadeStudy();
  EXPECT_EQ(text::BifurcationJobText(r),
            "bifurcation diagram over T0 = 0.08 .. 0.12 (4 values, "
            "both): 558 impacts written to imp.csv\n");
  r.diagram.down = false;
  r.diagram.over_values = {0.1, 0.2, 0.3};
  r.diagram.over = ModelParameter::kRestitution;
  r.summary = "sum.csv";
  r.summary_rows = 40;
  EXPECT_EQ(text::BifurcationJobText(r),
            "bifurcation diagram over T0 = 0.08 .. 0.12 (4 values, up) for 3 values of e: 558 "
            "impacts written to imp.csv, 40 summary rows to sum.csv\n");
}

TEST(BifurcationTextReport, ShardSaysItsPartOfTheContinuationsAndWhatWasResumed) {
  BifurcationJobResult r = HandMadeStudy();
  r.diagram.up = false;
  r.diagram.over_values = {0.1, 0.2, 0.3};
  r.diagram.over = ModelParameter::kRestitution;
  r.diagram.shard = 1;
  r.diagram.shards = 2;
  r.parts = 4;
  r.parts_resumed = 1;
  // One direction over 3 values of e: 3 continuations.
  EXPECT_EQ(text::BifurcationJobText(r),
            "bifurcation diagram over T0 = 0.08 .. 0.12 (4 values, down) for 3 values of e, shard "
            "1/2 of 3 continuations: 558 impacts written to imp.csv (3 of the shard's 4 parts "
            "computed, 1 resumed from the checkpoint)\n");
}

}  // namespace
}  // namespace capsubot
