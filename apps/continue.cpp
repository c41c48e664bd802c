// capsubot continue: pseudo-arclength continuation of a periodic motion in one model parameter,
// with its special points (docs/continuation.md).

#include <fmt/format.h>

#include <memory>
#include <optional>
#include <string>

#include "capsubot/cli/attract_options.hpp"
#include "capsubot/cli/help_format.hpp"
#include "capsubot/cli/progress.hpp"
#include "capsubot/cli/provenance.hpp"
#include "capsubot/cli/result_output.hpp"
#include "capsubot/cli/setting_options.hpp"
#include "capsubot/io/io.hpp"
#include "capsubot/job/continue_job.hpp"
#include "capsubot/job/continue_settings.hpp"
#include "capsubot/job/shooting_settings.hpp"
#include "capsubot/report/continuation_json.hpp"
#include "capsubot/report/continue_csv.hpp"
#include "capsubot/report/continue_text.hpp"
#include "commands.hpp"

namespace capsubot::cli {
namespace {

struct ContinueCommandOptions {
  RobotOptions robot;
  ContinueJobOptions job;
  StartStateOptions start_state;  // --x0, --u0, --v0, --psi
  bool from_orbit = false;
  bool switch_branch = false;
  std::string switch_at;
  FollowOptions follow;
  std::string follow_type;
  CLI::Option* param2 = nullptr;
  bool json = false;
  std::string output;
};

int Run(ContinueCommandOptions& opt, const CLI::App& cmd) {
  ContinueJobOptions& job = opt.job;
  const std::optional<PhaseState> state =
      opt.start_state.Spec().Build(opt.from_orbit, "from_orbit", "--from-orbit", kStartFlags);
  job.start = state ? ContinueStart(*state) : FromOneImpactOrbit{};
  job.robot = opt.robot.Model();
  if (opt.switch_branch) job.switch_at = SwitchPoint::kPeriodDoubling;
  if (!opt.switch_at.empty()) job.switch_at = ParseSwitchPoint(opt.switch_at);
  if (opt.param2->count() > 0) {
    opt.follow.type = ParseFollowType(opt.follow_type);
    job.follow = opt.follow;
  }
  job.on_stage = [](const std::string& stage) { ShowStage(stage); };
  job.Validate();
  RequireOutputApartFromJson(opt.output, "-o", opt.json);
  if (!opt.output.empty()) CheckWritable(opt.output, "-o");
  const ContinueJobResult result = RunContinueJob(job);
  const text::CsvTable table = text::ContinueJobCsv(result);
  std::string written;  // the note of the text on the CSV written
  if (!opt.output.empty() && table.rows > 0) {
    AtomicFile file(opt.output, "-o");
    file.stream() << OutputProvenance(cmd).CommentLine() << table.text;
    file.Commit();
    written = text::ContinueCsvWritten(result, table, opt.output);
  }
  fmt::print("{}", opt.json ? JsonOutput(json::ContinueJobJson(result), JsonProvenance(cmd))
                            : text::ContinueJobText(result) + written);
  return 0;
}

// The continuation's fields as the flags that set them: "--" and the field, and --switch-at.
const FlagNames& ContinueFlagNames() {
  static const FlagNames names = [] {
    FlagNames n = WithDashedFlags({}, ContinueParamSettings(), ContinuationRangeSettings(),
                                  ContinuationStepSettings(), ShootingSettings(), FollowSettings());
    n.insert(n.end(),
             {{"from_orbit", "--from-orbit"}, {"follow", "--follow"}, {"switch", "--switch-at"}});
    return n;
  }();
  return names;
}

// Beyond the branch: --switch, --switch-at, and the two-parameter curve (--param2, --from2,
// --to2, --follow).
void AddBranchOptions(CLI::App& cmd, ContinueCommandOptions& opt) {
  CLI::Option* switch_flag = cmd.add_flag(
      "--switch", opt.switch_branch,
      "also follow the period-2p branch born at the first located period doubling "
      "(predictor along the eigenvector of the multiplier -1, shooting with period 2p)");
  cmd.add_option("--switch-at", opt.switch_at,
                 "also follow a branch switched to at the first point of this kind: "
                 "period_doubling (as --switch) or grazing (the motion with other impacts per "
                 "period just beyond the first grazing, by Newton shooting from its state)")
      ->type_name("POINT")
      ->excludes(switch_flag);
  AddSettings(cmd, opt.follow, FollowSettings(), ContinueFlagNames());
  CLI::Option* follow =
      cmd.add_option("--follow", opt.follow_type,
                     "the special point followed with --param2: fold, period_doubling, "
                     "grazing or speed_extremum");
  opt.param2 = cmd.get_option("--param2");
  for (CLI::Option* part : {cmd.get_option("--from2"), cmd.get_option("--to2"), follow}) {
    opt.param2->needs(part);
    part->needs(opt.param2);
  }
}

}  // namespace

Command AddContinueCommand(CLI::App& app) {
  auto opt = std::make_shared<ContinueCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "continue",
      "Follow a periodic motion through a range of one model parameter by pseudo-arclength "
      "continuation of the fixed point of the stroboscopic map, with its folds, period "
      "doublings, Neimark-Sacker points, grazings, segment changes and speed extrema "
      "(docs/continuation.md). The parameter starts at the robot's value; the start is a state "
      "(--x0 --u0 --v0 --psi) or the robot's one-impact orbit (--from-orbit).");
  AddRobotOptions(*cmd, opt->robot, false);
  const FlagNames& flags = ContinueFlagNames();
  AddSettings(*cmd, opt->job, ContinueParamSettings(), flags);
  AddSettings(*cmd, opt->job.continuation, ContinuationRangeSettings(), flags);
  for (const char* flag : {"--param", "--from", "--to"}) cmd->get_option(flag)->required();
  opt->start_state.Add(*cmd);
  cmd->add_flag("--from-orbit", opt->from_orbit,
                "start on the robot's valid one-impact orbit with the smallest spectral radius "
                "(capsubot orbits), right after its impact");
  AddBranchOptions(*cmd, *opt);
  AddSettings(*cmd, opt->job.continuation, ContinuationStepSettings(), flags);
  AddSettings(*cmd, opt->job.continuation.shooting, ShootingSettings(), flags);
  cmd->add_option("-o,--output", opt->output,
                  "CSV of the branch: parameter, x, u, v, psi, period, impacts_right, "
                  "impacts_left, mean_velocity, spectral_radius, muK_re, muK_im, stable, label; "
                  "with --param2 the curve: parameter, parameter2, x, ..., stable, condition")
      ->type_name("FILE");
  cmd->add_flag("--json", opt->json,
                "print one JSON object: parameter, status, ends, points, special_points, "
                "(switched, follow, curve,) provenance");
  SetExamples(*cmd,
              {{"a stable one-impact gait followed in alpha: born in a period doubling, "
                "fastest at alpha = 0.2399, ended by a fold at 0.29035",
                "continue --A 0.05 --c 0.02 --phi0 -2.842 --T0 0.1 --e 0.5 "
                "--alpha 0.2792869076315278 --from-orbit --param alpha --from 0.2 --to 0.3"}});
  return {
      cmd,
      [opt, cmd] { return RunNamingFlags(ContinueFlagNames(), [&] { return Run(*opt, *cmd); }); },
      {}};
}

}  // namespace capsubot::cli
