// capsubot sweep: the orbit, its validity (and stability), or the optimum of P1, P2, P3 or the
// reach problem at every point of a grid of parameters, to a CSV file (library:
// capsubot/job/sweep_job.hpp).

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>
#include <type_traits>
#include <utility>
#include <vector>

#include "attract_options.hpp"
#include "capsubot/io/io.hpp"
#include "capsubot/job/sweep_job.hpp"
#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/report/sweep_plot.hpp"
#include "capsubot/report/sweep_text.hpp"
#include "cli.hpp"
#include "commands.hpp"
#include "from_rest_options.hpp"
#include "gnuplot.hpp"
#include "help_format.hpp"
#include "progress.hpp"
#include "provenance.hpp"
#include "ranks.hpp"

namespace capsubot::app {
namespace {

// The command line as parsed; ReadMode puts what a mode reads into its options.
struct SweepCliOptions {
  std::vector<std::string> grids;
  ForcingOptions forcing;
  Params params;
  Margins margins;
  bool stability = false;
  std::string optimize;          // empty: no --optimize
  PhaseOptions phase;            // --scan-points
  SearchRequest search;          // --rho-max, --bound and the search effort
  int starts = 0;                // --starts
  double alpha = kNaN;           // --alpha
  FromRestCliOptions from_rest;  // reach: starts and budgets
  GridFileOptions file;          // --output, --resume, --checkpoint-seconds, --threads
  bool no_header_comment = false;
  std::string shard;        // "K/N", empty: the whole grid
  std::string plot;         // --plot: the PNG, empty: none
  std::string plot_column;  // --plot-column, empty: the default of SweepPlotColumn
};

// Library messages name the job's options; the user typed these flags.
const FlagNames kFlagOf = {{"grid", "--grid"},
                           {"plot_column", "--plot-column"},
                           {"plot", "--plot"},
                           {"optimize", "--optimize"},
                           {"output", "--output"},
                           {"threads", "--threads"},
                           {"resume", "--resume"},
                           {"checkpoint_seconds", "--checkpoint-seconds"},
                           {"scan_points", "--scan-points"},
                           {"harmonics", "--harmonics"},
                           {"starts", "--starts"},
                           {"hops", "--hops"},
                           {"global_evaluations", "--global-evaluations"},
                           {"rho_max", "--rho-max"},
                           {"alpha", "--alpha"},
                           {"shard", "--shard"},
                           {"A", "--A"},
                           {"c", "--c"},
                           {"phi0", "--phi0"},
                           {"sin", "--sin"},
                           {"cos", "--cos"},
                           {"reach.global_evaluations", "--reach-evaluations"},
                           {"reach.local_evaluations", "--reach-local-evaluations"}};

// The option giving a grid parameter's value: "--rho-max" for rho_max.
std::string FlagOf(const GridAxis& axis) {
  std::string flag = "--" + axis.name();
  std::replace(flag.begin(), flag.end(), '_', '-');
  return flag;
}

// Reads the command line into a mode's options: an option given replaces the mode's default.
// It notes every option the mode reads (one given that the mode does not read would be
// ignored: refused) and, for a number not given, the mode's default where it differs from the
// command's (the robust gait of the reach search), for the provenance line. Without a command
// line it only notes the options.
class ModeReader {
 public:
  explicit ModeReader(const CLI::App* cmd) : cmd_(cmd) {}

  // Notes `flag`; whether it was given.
  bool Read(const char* flag) {
    read_.emplace_back(flag);
    return cmd_ != nullptr && cmd_->count(flag) > 0;
  }
  // `field` = `value` when `flag` was given (or `also`: another option set the value).
  template <class T>
  void Take(const char* flag, T& field, const T& value, bool also = false) {
    if (Read(flag) || also) {
      field = value;
    } else if constexpr (std::is_same_v<T, double>) {
      if (cmd_ != nullptr && field != value && !(std::isnan(field) && std::isnan(value))) {
        defaults_.emplace_back(flag, FormatNumber(field));
      }
    }
  }
  const std::vector<std::string>& read() const { return read_; }
  // (flag, the mode's default as text) of the numbers not given whose default is the mode's.
  const std::vector<std::pair<std::string, std::string>>& defaults() const { return defaults_; }

