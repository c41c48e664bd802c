// The bifurcation job (capsubot/job/bifurcation_job.hpp): its diagram is ComputeBifurcation's
// and its files are the CSV of that diagram; its shards join into the file of the whole study;
// the robot's alpha comes from the diagram when it steps alpha; bad options are named.

#include "capsubot/job/bifurcation_job.hpp"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <functional>
#include <sstream>
#include <string>
#include <vector>

#include "capsubot/sweep/bifurcation_shards.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::ReadFile;

using testing::InvalidArgumentMessage;

// A short diagram over T0 of the small stable orbit's robot (docs/attractors.md), for 2
// values of e: 4 continuations.
BifurcationJobOptions SmallStudy(const std::string& name) {
  BifurcationJobOptions job;
  job.robot.forcing = Forcing::Harmonic(0.05, 0.02, -2.842);
  job.robot.params.e = 0.5;
  job.robot.alpha = 0.2792869076315278;
  BifurcationOptions& d = job.diagram;
  d.param = ModelParameter::kT0;
  d.from = 0.08;
  d.to = 0.12;
  d.steps = 3;
  d.motion.transient = 40;
  d.motion.record = 20;
  d.over = ModelParameter::kRestitution;
  d.over_values = {0.4, 0.5};
  d.threads = 2;
  job.files.impacts = testing::TempPath(name + "_impacts.csv").string();
  job.files.summary = testing::TempPath(name + "_summary.csv").string();
  job.files.comments = "# a study\n";
  return job;
}

TEST(BifurcationJob, WritesTheDiagramOfComputeBifurcation) {
  const BifurcationJobOptions job = SmallStudy("bifurcation_job");
  const BifurcationJobResult r = RunBifurcationJob(job);
  const BifurcationDiagram d =
      ComputeBifurcation({job.robot.forcing, job.robot.params, job.robot.alpha}, job.diagram);
  ASSERT_EQ(r.rows.impacts.size(), d.impacts.size());
  ASSERT_EQ(r.rows.summary.size(), d.summary.size());
  for (std::size_t i = 0; i < d.impacts.size(); ++i) {
    EXPECT_EQ(r.rows.impacts[i].phase, d.impacts[i].phase) << i;
    EXPECT_EQ(r.rows.impacts[i].velocity, d.impacts[i].velocity) << i;
  }
  EXPECT_EQ(r.impact_rows, static_cast<std::int64_t>(d.impacts.size()));
  EXPECT_EQ(r.summary_rows, static_cast<std::int64_t>(d.summary.size()));
  EXPECT_EQ(r.parts, 0);
  std::string impacts = job.files.comments + BifurcationImpactsHeader(job.diagram);
  AppendImpactRows(impacts, d, true);
  std::string summary = job.files.comments + BifurcationSummaryHeader(job.diagram);
  AppendSummaryRows(summary, d, true);
  EXPECT_TRUE(ReadFile(job.files.impacts) == impacts);
  EXPECT_TRUE(ReadFile(job.files.summary) == summary);
}

TEST(BifurcationJob, ItsShardsJoinIntoTheFileOfTheWholeStudy) {
  const BifurcationJobOptions whole = SmallStudy("bifurcation_whole");
  RunBifurcationJob(whole);
  std::vector<std::string> impacts;
  int parts = 0;
  for (int k = 0; k < 2; ++k) {
    BifurcationJobOptions shard = SmallStudy("bifurcation_shard" + std::to_string(k));
    shard.diagram.shard = k;
    shard.diagram.shards = 2;
    const BifurcationJobResult r = RunBifurcationJob(shard);
    parts += r.parts;
    EXPECT_EQ(r.parts_resumed, 0);
    EXPECT_TRUE(r.rows.impacts.empty());
    impacts.push_back(shard.files.impacts);
  }
  EXPECT_EQ(parts,
            BifurcationParts(PlanBifurcationJob(whole).diagram));  // 2 x (up, down, analytic)
  const std::string joined = testing::TempPath("bifurcation_joined.csv").string();
  MergeBifurcationShards(impacts, joined);
  EXPECT_TRUE(ReadFile(joined) == ReadFile(whole.files.impacts));
}

