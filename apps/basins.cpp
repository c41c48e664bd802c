// capsubot basins: the attractor reached from every start of a grid (docs/model.md sections 12
// and 13), as a CSV map and optionally a PNG drawn by gnuplot.

#include <fmt/format.h>

#include <memory>
#include <stdexcept>
#include <string>

#include "capsubot/cli/attract_options.hpp"
#include "capsubot/cli/gnuplot.hpp"
#include "capsubot/cli/help_format.hpp"
#include "capsubot/cli/provenance.hpp"
#include "capsubot/cli/result_output.hpp"
#include "capsubot/cli/setting_options.hpp"
#include "capsubot/cli/start_shard.hpp"
#include "capsubot/io/io.hpp"
#include "capsubot/job/basins_job.hpp"
#include "capsubot/job/basins_settings.hpp"
#include "capsubot/report/attractors_json.hpp"
#include "capsubot/report/basins_text.hpp"
#include "commands.hpp"

namespace capsubot::cli {
namespace {

struct BasinsCommandOptions {
  MapCommandOptions map;  // the robot, --starts, -o, the shard, --threads, --json
  std::string plane = "x0-psi";
  VelocityPlane velocity;  // --psi, --u-min, --u-max
  std::string plot;
};

int Run(const BasinsCommandOptions& opt, const CLI::App& cmd) {
  BasinsJobOptions o;
  const MapCommandOptions& map = opt.map;
  o.map = MapJobOptions(map.robot, map.starts, map.threads);
  o.plane =
      StartPlaneNamed(opt.plane, opt.velocity, SettingNames{DashedFlags("plane u_min u_max")});
  RequireDistinctOutputs({{map.output, "-o"}, {opt.plot, "--plot"}});
  RequireOutputApartFromJson(map.output, "-o", map.json);
  o.map.run =
      MapRun(map.shard, cmd, map.output, {{"--plot", !opt.plot.empty()}, {"--json", map.json}});
  return RunMapOnRanks(
      o.map, [&o] { return BasinsJobWork(o); },
      [&] {
        const BasinsJobResult r = RunBasinsJob(o);
        if (!opt.plot.empty()) {
          DrawPng([&r](const std::string& png) { return text::BasinsPlotScript(r, png); },
                  opt.plot);
        }
        return map.json ? JsonOutput(json::BasinsJobJson(r), JsonProvenance(cmd))
                        : text::BasinsJobText(r);
      });
}

}  // namespace

Command AddBasinsCommand(CLI::App& app) {
  auto opt = std::make_shared<BasinsCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "basins",
      "Basins of attraction (docs/model.md sections 12 and 13): the long-run motion of every "
      "start of a grid, labelled by attractor (1 = reached from most starts). Plane x0-psi: "
      "starts from rest as in `attractors`; plane x0-u0: inner body at x0 with relative velocity "
      "u0, capsule at rest, at forcing phase --psi. Writes a CSV (x0, psi or u0, attractor, "
      "period, impacts_right, impacts_left, mean_velocity, status) and with --plot a PNG map "
      "drawn by gnuplot.");
  opt->map.starts = "64x64";  // finer than the grid of `attractors`: a map is drawn
  AddMapStartOptions(*cmd, opt->map, "grid of starts NXxNY (x0 x psi, or x0 x u0)");
  cmd->add_option("--plane", opt->plane, "x0-psi (starts from rest) or x0-u0")
      ->capture_default_str();
  AddSettings(*cmd, opt->velocity, VelocityPlaneSettings(),
              WithDashedFlags({}, VelocityPlaneSettings()));
  cmd->add_option("-o,--output", opt->map.output, "the CSV file (written atomically)")
      ->required()
      ->type_name("FILE");
  cmd->add_option("--plot", opt->plot, "also draw the map into this PNG file (needs gnuplot)")
      ->type_name("FILE");
  AddMapRunOptions(*cmd, opt->map, "basins",
                   "print the attractors object of `attractors --json` with provenance");
  SetExamples(*cmd, {{"the basins of coexisting motions over 32 x 32 starts from rest",
                      "basins --A 0.05 --c 0.02 --phi0 -2.842 --T0 0.1 --e 0.5 "
                      "--alpha 0.2792869076315278 --max-period 16 --transient 1000 "
                      "--starts 32x32 -o basins.csv"}});
  return MapCommand(cmd, [opt, cmd] { return Run(*opt, *cmd); });
}

}  // namespace capsubot::cli
