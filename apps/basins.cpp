// capsubot basins: the attractor reached from every start of a grid (docs/model.md sections 12
// and 13), as a CSV map and optionally a PNG drawn by gnuplot.

#include <fmt/format.h>

#include <cstdio>
#include <filesystem>
#include <memory>
#include <optional>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "attract_options.hpp"
#include "capsubot/io/io.hpp"
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

constexpr int kPlotColors = 10;  // attractors drawn in their own colour; the rest in grey
const char* const kColors[kPlotColors] = {"#1f77b4", "#ff7f0e", "#2ca02c", "#d62728", "#9467bd",
                                          "#8c564b", "#e377c2", "#17becf", "#bcbd22", "#7f7f7f"};

struct BasinsCommandOptions {
  RobotOptions robot;
  std::string starts = "64x64";
  std::string plane = "x0-psi";
  double psi = 0.0;
  double u_min = -1.0, u_max = 1.0;
  std::string output;
  std::string plot;
  StartShardCliOptions shard;
  int threads = 0;
  bool json = false;
};

std::string Legend(const Attractor& a, int max_period) {
  return fmt::format("{:.1f} %: {}, mean velocity {}", 100.0 * a.fraction,
                     AttractorWords(a, max_period), Num(a.mean_velocity, 4));
}

// Draws the map with gnuplot into a temporary file beside `path`, then renames it.
void Plot(const std::string& csv, const std::string& path, const Attractors& a, bool x0_u0,
          double u_min, double u_max, const std::string& title, int max_period) {
  const std::string temp = path + ".tmp.png";
  FILE* gp = popen("gnuplot 2>&1", "w");
  if (gp == nullptr) throw IoError("--plot: cannot run gnuplot");
  std::string s;
  s += "set terminal pngcairo size 1000,800 font ',12'\n";
  s += fmt::format("set output '{}'\n", temp);
  s += "set datafile separator ','\nset datafile columnheaders\n";
  s += fmt::format("set title \"{}\" noenhanced\n", title);
  s += "set xlabel 'start position x_0 of the inner body [L]'\n";
  s += x0_u0 ? "set ylabel 'start relative velocity u_0 [{/Symbol w}L]'\n"
             : "set ylabel 'start forcing phase {/Symbol y} [rad]'\n";
  s += "set xrange [0:1]\n";
  s += x0_u0 ? fmt::format("set yrange [{}:{}]\n", u_min, u_max) : "set yrange [0:2*pi]\n";
  const int colors = std::min<int>(kPlotColors, static_cast<int>(a.attractors.size()));
  s += fmt::format("set cbrange [0.5:{}.5]\nunset colorbox\n", kPlotColors + 1);
  s += "set palette maxcolors 11 defined (";
  for (int k = 0; k < kPlotColors; ++k) {
    s += fmt::format("{} '{}', ", k + 1, k < colors ? kColors[k] : "#cccccc");
  }
  s += "11 '#cccccc')\n";
  s += "set key outside below left Left reverse noenhanced\n";
  s += fmt::format(
      "plot '{}' using 1:2:(column('attractor') > {} ? {} : column('attractor')) "
      "with image notitle",
      csv, kPlotColors, kPlotColors + 1);
  for (int k = 0; k < colors; ++k) {
    s += fmt::format(", NaN with boxes fs solid fc rgb '{}' title \"{}: {}\"", kColors[k], k + 1,
                     Legend(a.attractors[static_cast<std::size_t>(k)], max_period));
  }
  if (static_cast<int>(a.attractors.size()) > colors) {
    s += ", NaN with boxes fs solid fc rgb '#cccccc' title 'other attractors'";
  }
  s += "\n";
  std::fputs(s.c_str(), gp);
  const int status = pclose(gp);
  if (status != 0 || !std::filesystem::exists(temp)) {
    std::filesystem::remove(temp);
    throw IoError(
        fmt::format("--plot {}: gnuplot failed (is it installed? Debian package "
                    "gnuplot-nox, see scripts/install-deps.sh)",
                    path));
  }
  std::filesystem::rename(temp, path);
}

