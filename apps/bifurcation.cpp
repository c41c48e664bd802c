// capsubot bifurcation: brute-force bifurcation diagram with the state carried along, up and
// down, plus the analytic one-impact orbits (docs/model.md section 13; library:
// capsubot/job/bifurcation_job.hpp); under mpirun its parts are computed on the ranks
// (ranks.hpp).

#include <fmt/format.h>

#include <cstdint>
#include <memory>
#include <string>
#include <tuple>

#include "capsubot/cli/attract_options.hpp"
#include "capsubot/cli/help_format.hpp"
#include "capsubot/cli/progress.hpp"
#include "capsubot/cli/provenance.hpp"
#include "capsubot/cli/setting_options.hpp"
#include "capsubot/cli/shard_option.hpp"
#include "capsubot/cluster/ranks.hpp"
#include "capsubot/job/bifurcation_job.hpp"
#include "capsubot/job/bifurcation_settings.hpp"
#include "capsubot/report/bifurcation_text.hpp"
#include "capsubot/sweep/grid.hpp"
#include "commands.hpp"

namespace capsubot::cli {
namespace {

struct BifurcationCommandOptions {
  RobotOptions robot;
  BifurcationOptions diagram;
  std::string param;
  std::string direction = "both";
  std::string start = "0.5,0";
  std::string over;             // "NAME=lo:hi:n" (the sweep's axis syntax), empty: one diagram
  std::string shard;            // "K/N", empty: the whole study
  BifurcationShardFiles files;  // -o, --summary, --resume, --checkpoint-seconds
  bool no_analytic = false;
};

// The flags of the job's settings: its messages name the settings by their fields.
const FlagNames& BifurcationFlagNames() {
  static const FlagNames names = [] {
    FlagNames n = MotionFlagNames();
    n.insert(n.end(), {{"steps", "--steps"},
                       {"impacts", "-o"},
                       {"summary", "--summary"},
                       {"shard", "--shard"},
                       {"resume", "--resume"},
                       {"from", "--from"},
                       {"to", "--to"},
                       {"checkpoint_seconds", "--checkpoint-seconds"},
                       {"direction", "--direction"},
                       {"over", "--over"}});
    return n;
  }();
  return names;
}

// The job the command line describes.
BifurcationJobOptions JobOptions(const BifurcationCommandOptions& opt, const CLI::App& cmd) {
  BifurcationJobOptions job;
  job.robot = opt.robot.Model();
  BifurcationOptions& o = job.diagram;
  o = opt.diagram;
  o.param = ParseRobotParameter(opt.param, &o.harmonic);
  o.motion = opt.robot.motion;
  o.start = ParseRestStart("--start", opt.start);
  o.analytic = !opt.no_analytic;
  SetBifurcationDirection(opt.direction, o);
  if (!opt.over.empty()) SetBifurcationOver(opt.over, o);
  const bool sharded = SplitsRun(opt.shard);  // --shard 0/1: the files of the whole study
  if (sharded) std::tie(o.shard, o.shards) = ParseShard(opt.shard);
  RequireShardForResume(cmd, sharded, "study");
  job.files = opt.files;
  // The run's name, in both files: the same for a shard and the whole study (the join writes
  // it), without the paths and how it runs.
  job.files.comments = OutputProvenance(cmd).CommentLine();
  job.progress = CountProgress("parameter values");
  return job;
}

int Run(const BifurcationCommandOptions& opt, const CLI::App& cmd) {
  const BifurcationJobOptions job = JobOptions(opt, cmd);
  // Every rank checks the whole study (both ends of the range at every robot, a bad --shard)
  // before the processes of an MPI job meet: bad input fails at once, before any file is
  // touched.
  const BifurcationJobPlan plan = PlanBifurcationJob(job);
  Ranks ranks;  // under mpirun: rank 0 runs the study, the others compute its parts
  if (ranks.worker()) {
    const RobotModel& robot = plan.robot;
    return ranks.Serve(BifurcationBlocks(robot, plan.diagram), plan.diagram.threads);
  }
  fmt::print("{}", text::BifurcationJobText(RunBifurcationJob(job, ranks.backend())));
  return 0;
}

}  // namespace

Command AddBifurcationCommand(CLI::App& app) {
  auto opt = std::make_shared<BifurcationCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "bifurcation",
      "Bifurcation diagram by brute force (docs/model.md section 13): the parameter is stepped "
      "over its range with the state carried from each value to the next, up and then down, so "
      "coexisting attractors show as hysteresis. At each value: a transient, then the impacts of "
      "the record (-o) and a summary row (--summary) with the period, impacts, mean velocity and "
      "largest multiplier (Newton shooting), plus the valid analytic one-impact orbits "
      "(direction = analytic). --over: one diagram per value of a second parameter; --shard "
      "K/N: some of the continuations, joined by `capsubot merge`; under mpirun the parts "
      "(up, down, analytic per value) run on the ranks (docs/cluster.md).");
  AddRobotOptions(*cmd, opt->robot);
  cmd->get_option("--alpha")->required(false)->description(
      "mass ratio m2/(m1+m2) of the robot, 0 < alpha < 1 (not needed with --param alpha)");
  cmd->add_option("--param", opt->param,
                  "the parameter: A, c, alpha, T0, e, phi0, or a Fourier coefficient a1, b1, "
                  "a2, ... (a_k, b_k of the force given by --sin/--cos; a1 and b1 of the "
                  "harmonic force are 0 and A)")
      ->required();
  const FlagNames& flags = BifurcationFlagNames();
  AddSettings(*cmd, opt->diagram, BifurcationRangeSettings(), flags);
  for (const char* flag : {"--from", "--to"}) cmd->get_option(flag)->required();
  cmd->add_option("--direction", opt->direction, "up, down or both (up, then down)")
      ->capture_default_str();
  cmd->add_option("--start", opt->start,
                  "start of each sweep: from rest at x0 = X0, forcing phase PSI")
      ->type_name("X0,PSI")
      ->capture_default_str();
  cmd->add_option("-o,--output", opt->files.impacts,
                  "CSV of every recorded impact: param, direction, period_index, wall, phase, "
                  "velocity")
      ->required()
      ->type_name("FILE");
  cmd->add_option("--summary", opt->files.summary,
                  "CSV, one row per value and direction: param, direction, period, "
                  "impacts_right, impacts_left, mean_velocity, largest_multiplier (real part), "
                  "largest_multiplier_im, spectral_radius, status; plus the analytic orbits")
      ->type_name("FILE");
  cmd->add_flag("--no-analytic", opt->no_analytic,
                "leave the analytic one-impact orbits out of the summary");
  cmd->add_option("--over", opt->over,
                  "a two-parameter study: one diagram per value of this second parameter, "
                  "NAME=lo:hi:n, NAME=lo:hi:n:log or NAME=v1,v2,... (the syntax of `sweep "
                  "--grid`; NAME one of the --param choices); both CSVs get a first column NAME")
      ->type_name("NAME=LO:HI:N");
  cmd->add_option("--shard", opt->shard,
                  "compute only shard K of N (0 <= K < N <= the continuations, one per "
                  "direction and value of --over): the continuations q with q % N = K (q = "
                  "value index x directions + direction); the files get a comment line naming "
                  "the run, a line '# shard K/N of T continuations' and a line '# part P of Q: "
                  "R rows' before each part; `capsubot merge OUT SHARDS...` joins the N files "
                  "of -o (or of --summary) into the file of the whole study (docs/cluster.md); a "
                  "shard's files are written as FILE.partial with checkpoints (--resume); 0/1 "
                  "writes the files of the whole study");
  AddSettings(*cmd, opt->files, BifurcationResumeSettings(), flags);
  AddThreadsOption(*cmd, opt->diagram.threads);
  AddProgressOptions(*cmd);
  SetExamples(*cmd, {{"a diagram over T0, stepped up and down, for 3 values of e",
                      "bifurcation --A 0.05 --c 0.02 --phi0 -2.842 --e 0.5 --alpha "
                      "0.2792869076315278 --param T0 --from 0.08 --to 0.12 --steps 4 "
                      "--transient 40 --record 20 --over e=0.4:0.6:3 -o i.csv --summary "
                      "s.csv"}});
  return {
      cmd,
      [opt, cmd] {
        // The study's messages speak of the shard count N and the shard K, not of the
        // flag's K/N, and of the checkpoints resumed as every grid command does.
        static const FlagNames kMessageNames = Without(BifurcationFlagNames(), {"shard", "resume"});
        return RunNamingFlags(kMessageNames, [&] { return Run(*opt, *cmd); });
      },
      [] { return true; }};
}

}  // namespace capsubot::cli