 private:
  const CLI::App* cmd_;
  std::vector<std::string> read_;
  std::vector<std::pair<std::string, std::string>> defaults_;
};

void ReadParams(ModeReader& r, const SweepCliOptions& o, Params& p, Margins& m) {
  r.Take("--T0", p.T0, o.params.T0);
  r.Take("--e", p.e, o.params.e);
  r.Take("--margin", m.clearance, o.margins.clearance);
  r.Take("--margin-stroke", m.clearance_stroke, o.margins.clearance_stroke);
  r.Take("--stick-margin", m.stick, o.margins.stick);
}

void ReadForce(ModeReader& r, const SweepCliOptions& o, SweepForce& f) {
  // A sweep solves the analytic orbit at every point: a pulse force is refused.
  const bool pulse = r.Read("--levels") || r.Read("--switches") ||
                     (r.Read("--waveform") && o.forcing.waveform == "pulse");
  if (pulse) {
    throw std::invalid_argument(
        "a pulse force is invalid for sweep: expected a sine or Fourier force (the analytic "
        "one-impact orbit needs one; simulate, attractors, periodic, continue, basins and "
        "bifurcation take a pulse force)");
  }
  r.Take("--A", f.A, std::optional<double>(o.forcing.A));
  r.Take("--c", f.c, std::optional<double>(o.forcing.c));
  if (r.Read("--sin")) f.sin = o.forcing.Sines();
  if (r.Read("--cos")) f.cos = o.forcing.Cosines();
}

void ReadRhoMax(ModeReader& r, const SweepCliOptions& o, double& rho_max) {
  const bool stable_only = r.Read("--stable-only");  // rho_max = 1
  r.Take("--rho-max", rho_max, o.search.gait.rho_max, stable_only);
}

// The bound, rho_max and search effort of P2, P3 and the reach search's seed.
void ReadSearch(ModeReader& r, const SweepCliOptions& o, SearchRequest& s) {
  ReadRhoMax(r, o, s.gait.rho_max);
  r.Take("--bound", s.gait.force_bound, o.search.gait.force_bound);
  r.Take("--starts", s.starts, std::optional<int>(o.starts));
  r.Take("--global-algorithm", s.global_algorithm, o.search.global_algorithm);
  r.Take("--local-algorithm", s.local_algorithm, o.search.local_algorithm);
  r.Take("--global-evaluations", s.global_evaluations, o.search.global_evaluations);
}

void ReadMode(ModeReader& r, const SweepCliOptions& o, SweepOrbitMode& m) {
  ReadParams(r, o, m.params, m.margins);
  ReadForce(r, o, m.force);
  r.Take("--phi0", m.phi0, std::optional<double>(o.forcing.phi0));
  r.Take("--stability", m.stability, o.stability);
}

void ReadMode(ModeReader& r, const SweepCliOptions& o, SweepPhaseMode& m) {
  ReadParams(r, o, m.params, m.phase.gait.margins);
  ReadForce(r, o, m.force);
  r.Take("--stability", m.stability, o.stability);
  ReadRhoMax(r, o, m.phase.gait.rho_max);
  r.Take("--scan-points", m.phase.scan_points, o.phase.scan_points);
}

void ReadMode(ModeReader& r, const SweepCliOptions& o, SweepForcingMode& m) {
  ReadParams(r, o, m.params, m.search.gait.margins);
  r.Take("--stability", m.stability, o.stability);
  ReadSearch(r, o, m.search);
  r.Take("--hops", m.search.hops, o.search.hops);
}

void ReadMode(ModeReader& r, const SweepCliOptions& o, SweepFourierMode& m) {
  ReadParams(r, o, m.params, m.search.gait.margins);
  r.Take("--stability", m.stability, o.stability);
  ReadSearch(r, o, m.search);
  r.Take("--harmonics", m.search.harmonics, o.search.harmonics);
}

void ReadMode(ModeReader& r, const SweepCliOptions& o, SweepReachMode& m) {
  ReadParams(r, o, m.params, m.search.gait.margins);
  ReadSearch(r, o, m.search);
  r.Take("--hops", m.search.hops, o.search.hops);
  r.Take("--alpha", m.reach.alpha, o.alpha);
  if (r.Read("--from-rest-starts")) {
    std::tie(m.reach.check.n_x, m.reach.check.n_psi) =
        ParseGridSize("--from-rest-starts", o.from_rest.starts);
  }
  if (r.Read("--reach-starts")) {
    std::tie(m.reach.search.n_x, m.reach.search.n_psi) =
        ParseGridSize("--reach-starts", o.from_rest.reach_starts);
  }
  r.Take("--reach-evaluations", m.reach.global_evaluations, o.from_rest.reach_evaluations);
  r.Take("--reach-local-evaluations", m.reach.local_evaluations,
         o.from_rest.reach_local_evaluations);
}

// "" (no --optimize) and the name of every mode, in SweepMode's order.
std::vector<std::string> ModeNames() {
  std::vector<std::string> names = {""};
  for (SweepOptimize mode : SweepOptimizeModes()) names.emplace_back(SweepOptimizeName(mode));
  return names;
}

std::string ModeText(const std::string& name) {
  return name.empty() ? "no --optimize" : "--optimize " + name;
}

// The options each mode reads: (its name, its options), in SweepMode's order.
std::vector<std::pair<std::string, std::vector<std::string>>> OptionsOfModes(
    const SweepCliOptions& opt) {
  std::vector<std::pair<std::string, std::vector<std::string>>> modes;
  for (const std::string& name : ModeNames()) {
    SweepMode mode = SweepModeNamed(name);
    ModeReader reader(nullptr);
    std::visit([&](auto& m) { ReadMode(reader, opt, m); }, mode);
    modes.emplace_back(name, reader.read());
  }
  return modes;
}

// Refuses an option given that the mode `name` does not read (it would be silently ignored),
// naming the modes that read it; returns the options of the other modes that this one does
// not read, whose defaults do not shape its file.
std::vector<std::string> RejectUnread(const CLI::App& cmd, const SweepCliOptions& opt,
                                      const std::string& name, const ModeReader& reader) {
  const auto has = [](const std::vector<std::string>& flags, const std::string& flag) {
    return std::find(flags.begin(), flags.end(), flag) != flags.end();
  };
  const auto modes = OptionsOfModes(opt);
  std::vector<std::string> unread;
  for (const auto& mode : modes) {
    for (const std::string& flag : mode.second) {
      if (!has(reader.read(), flag) && !has(unread, flag)) unread.push_back(flag);
    }
  }
  for (const CLI::Option* option : cmd.get_options()) {  // the first given, as declared
    const std::string flag = option->get_name();
    if (option->count() == 0 || !has(unread, flag)) continue;
    std::string readers;
    for (const auto& mode : modes) {
      if (has(mode.second, flag)) readers += (readers.empty() ? "" : ", ") + ModeText(mode.first);
    }
    throw std::invalid_argument(fmt::format(
        "{} is invalid {}: expected it only with {}", flag,
        name.empty() ? std::string("without --optimize") : "with --optimize " + name, readers));
  }
  return unread;
}

// An option that gives a value the grid also gives.
void RejectGridConflicts(const Grid& grid, const CLI::App& cmd) {
  for (const GridAxis& axis : grid.axes) {
    const std::string flag = FlagOf(axis);
    const CLI::Option* option = cmd.get_option_no_throw(flag);
    if (option != nullptr && option->count() > 0) {
      throw std::invalid_argument(
          fmt::format("{} = {} is invalid with --grid {}: expected the value from only one of them",
                      flag, option->as<std::string>(), axis.ToString()));
    }
    if (axis.parameter == ModelParameter::kRhoMax && cmd.count("--stable-only") > 0) {
      throw std::invalid_argument(fmt::format(
          "--stable-only (rho_max = 1) is invalid with --grid {}: expected the value from only "
          "one of them",
          axis.ToString()));
    }
  }
}

// The comment line: every option that determines the content, with the value this run uses
// (a mode's own default where it is not the command's). Left out: how and where the sweep
// runs, the options this mode does not read, and the options a grid replaces.
std::string ProvenanceLine(const CLI::App& cmd, const Grid& grid, std::vector<std::string> exclude,
                           const ModeReader& reader) {
  for (const GridAxis& axis : grid.axes) exclude.push_back(FlagOf(axis));
  Provenance p = OutputProvenance(cmd, exclude);
  for (auto& [name, value] : p.options) {
    for (const auto& [flag, text] : reader.defaults()) {
      if (name == flag) value = text;
    }
  }
  return p.CommandLine();
}

// The job the command line describes (its file options and comment line included).
SweepJobOptions JobOptions(SweepCliOptions& opt, const CLI::App& cmd) {
  SweepJobOptions job;
  for (const std::string& spec : opt.grids) {
    job.grid.axes.push_back(ParseGridAxis(spec));
    const GridAxis& axis = job.grid.axes.back();
    const double far = std::abs(axis.Min()) > std::abs(axis.Max()) ? axis.Min() : axis.Max();
    if (axis.parameter == ModelParameter::kPhi0 && std::abs(far) > kTau) {
      NotePhaseInRadians("--grid phi0", FormatNumber(far), far);
    }
  }
  job.mode = SweepModeNamed(opt.optimize);
  job.file = opt.file;
  if (!opt.shard.empty()) std::tie(job.file.shard, job.file.shards) = ParseShard(opt.shard);
  RejectGridConflicts(job.grid, cmd);
  ModeReader reader(&cmd);
  std::visit([&](auto& m) { ReadMode(reader, opt, m); }, job.mode);
  const std::vector<std::string> unread = RejectUnread(cmd, opt, opt.optimize, reader);
  if (cmd.count("--global-evaluations") > 0 && opt.search.global_algorithm == kMultistart) {
    throw std::invalid_argument(
        "--global-evaluations is invalid with --global-algorithm multistart: expected an "
        "NLopt global algorithm with it (multistart has no evaluation budget)");
  }
  if (!opt.no_header_comment) {
    job.file.comments.push_back(ProvenanceLine(cmd, job.grid, unread, reader));
  }
  return job;
}

int RunSweepCommand(SweepCliOptions& opt, const CLI::App& cmd) {
  SweepJobOptions job = JobOptions(opt, cmd);
  const bool shown = ProgressShown();
  ProgressBar bar("points");
  job.progress = GridProgress(bar);
  // Every process checks the input before the processes of an MPI job meet.
  const SweepOptions sweep = PlanSweepJob(job);
  std::string column;
  if (!opt.plot.empty()) {
    column = text::SweepPlotColumn(sweep, opt.plot_column);
    RequireDistinctOutputs({{opt.file.output, "-o"}, {opt.plot, "--plot"}});
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

int Run(SweepCliOptions& opt, const CLI::App& cmd) {
  return RunNamingFlags(kFlagOf, [&] {
    try {
      return RunSweepCommand(opt, cmd);
    } catch (const SweepResumableError& e) {
      throw WriteError(std::string(e.what()) + ": run the same command with --resume to continue");
    }
  });
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
  AddParamsOptions(*cmd, opt.params, &opt.margins);
  cmd->add_option(
         "--output,-o", opt.file.output,
         "the CSV file to write (required); - writes to standard output (no --resume then)")
      ->required()
      ->type_name("FILE");
  cmd->add_flag("--stability", opt.stability,
                "add the columns spectral_radius (of the impact map, docs/model.md section 8), "
                "lambda_re, lambda_im (its largest multiplier), stable (1 when < 1) and loss "
                "(fold, flip or torus when unstable)");
}

// --optimize and the options of its modes.
void AddOptimizeOptions(CLI::App* cmd, SweepCliOptions& opt) {
  std::string modes;
  for (SweepOptimize mode : SweepOptimizeModes()) {
    modes += (modes.empty() ? "" : "|") + std::string(SweepOptimizeName(mode));
  }
  CLI::Option* optimize =
      cmd->add_option(
             "--optimize", opt.optimize,
             "the best gait at every point: phi0 (P1: the impact phase for the given force "
             "shape; adds column phi0), forcing (P2: A, c, phi0 with A + c <= --bound; "
             "adds A, c, phi0), fourier (P3: a --harmonics K force with max |F| <= "
             "--bound; adds c, a1..aK, b1..bK) or reach (the fastest motion from rest, as "
             "`optimize --problem reach`: A, c, phi0, alpha, mean_velocity, ..., the robust "
             "seed's seed_v_mean and seed_mean_velocity_from_rest; seconds per point); adds a "
             "status column")
          ->type_name(modes);
  CLI::Option* rho_max =
      cmd->add_option("--rho-max", opt.search.gait.rho_max,
                      "with --optimize: maximise over orbits whose spectral radius is at most "
                      "rho_max > 0 (docs/model.md sections 8, 12); inf: no stability requirement")
          ->capture_default_str()
          ->type_name(kFloatOrInf)
          ->needs(optimize);
  cmd->add_flag_callback(
         "--stable-only", [&opt] { opt.search.gait.rho_max = 1.0; },
         "with --optimize: the same as --rho-max 1 (valid and stable orbits only)")
      ->excludes(rho_max)
      ->needs(optimize);
  cmd->add_option("--scan-points", opt.phase.scan_points,
                  fmt::format("with --optimize phi0: points of the optimiser's initial scan of "
                              "phi0, {} to {}",
                              kMinScanPoints, kMaxScanPoints))
      ->capture_default_str()
      ->needs(optimize);
  cmd->add_option("--bound", opt.search.gait.force_bound,
                  "with --optimize forcing|fourier|reach: the force bound A + c (max |F|) <= "
                  "bound <= T0 (default: T0)");
  cmd->add_option("--harmonics", opt.search.harmonics,
                  "with --optimize fourier: the number K of harmonics")
      ->capture_default_str();
  cmd->add_option("--starts", opt.starts,
                  "with --optimize forcing|fourier|reach: local polishes of the multistart, >= 1 "
                  "(default: 10 for forcing and reach's seed, 20 for fourier)");
  cmd->add_option("--hops", opt.search.hops,
                  "with --optimize forcing|reach: basin-hopping restarts after the starts")
      ->capture_default_str();
  cmd->add_option("--global-algorithm", opt.search.global_algorithm,
                  "with --optimize forcing|fourier|reach: multistart or an NLopt global "
                  "algorithm (GN_ISRES, GN_ORIG_DIRECT, GN_ORIG_DIRECT_L, GN_AGS)")
      ->capture_default_str();
  cmd->add_option("--local-algorithm", opt.search.local_algorithm,
                  "with --optimize forcing|fourier|reach: the local polish (LN_COBYLA, "
                  "LD_SLSQP, LD_MMA, LD_CCSAQ)")
      ->capture_default_str();
  cmd->add_option(
      "--global-evaluations", opt.search.global_evaluations,
      fmt::format("with --optimize forcing|fourier|reach: evaluation budget of an NLopt global "
                  "algorithm (not multistart), 10 to {}",
                  kMaxStageEvaluations));
  cmd->add_option("--alpha", opt.alpha,
                  "with --optimize reach: a fixed mass ratio 0 < alpha < 1 (default: alpha is "
                  "optimised too)");
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
  cmd->add_flag("--resume", opt.file.resume,
                "continue an interrupted sweep from <output>.checkpoint (same options "
                "required; the checkpoint's checksums are verified); without it a sweep "
                "always starts again");
  cmd->add_option("--checkpoint-seconds", opt.file.checkpoint_seconds,
                  "minimum time [s] between two checkpoints (each one fsyncs the partial file); "
                  "0: after every block of rows")
      ->capture_default_str();
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
  AddThreadsOption(*cmd, opt.file.threads,
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

}  // namespace capsubot::app