int Run(const BasinsCommandOptions& opt, const CLI::App& cmd) {
  const Forcing forcing = opt.robot.forcing.Build();
  int nx = 0, ny = 0;
  std::tie(nx, ny) = ParseGridSize("--starts", opt.starts);
  const bool x0_u0 = opt.plane == "x0-u0";
  if (!x0_u0 && opt.plane != "x0-psi") {
    throw std::invalid_argument(
        fmt::format("--plane = {} is invalid: expected x0-psi or x0-u0", opt.plane));
  }
  if (!(opt.u_min < opt.u_max)) {  // also in the x0-psi plane: never accepted unchecked
    throw std::invalid_argument(fmt::format(
        "--u-min = {} and --u-max = {} are invalid: expected u-min < u-max", opt.u_min, opt.u_max));
  }
  std::vector<PhaseState> starts = GridStarts(nx, ny);
  if (x0_u0) {
    for (int i = 0; i < nx; ++i) {
      for (int j = 0; j < ny; ++j) {
        PhaseState& s = starts[static_cast<std::size_t>(i) * static_cast<std::size_t>(ny) +
                               static_cast<std::size_t>(j)];
        s = RestStart((i + 0.5) / nx, opt.psi);
        s.u = opt.u_min + (j + 0.5) * (opt.u_max - opt.u_min) / ny;
      }
    }
  }
  AttractorOptions ao;
  ao.motion = opt.robot.motion;
  ao.threads = CapThreads(opt.threads, "capsubot basins");
  RequireShardForResume(cmd, opt.shard);
  RequireDistinctOutputs({{opt.output, "-o"}, {opt.plot, "--plot"}});
  if (SplitsRun(opt.shard.shard)) {
    return RunStartShard(opt.shard, cmd, opt.robot, forcing, starts, ao, x0_u0, opt.output,
                         {{"--plot", !opt.plot.empty()}, {"--json", opt.json}});
  }
  const std::optional<Attractors> map =
      ClassifyWholeMap(opt.robot, forcing, starts, ao, opt.output);
  if (!map) return 0;  // a worker of an MPI job: rank 0 writes and prints
  const Attractors& a = *map;
  WriteStartMap(opt.output, starts, a, x0_u0, OutputProvenance(cmd).CommentLine());
  if (!opt.plot.empty()) {
    const std::string title =
        fmt::format("Basins of attraction: {}, T0 = {:g}, e = {:g}, alpha = {:.6g}{}",
                    ForceFormula(forcing), opt.robot.params.T0, opt.robot.params.e, opt.robot.alpha,
                    x0_u0 ? fmt::format(", start phase psi = {:g}", opt.psi) : "");
    Plot(opt.output, opt.plot, a, x0_u0, opt.u_min, opt.u_max, title, opt.robot.motion.max_period);
  }
  if (opt.json) {
    nlohmann::json j = AttractorsJson(a);
    AddProvenanceJson(j, cmd);
    fmt::print("{}\n", j.dump());
    return 0;
  }
  std::string t = fmt::format("basins: {} starts ({} x {}, plane {}) written to {}\n", a.starts, nx,
                              ny, opt.plane, opt.output);
  int k = 0;
  for (const Attractor& at : a.attractors) {
    t += fmt::format("  {:>2}. {}{}\n", ++k, Legend(at, opt.robot.motion.max_period),
                     at.one_impact_orbit ? " (the analytic one-impact orbit)" : "");
  }
  fmt::print("{}", t);
  return 0;
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
  AddRobotOptions(*cmd, opt->robot);
  cmd->add_option("--starts", opt->starts, "grid of starts NXxNY (x0 x psi, or x0 x u0)")
      ->capture_default_str();
  cmd->add_option("--plane", opt->plane, "x0-psi (starts from rest) or x0-u0")
      ->capture_default_str();
  cmd->add_option("--psi", opt->psi, "forcing phase of the starts in the x0-u0 plane")
      ->type_name(kPhase)
      ->capture_default_str();
  cmd->add_option("--u-min", opt->u_min, "smallest u0 of the x0-u0 plane")->capture_default_str();
  cmd->add_option("--u-max", opt->u_max, "largest u0 of the x0-u0 plane")->capture_default_str();
  cmd->add_option("-o,--output", opt->output, "the CSV file (written atomically)")
      ->required()
      ->type_name("FILE");
  cmd->add_option("--plot", opt->plot, "also draw the map into this PNG file (needs gnuplot)")
      ->type_name("FILE");
  AddStartShardOptions(*cmd, opt->shard, "basins");
  AddThreadsOption(*cmd, opt->threads);
  cmd->add_flag("--json", opt->json,
                "print the attractors object of `attractors --json` with provenance");
  AddProgressOptions(*cmd);
  SetExamples(*cmd, {{"the basins of coexisting motions over 32 x 32 starts from rest",
                      "basins --A 0.05 --c 0.02 --phi0 -2.842 --T0 0.1 --e 0.5 "
                      "--alpha 0.2792869076315278 --max-period 16 --transient 1000 "
                      "--starts 32x32 -o basins.csv"}});
  return {cmd,
          [opt, cmd] { return RunNamingFlags(MotionFlagNames(), [&] { return Run(*opt, *cmd); }); },
          [] { return true; }};
}

}  // namespace capsubot::app