TEST(BifurcationJob, TheDiagramGivesAlphaWhenItStepsAlpha) {
  BifurcationJobOptions job = SmallStudy("bifurcation_alpha");
  job.robot.alpha = std::nan("");
  job.diagram.param = ModelParameter::kAlpha;
  job.diagram.from = 0.25;
  job.diagram.to = 0.3;
  EXPECT_EQ(PlanBifurcationJob(job).robot.alpha, 0.25);
  job.diagram.param = ModelParameter::kT0;
  job.diagram.from = 0.08;
  job.diagram.to = 0.12;
  job.diagram.over = ModelParameter::kAlpha;
  job.diagram.over_values = {0.27, 0.28};
  EXPECT_EQ(PlanBifurcationJob(job).robot.alpha, 0.27);
  job.diagram.over_values.clear();
  EXPECT_EQ(InvalidArgumentMessage([&] { job.Validate(); }),
            "alpha is missing: give the mass ratio of the robot");
}

TEST(BifurcationJob, AnalyticOrbitsOnlyWithASummaryFile) {
  BifurcationJobOptions job = SmallStudy("bifurcation_analytic");
  EXPECT_TRUE(PlanBifurcationJob(job).diagram.analytic);
  job.files.summary.clear();
  EXPECT_FALSE(PlanBifurcationJob(job).diagram.analytic);
}

TEST(BifurcationJob, RefusesBadOptionsNamingThem) {
  const auto message = [](const std::function<void(BifurcationJobOptions&)>& change) {
    BifurcationJobOptions job = SmallStudy("bifurcation_bad");
    change(job);
    return InvalidArgumentMessage([&] { job.Validate(); });
  };
  EXPECT_EQ(message([](BifurcationJobOptions& j) { j.diagram.to = j.diagram.from; }),
            "to = 0.08 is invalid with from = 0.08: expected a range, to other than from");
  EXPECT_EQ(message([](BifurcationJobOptions& j) { j.files.resume = true; }),
            "resume = true is invalid for the whole study: expected it only for a shard (shards "
            ">= 2; the whole study is not checkpointed)");
  EXPECT_EQ(message([](BifurcationJobOptions& j) { j.files.summary = j.files.impacts; }),
            "summary = " + SmallStudy("bifurcation_bad").files.impacts +
                " is invalid: it is the file of impacts = " +
                SmallStudy("bifurcation_bad").files.impacts + ": expected another file");
  EXPECT_EQ(message([](BifurcationJobOptions& j) { j.files.impacts.clear(); }),
            "impacts is missing: expected the path of the impacts CSV");
  EXPECT_EQ(message([](BifurcationJobOptions& j) {
              j.diagram.shards = 5;
            }).rfind("shard count N = 5 is invalid: the study has 4 continuations", 0),
            0U);
}

TEST(BifurcationJob, DirectionsAndSecondParameterFromTheirNames) {
  BifurcationOptions o;
  SetBifurcationDirection("down", o);
  EXPECT_FALSE(o.up);
  EXPECT_TRUE(o.down);
  SetBifurcationDirection("both", o);
  EXPECT_TRUE(o.up && o.down);
  EXPECT_EQ(InvalidArgumentMessage([&] { SetBifurcationDirection("sideways", o); }),
            "direction = sideways is invalid: expected up, down or both");
  SetBifurcationOver("b2=0.1,0.3", o);
  EXPECT_EQ(o.over, ModelParameter::kSin);
  EXPECT_EQ(o.over_harmonic, 2);
  EXPECT_EQ(o.over_values, (std::vector<double>{0.1, 0.3}));
  // Refused from its size, before its values are held.
  EXPECT_EQ(InvalidArgumentMessage([&] { SetBifurcationOver("e=0:1:200000", o); }),
            "over = e=0:1:200000 is invalid: 200000 values: expected at most 100000 values");
}

}  // namespace
}  // namespace capsubot
