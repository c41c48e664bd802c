// capsubot attractors: the long-run motions reached from rest on a grid of starts
// (docs/model.md sections 12 and 13), with the exact simulator.

#include <fmt/format.h>

#include <memory>
#include <optional>
#include <stdexcept>
#include <tuple>
#include <vector>

#include "attract_options.hpp"
#include "capsubot/sweep/start_map.hpp"
#include "commands.hpp"
#include "help_format.hpp"
#include "progress.hpp"
#include "provenance.hpp"
#include "report.hpp"
#include "start_shard.hpp"
#include "whole_map.hpp"

namespace capsubot::app {
namespace {

struct AttractorsCommandOptions {
  RobotOptions robot;
  std::string starts = "8x8";
  std::string output;  // the per-start CSV; empty: none
  StartShardCliOptions shard;
  int threads = 0;
  bool json = false;
};

int Run(const AttractorsCommandOptions& opt, const CLI::App& cmd) {
  const Forcing forcing = opt.robot.forcing.Build();
  int n_x = 0, n_psi = 0;
  std::tie(n_x, n_psi) = ParseGridSize("--starts", opt.starts);  // the rules of FromRestOptions
  const std::vector<PhaseState> starts = GridStarts(n_x, n_psi);
  AttractorOptions ao;
  ao.motion = opt.robot.motion;
  ao.threads = CapThreads(opt.threads, "capsubot attractors");
  RequireShardForResume(cmd, opt.shard);
  if (SplitsRun(opt.shard.shard)) {
    if (opt.output.empty()) {
      throw std::invalid_argument(
          "--shard is invalid without -o: expected the shard file to write (docs/cluster.md)");
    }
    return RunStartShard(opt.shard, cmd, opt.robot, forcing, starts, ao, false, opt.output,
                         {{"--json", opt.json}});
  }
  // The starts from rest of FindAttractors, classified on the ranks under mpirun.
  const std::optional<Attractors> map =
      ClassifyWholeMap(opt.robot, forcing, starts, ao, opt.output);
  if (!map) return 0;  // a worker of an MPI job: rank 0 writes and prints
  const Attractors& a = *map;
  if (!opt.output.empty()) {
    WriteStartMap(opt.output, starts, a, false, OutputProvenance(cmd).CommentLine());
  }
  if (opt.json) {
    nlohmann::json j = AttractorsJson(a);
    AddProvenanceJson(j, cmd);
    fmt::print("{}\n", j.dump());
    return 0;
  }
  const MotionOptions& mo = ao.motion;
  std::string t =
      fmt::format("attractors from rest: {} starts ({} x0 x {} phases), {} + {} periods\n",
                  a.starts, n_x, n_psi, mo.transient, mo.record);
  t += fmt::format("  force          {}\n", ForceFormula(forcing));
  t += fmt::format("  model          T0 = {}, e = {}, alpha = {}\n", opt.robot.params.T0,
                   opt.robot.params.e, opt.robot.alpha);
  int k = 0;
  for (const Attractor& at : a.attractors) {
    t += fmt::format("  {:>2}. {:5.1f} % of starts  mean velocity {:<13} {}{}\n", ++k,
                     100.0 * at.fraction, Num(at.mean_velocity, 10),
                     AttractorWords(at, mo.max_period),
                     at.one_impact_orbit ? "  (the analytic one-impact orbit)" : "");
    t += fmt::format("      e.g. from x0 = {:.6g}, psi = {:.6g}\n", at.example.x, at.example.psi);
  }
  t += fmt::format("  mean velocity over the starts: {} (omega L)", Num(a.mean_velocity, 10));
  if (a.event_limit_starts > 0) {
    t += fmt::format(", {} starts hit the work bound and are left out", a.event_limit_starts);
  }
  t += "\n";
  if (!opt.output.empty())
    t += fmt::format("  the motion of every start written to {}\n", opt.output);
  fmt::print("{}", t);
  return 0;
}

}  // namespace

Command AddAttractorsCommand(CLI::App& app) {
  auto opt = std::make_shared<AttractorsCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "attractors",
      "What the robot does from rest (docs/model.md sections 12 and 13): the exact simulator is "
      "started with shell and inner body at rest, the inner body at x0 = (i + 0.5)/NX and the "
      "forcing at phase psi = 2 pi j/NPSI (F = A sin(psi + phi0) + c at the start); after a "
      "transient the long-run motion of each start is classified (period, impacts, mean "
      "velocity) and equal motions are grouped into attractors.");
  AddRobotOptions(*cmd, opt->robot);
  cmd->add_option("--starts", opt->starts, "grid of starts NXxNPSI (positions x phases)")
      ->capture_default_str();
  cmd->add_option("-o,--output", opt->output,
                  "also write the motion of every start to this CSV (x0, psi, attractor, period, "
                  "impacts_right, impacts_left, mean_velocity, status: the map of `basins`; "
                  "written atomically)")
      ->type_name("FILE");
  AddStartShardOptions(*cmd, opt->shard, "attractors");
  AddThreadsOption(*cmd, opt->threads);
  cmd->add_flag("--json", opt->json,
                "print one JSON object: starts, attractors (status, period, impacts_right, "
                "impacts_left, mean_velocity, fraction, starts, example_start {x0, psi}, "
                "one_impact_orbit), mean_velocity (over the starts), event_limit_starts, "
                "provenance");
  AddProgressOptions(*cmd);
  SetExamples(*cmd, {{"the fastest stable one-impact gait started from rest on an 8 x "
                      "8 grid: every start settles into another motion",
                      "attractors --A 0.34063197373861814 --c 0.06410131873607934 "
                      "--phi0 -3.1181183398453047 --alpha 0.6435592358295166 --T0 1 "
                      "--e 1"}});
  return {cmd,
          [opt, cmd] { return RunNamingFlags(MotionFlagNames(), [&] { return Run(*opt, *cmd); }); },
          [] { return true; }};
}

}  // namespace capsubot::app
