// capsubot attractors: the long-run motions reached from rest on a grid of starts
// (docs/model.md sections 12 and 13), with the exact simulator.

#include <memory>
#include <stdexcept>

#include "capsubot/cli/attract_options.hpp"
#include "capsubot/cli/help_format.hpp"
#include "capsubot/cli/provenance.hpp"
#include "capsubot/cli/result_output.hpp"
#include "capsubot/cli/shard_option.hpp"
#include "capsubot/cli/start_shard.hpp"
#include "capsubot/job/attractors_job.hpp"
#include "capsubot/report/attractors_json.hpp"
#include "capsubot/report/attractors_text.hpp"
#include "commands.hpp"

namespace capsubot::cli {
namespace {

int Run(const MapCommandOptions& opt, const CLI::App& cmd) {
  AttractorsJobOptions o = MapJobOptions(opt.robot, opt.starts, opt.threads);
  if (SplitsRun(opt.shard.shard) && opt.output.empty()) {
    throw std::invalid_argument(
        "--shard is invalid without -o: expected the shard file to write (docs/cluster.md)");
  }
  RequireOutputApartFromJson(opt.output, "-o", opt.json);
  o.run = MapRun(opt.shard, cmd, opt.output, {{"--json", opt.json}});
  return RunMapOnRanks(
      o, [&o] { return AttractorsJobWork(o); },
      [&] {
        const AttractorsJobResult r = RunAttractorsJob(o);
        return opt.json ? JsonOutput(json::AttractorsJobJson(r), JsonProvenance(cmd))
                        : text::AttractorsJobText(r);
      });
}

}  // namespace

Command AddAttractorsCommand(CLI::App& app) {
  auto opt = std::make_shared<MapCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "attractors",
      "What the robot does from rest (docs/model.md sections 12 and 13): the exact simulator is "
      "started with shell and inner body at rest, the inner body at x0 = (i + 0.5)/NX and the "
      "forcing at phase psi = 2 pi j/NPSI (F = A sin(psi + phi0) + c at the start); after a "
      "transient the long-run motion of each start is classified (period, impacts, mean "
      "velocity) and equal motions are grouped into attractors.");
  AddMapStartOptions(*cmd, *opt, "grid of starts NXxNPSI (positions x phases)");
  cmd->add_option("-o,--output", opt->output,
                  "also write the motion of every start to this CSV (x0, psi, attractor, period, "
                  "impacts_right, impacts_left, mean_velocity, status: the map of `basins`; "
                  "written atomically)")
      ->type_name("FILE");
  AddMapRunOptions(*cmd, *opt, "attractors",
                   "print one JSON object: starts, attractors (status, period, impacts_right, "
                   "impacts_left, mean_velocity, fraction, starts, example_start {x0, psi}, "
                   "one_impact_orbit), mean_velocity (over the starts), event_limit_starts, "
                   "provenance");
  SetExamples(*cmd, {{"the fastest stable one-impact gait started from rest on an 8 x "
                      "8 grid: every start settles into another motion",
                      "attractors --A 0.34063197373861814 --c 0.06410131873607934 "
                      "--phi0 -3.1181183398453047 --alpha 0.6435592358295166 --T0 1 "
                      "--e 1"}});
  return MapCommand(cmd, [opt, cmd] { return Run(*opt, *cmd); });
}

}  // namespace capsubot::cli
