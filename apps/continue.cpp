// capsubot continue: pseudo-arclength continuation of a periodic motion in one model parameter,
// with its special points (docs/continuation.md).

#include <fmt/format.h>

#include <memory>
#include <optional>
#include <string>

#include "attract_options.hpp"
#include "capsubot/io/io.hpp"
#include "capsubot/job/continue_job.hpp"
#include "capsubot/report/continuation_json.hpp"
#include "capsubot/report/continue_csv.hpp"
#include "capsubot/report/continue_text.hpp"
#include "commands.hpp"
#include "help_format.hpp"
#include "progress.hpp"
#include "provenance.hpp"
#include "result_output.hpp"

namespace capsubot::app {
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
  job.forcing = opt.robot.forcing.Build();
  job.params = opt.robot.params;
  job.alpha = opt.robot.alpha;
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
    written = fmt::format("  written        {} {}points to {}\n", table.rows,
                          job.follow ? "curve " : "", opt.output);
  }
  fmt::print("{}", opt.json ? JsonOutput(json::ContinueJobJson(result), JsonProvenance(cmd))
                            : text::ContinueJobText(result) + written);
  return 0;
}

// The continuation's fields as the flags that set them.
const FlagNames& ContinueFlagNames() {
  static const FlagNames names = {{"param", "--param"},
                                  {"from", "--from"},
                                  {"to", "--to"},
                                  {"max_points", "--max-points"},
                                  {"initial_step", "--initial-step"},
                                  {"min_step", "--min-step"},
                                  {"max_step", "--max-step"},
                                  {"max_period", "--max-period"},
                                  {"step", "--step"},
                                  {"chatter_velocity", "--chatter-velocity"},
                                  {"from_orbit", "--from-orbit"},
                                  {"param2", "--param2"},
                                  {"from2", "--from2"},
                                  {"to2", "--to2"},
                                  {"follow", "--follow"},
                                  {"switch", "--switch-at"}};
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
  opt.param2 =
      cmd.add_option("--param2", opt.follow.param2,
                     "also follow the branch's first located special point of the --follow "
                     "type in two parameters, this one the second (a parameter other than "
                     "--param)");
  CLI::Option* from2 =
      cmd.add_option("--from2", opt.follow.from2, "lower end of the --param2 range");
  CLI::Option* to2 = cmd.add_option("--to2", opt.follow.to2, "upper end of the --param2 range");
  CLI::Option* follow =
      cmd.add_option("--follow", opt.follow_type,
                     "the special point followed with --param2: fold, period_doubling, "
                     "grazing or speed_extremum");
  opt.param2->needs(from2)->needs(to2)->needs(follow);
  from2->needs(opt.param2);
  to2->needs(opt.param2);
  follow->needs(opt.param2);
}

// The steps of the continuation and of its shooting.
void AddStepOptions(CLI::App& cmd, ContinueCommandOptions& opt) {
  cmd.add_option("--max-points", opt.job.continuation.max_points,
                 "points of the branch (and of the curve), both directions together")
      ->capture_default_str();
  cmd.add_option("--initial-step", opt.job.continuation.initial_step, "first arclength step")
      ->capture_default_str();
  cmd.add_option("--min-step", opt.job.continuation.min_step,
                 "smallest arclength step: a failure there ends the branch (lost)")
      ->capture_default_str();
  cmd.add_option("--max-step", opt.job.continuation.max_step, "largest arclength step")
      ->capture_default_str();
  cmd.add_option("--max-period", opt.job.continuation.shooting.max_period,
                 "largest period searched at the start, in forcing periods")
      ->capture_default_str();
  cmd.add_option("--step", opt.job.continuation.shooting.step,
                 "step of the central finite differences of the Jacobians")
      ->capture_default_str();
  cmd.add_option("--chatter-velocity", opt.job.continuation.shooting.chatter_velocity,
                 "the simulator's chatter cut-off (omega L)")
      ->capture_default_str();
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
  cmd->add_option("--param", opt->job.param,
                  "the parameter followed: A, c, alpha, T0, e, phi0, or a Fourier coefficient "
                  "a1..a16, b1..b16")
      ->required();
  cmd->add_option("--from", opt->job.continuation.from, "lower end of the range")->required();
  cmd->add_option("--to", opt->job.continuation.to, "upper end of the range")->required();
  opt->start_state.Add(*cmd);
  cmd->add_flag("--from-orbit", opt->from_orbit,
                "start on the robot's valid one-impact orbit with the smallest spectral radius "
                "(capsubot orbits), right after its impact");
  AddBranchOptions(*cmd, *opt);
  AddStepOptions(*cmd, *opt);
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

}  // namespace capsubot::app
