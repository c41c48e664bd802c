// capsubot sweep: the orbit, its validity (and stability), or the optimum of P1, P2, P3 or the
// reach problem at every point of a grid of parameters, to a CSV file (library:
// capsubot/job/sweep_job.hpp).

#include <fmt/format.h>

#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>
#include <vector>

#include "capsubot/cli/command.hpp"
#include "capsubot/cli/force_options.hpp"
#include "capsubot/cli/from_rest_options.hpp"
#include "capsubot/cli/gnuplot.hpp"
#include "capsubot/cli/help_format.hpp"
#include "capsubot/cli/progress.hpp"
#include "capsubot/cli/provenance.hpp"
#include "capsubot/cli/setting_options.hpp"
#include "capsubot/cli/shard_option.hpp"
#include "capsubot/cli/strict_values.hpp"
#include "capsubot/cluster/ranks.hpp"
#include "capsubot/io/io.hpp"
#include "capsubot/job/sweep_job.hpp"
#include "capsubot/job/sweep_setting_tables.hpp"
#include "capsubot/job/sweep_settings.hpp"
#include "capsubot/report/sweep_plot.hpp"
#include "capsubot/report/sweep_text.hpp"
#include "commands.hpp"
#include "sweep_flags.hpp"

namespace capsubot::cli {
namespace {

// The command line as parsed: the job's settings bound to their flags, and the syntax read
// into them.
struct SweepCliOptions {
  SweepSettings settings;
  std::vector<std::string> grids;
  ForcingOptions forcing;        // --A, --c, --phi0, --sin, --cos and a pulse's options
  int starts = 0;                // --starts (settings.search.starts when given)
  FromRestCliOptions from_rest;  // reach: starts and budgets
  bool no_header_comment = false;
  std::string shard;        // "K/N", empty: the whole grid
  std::string plot;         // --plot: the PNG, empty: none
  std::string plot_column;  // --plot-column, empty: the default of SweepPlotColumn
};

// The settings as the command line gives them: the flags given, the grid's axes, the force's
// and the reach search's options, the shard.
SweepSettings SettingsOf(const SweepCliOptions& opt, const CLI::App& cmd) {
  SweepSettings s = opt.settings;
  s.given = GivenFields(cmd, kSweepFlags);
  for (const std::string& spec : opt.grids) {
    const GridAxis& axis = s.grid.axes.emplace_back(ParseGridAxis(spec));
    const double far = std::abs(axis.Min()) > std::abs(axis.Max()) ? axis.Min() : axis.Max();
    if (axis.parameter == ModelParameter::kPhi0 && std::abs(far) > kTau) {
      NotePhaseInRadians("--grid phi0", FormatNumber(far), far);
    }
  }
  s.A = opt.forcing.parts.A;
  s.c = opt.forcing.parts.c;
  s.phi0 = opt.forcing.parts.phi0;
  s.waveform = opt.forcing.parts.waveform;
  if (s.Given("sin")) s.sin = opt.forcing.Sines();
  if (s.Given("cos")) s.cos = opt.forcing.Cosines();
  if (s.Given("starts")) s.search.starts = opt.starts;
  s.from_rest_starts = opt.from_rest.starts;
  s.reach_starts = opt.from_rest.reach_starts;
  s.reach_evaluations = opt.from_rest.budgets.global_evaluations;
  s.reach_local_evaluations = opt.from_rest.budgets.local_evaluations;
  if (!opt.shard.empty()) std::tie(s.file.shard, s.file.shards) = ParseShard(opt.shard);
  return s;
}

// The comment line: every option that determines the content, with the value this run uses
// (a mode's own default where it is not the command's). Left out: how and where the sweep
// runs, the options this mode does not read, and the options a grid replaces.
std::string ProvenanceLine(const CLI::App& cmd, const SweepSettings& settings,
                           const SettingNames& names) {
  std::vector<std::string> exclude;
  for (const std::string& field : UnusedSettings(SweepSettingUses(), settings.optimize)) {
    exclude.push_back(names.Name(field));
  }
  for (const GridAxis& axis : settings.grid.axes) exclude.push_back(names.Name(axis.name()));
  Provenance p = OutputProvenance(cmd, exclude);
  const auto defaults = SweepModeDefaults(settings);
  for (auto& [name, value] : p.options) {
    for (const auto& [field, text] : defaults) {
      if (name == names.Name(field)) value = text;
    }
  }
  return p.CommandLine();
}

// The job the command line describes (its file options and comment line included).
SweepJobOptions JobOptions(const SweepCliOptions& opt, const CLI::App& cmd) {
  const SweepSettings settings = SettingsOf(opt, cmd);
  const SettingNames names{kSweepFlags};
  SweepJobOptions job = SweepJobFrom(settings, names);
  if (!opt.no_header_comment) job.file.comments.push_back(ProvenanceLine(cmd, settings, names));
  return job;
}

int RunSweepCommand(const SweepCliOptions& opt, const CLI::App& cmd) {
  SweepJobOptions job = JobOptions(opt, cmd);
  const bool shown = ProgressShown();
  ProgressBar bar("points");
  job.progress = GridProgress(bar);
  // Every process checks the input before the processes of an MPI job meet.
  const SweepOptions sweep = PlanSweepJob(job);
  std::string column;
  if (!opt.plot.empty()) {
    column = text::SweepPlotColumn(sweep, opt.plot_column);
    RequireDistinctOutputs({{opt.settings.file.output, "-o"}, {opt.plot, "--plot"}});
    CheckWritable(opt.plot, "--plot");
  }
  Ranks ranks;  // under mpirun: rank 0 runs the sweep, the others compute blocks of points
  if (ranks.worker()) return ranks.Serve(SweepBlocks(sweep), sweep.threads);
  const SweepJobResult result = RunSweepJob(job, ranks.backend());
  if (!opt.plot.empty()) {
    DrawPng([&](const std::string& png) { return text::SweepPlotScript(sweep, column, png); },
            opt.plot);
  }
  if (shown) fmt::print(stderr, "capsubot sweep: {}", text::SweepJobText(result));
  return 0;
}

int Run(const SweepCliOptions& opt, const CLI::App& cmd) {
  return RunNamingFlags(kSweepRenamedFields, [&] {
    try {
      return RunSweepCommand(opt, cmd);
    } catch (const SweepResumableError& e) {
      throw WriteError(std::string(e.what()) + ": run the same command with --resume to continue");
    }
  });
}

// The flags the options of the library's tables are declared with: the sweep's flags, and -o
// for the output too.
const FlagNames& SweepDeclaredFlags() {
  static const FlagNames names = [] {
    FlagNames n = {{"output", "--output,-o"}};
    n.insert(n.end(), kSweepFlags.begin(), kSweepFlags.end());
    return n;
  }();
  return names;
}

// --grid, the force, the model parameters, --output and --stability.
void AddInputOptions(CLI::App* cmd, SweepCliOptions& opt) {
  cmd->add_option("--grid", opt.grids,
                  "an axis: name=lo:hi:n (n >= 1 equally spaced values from lo to hi inclusive; "
                  "lo, hi may be pi or -pi), name=lo:hi:n:log (geometric, lo, hi > 0) or "
                  "name=v1,v2,... (a list). name: " +
                      ModelParameterNames() + ". Any number of axes (at most " +
                      std::to_string(kMaxGridPoints) +
                      " points in all), the first slowest. alpha (robot mode) finds every "
                      "orbit of the robot with that mass ratio: one row per orbit, with columns "
                      "orbits, orbit, phi0")
      ->required()
      ->take_all()
      ->allow_extra_args(false);
  AddForcingOptions(*cmd, opt.forcing);
  cmd->get_option("--c")->required(false)->description(
      "mean force c of F (same unit as A), required unless c has a --grid or the force is "
      "optimised (--optimize forcing|fourier); a directed orbit needs c > 0");
  cmd->get_option("--A")->description(
      "amplitude A >= 0 of the force F = A sin(phi + phi0) + c, in units of (m1+m2) omega^2 L "
      "(required unless A has a --grid, --sin/--cos are given or the force is optimised)");
  cmd->get_option("--phi0")->description(
      "motor phase phi0 [rad] at the impact (phi = 0): F(phi) = A sin(phi + phi0) + c; "
      "required unless phi0 has a --grid, is optimised (--optimize) or solved for "
      "(--grid alpha); default 0 for a Fourier force");
  AddParamsOptions(*cmd, opt.settings.params, &opt.settings.margins);
  const FlagNames& flags = SweepDeclaredFlags();
  AddSettings(*cmd, opt.settings.file, SweepFileSettings(), flags, {"output"});
  cmd->get_option("--output")->required();
  AddSettings(*cmd, opt.settings, SweepModeSettings(), flags, {"stability"});
}

// --optimize and the options of its modes.
void AddOptimizeOptions(CLI::App* cmd, SweepCliOptions& opt) {
  std::string modes;
  for (SweepOptimize mode : SweepOptimizeModes()) {
    modes += (modes.empty() ? "" : "|") + std::string(SweepOptimizeName(mode));
  }
  const FlagNames& flags = SweepDeclaredFlags();
  SweepSettings& s = opt.settings;
  AddSettings(*cmd, s, SweepModeSettings(), flags, {"optimize"});
  CLI::Option* optimize = cmd->get_option("--optimize")->type_name(modes);
  AddSettings(*cmd, s.search.gait, SweepGaitSettings(), flags, {"rho_max"});
  CLI::Option* rho_max = cmd->get_option("--rho-max")->type_name(kFloatOrInf)->needs(optimize);
  cmd->add_flag_callback(
         "--stable-only", [&opt] { opt.settings.stable_only = true; },
         "with --optimize: the same as --rho-max 1 (valid and stable orbits only)")
      ->excludes(rho_max)
      ->needs(optimize);
  AddSettings(*cmd, s, SweepModeSettings(), flags, {"scan_points"});
  cmd->get_option("--scan-points")->needs(optimize);
  AddSettings(*cmd, s.search.gait, SweepGaitSettings(), flags, {"bound"});
  AddSettings(*cmd, s.search, SweepSearchSettings(), flags, {"harmonics"});
  cmd->add_option("--starts", opt.starts,
                  HelpIn(ModesOpening(SweepSettingUses(), "starts", SweepModes()) +
                             "local polishes of the multistart, >= 1 (default: 10 for forcing "
                             "and reach's seed, 20 for fourier)",
                         flags));
  AddSettings(*cmd, s.search, SweepSearchSettings(), flags,
              {"hops", "global_algorithm", "local_algorithm", "global_evaluations"});
  AddSettings(*cmd, s, SweepModeSettings(), flags, {"alpha"});
  // reach: the seed's check from rest and the search's evaluation budgets, which bound each
  // point (no wall-clock limit: the rows must not depend on the machine's speed).
  AddFromRestStartsOption(*cmd, opt.from_rest);
  AddReachBudgetOptions(*cmd, opt.from_rest);
}

// How and where the sweep runs.
void AddRunOptions(CLI::App* cmd, SweepCliOptions& opt) {
  cmd->add_flag("--no-header-comment", opt.no_header_comment,
                "write no comment lines before the header (for tools that cannot skip '#' "
                "lines; pandas: comment='#', gnuplot: skips them by default)");
  AddSettings(*cmd, opt.settings.file, SweepFileSettings(), SweepDeclaredFlags(),
              {"resume", "checkpoint_seconds"});
  cmd->add_option("--shard", opt.shard,
                  "compute only shard K of N (0 <= K < N): the grid points p with p % N = K; "
                  "the file gets a line '# shard K/N of T points'; `capsubot merge OUT "
                  "SHARD_FILES...` joins the N files into the file of the whole sweep; 0/1 "
                  "writes the file of the whole sweep (docs/cluster.md)")
      ->type_name("K/N");
  CLI::Option* plot = cmd->add_option(
      "--plot", opt.plot,
      "also draw the CSV into this PNG with gnuplot: the column of --plot-column against the "
      "grid's axis (one axis) or as a coloured map over its two axes (two); needs -o FILE");
  cmd->add_option("--plot-column", opt.plot_column,
                  "the column --plot draws (default: mean_velocity, v_mean or I, the first the "
                  "sweep writes)")
      ->needs(plot);
  AddThreadsOption(*cmd, opt.settings.file.threads,
                   "worker threads (default 0: all cores, std::thread::hardware_concurrency); "
                   "more than 4 per core is lowered to that, with a note");
  AddProgressOptions(*cmd);
  SetExamples(*cmd, {{"the orbit and its stability at 4 phases x 2 restitutions, to "
                      "standard output",
                      "sweep --grid phi0=-3:-2.4:4 --grid e=0.5,1 --A 0.05 --c 0.02 "
                      "--T0 0.1 --stability -o -"},
                     {"P2 at every point of a 17 x 11 grid, shard 0 of 3 (1/3 and 2/3 "
                      "elsewhere, then `capsubot merge`; --progress for lines in a Slurm log)",
                      "sweep --grid T0=0.01:1:17:log --grid e=0:1:11 --optimize forcing "
                      "--shard 0/3 -o part0.csv"}});
}

}  // namespace

Command AddSweepCommand(CLI::App& app) {
  auto opt = std::make_shared<SweepCliOptions>();
  CLI::App* cmd = app.add_subcommand(
      "sweep",
      "The orbit and its validity (docs/model.md sections 4-5), the best gait of problem "
      "P1, P2 or P3 (section 7) or the fastest motion from rest (section 13), at every point "
      "of a grid of parameters, to a CSV file: "
      "comment lines (# capsubot <version> sweep <options>), a header, one row per point "
      "(empty cell: the quantity does not exist). Runs on all cores; the file is "
      "byte-identical for any --threads, written to <output>.partial and renamed at the end; "
      "--resume continues a killed sweep. See docs/sweep.md.");
  AddInputOptions(cmd, *opt);
  AddOptimizeOptions(cmd, *opt);
  AddRunOptions(cmd, *opt);
  return {cmd, [opt, cmd] { return Run(*opt, *cmd); }, [] { return true; }};
}

}  // namespace capsubot::cli
