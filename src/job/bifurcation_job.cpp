// `capsubot bifurcation` as one call (capsubot/job/bifurcation_job.hpp).

#include "capsubot/job/bifurcation_job.hpp"

#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <stdexcept>

#include "capsubot/io/io.hpp"
#include "capsubot/sweep/grid.hpp"

namespace capsubot {
namespace {

// The whole study's files, written once the diagram is computed: both or neither.
void WriteDiagram(const BifurcationDiagram& rows, const BifurcationOptions& diagram,
                  const BifurcationShardFiles& files) {
  const bool over = !diagram.over_values.empty();
  std::string text = files.comments + BifurcationImpactsHeader(diagram);
  AppendImpactRows(text, rows, over);
  AtomicFile impacts(files.impacts, "impacts");
  impacts.stream() << text;
  std::unique_ptr<AtomicFile> summary;
  if (!files.summary.empty()) {
    text = files.comments + BifurcationSummaryHeader(diagram);
    AppendSummaryRows(text, rows, over);
    summary = std::make_unique<AtomicFile>(files.summary, "summary");
    summary->stream() << text;
  }
  impacts.Commit();
  if (summary) summary->Commit();
}

}  // namespace

void SetBifurcationDirection(const std::string& name, BifurcationOptions& options) {
  if (name != "up" && name != "down" && name != "both") {
    throw std::invalid_argument(
        fmt::format("direction = {} is invalid: expected up, down or both", name));
  }
  options.up = name != "down";
  options.down = name != "up";
}

void SetBifurcationOver(const std::string& spec, BifurcationOptions& options) {
  const GridAxis axis = ParseGridAxis(spec);
  options.over = ParseRobotParameter(axis.name(), &options.over_harmonic);
  if (axis.size() > kMaxOverValues) {
    throw std::invalid_argument(
        fmt::format("over = {} is invalid: {} values: expected at most {} values", spec,
                    axis.size(), kMaxOverValues));
  }
  options.over_values.clear();
  for (std::int64_t i = 0; i < axis.size(); ++i) options.over_values.push_back(axis.Value(i));
}

BifurcationJobPlan PlanBifurcationJob(const BifurcationJobOptions& options) {
  const BifurcationShardFiles& files = options.files;
  RequireDistinctOutputs({{files.impacts, "impacts"}, {files.summary, "summary"}});
  files.Validate();
  BifurcationJobPlan plan{options.robot, options.diagram};
  BifurcationOptions& d = plan.diagram;
  if (files.resume && d.shards < 2) {
    throw std::invalid_argument(
        "resume = true is invalid for the whole study: expected it only for a shard (shards >= "
        "2; the whole study is not checkpointed)");
  }
  // The analytic orbits are summary rows; a pulse force has none (they need a smooth force).
  d.analytic = d.analytic && !files.summary.empty() && !plan.robot.forcing.pulse();
  double& alpha = plan.robot.alpha;
  if (d.param == ModelParameter::kAlpha) alpha = d.from;  // the stepped value decides
  if (!d.over_values.empty() && d.over == ModelParameter::kAlpha) alpha = d.over_values.front();
  if (std::isnan(alpha)) {
    throw std::invalid_argument("alpha is missing: give the mass ratio of the robot");
  }
  if (d.from == d.to) {  // one value: no diagram (and "up" and "down" would be the same)
    throw std::invalid_argument(
        fmt::format("to = {} is invalid with from = {}: expected a range, to other than from",
                    FormatNumber(d.to), FormatNumber(d.from)));
  }
  ValidateBifurcation(plan.robot, d);
  return plan;
}

void BifurcationJobOptions::Validate() const { (void)PlanBifurcationJob(*this); }

BifurcationJobResult RunBifurcationJob(const BifurcationJobOptions& options,
                                       const BlockBackend& backend) {
  const BifurcationJobPlan plan = PlanBifurcationJob(options);
  const RobotModel& robot = plan.robot;
  BifurcationJobResult result;
  result.diagram = plan.diagram;
  result.impacts = options.files.impacts;
  result.summary = options.files.summary;
  if (plan.diagram.shards > 1) {
    const BifurcationShardSummary s =
        WriteBifurcationShard(robot, plan.diagram, options.files, options.progress, backend);
    result.impact_rows = s.impacts;
    result.summary_rows = s.summary_rows;
    result.parts = s.parts;
    result.parts_resumed = s.resumed;
    return result;
  }
  CheckWritable(options.files.impacts, "impacts");  // fail on an unwritable path before the run
  result.rows = ComputeBifurcation(robot, plan.diagram, options.progress, backend);
  WriteDiagram(result.rows, plan.diagram, options.files);
  result.impact_rows = static_cast<std::int64_t>(result.rows.impacts.size());
  if (!result.summary.empty()) {
    result.summary_rows = static_cast<std::int64_t>(result.rows.summary.size());
  }
  return result;
}

}  // namespace capsubot
