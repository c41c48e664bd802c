// capsubot sweep: the orbit, its validity (and stability), or the optimum of P1, P2, P3 or the
// reach problem at every point of a grid of parameters, to a CSV file (library:
// capsubot/sweep/sweep.hpp).

#include "capsubot/sweep/sweep.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstdio>
#include <cstring>
#include <limits>
#include <memory>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "capsubot/optimize/optimize_request.hpp"
#include "cli.hpp"
#include "commands.hpp"
#include "from_rest_report.hpp"
#include "help_format.hpp"
#include "progress.hpp"
#include "provenance.hpp"
#include "ranks.hpp"

namespace capsubot::app {
namespace {

struct SweepCliOptions {
  std::vector<std::string> grids;
  ForcingOptions forcing;
  SweepOptions sweep;
  std::string optimize;
  SearchRequest search;  // --optimize: the bound, stability and search effort
  int starts = 0;        // used only when given: else the problem's default
  CLI::Option* starts_option = nullptr;
  CLI::Option* global_evaluations_option = nullptr;
  double alpha = std::numeric_limits<double>::quiet_NaN();  // reach: NaN: alpha is optimised
  FromRestCliOptions from_rest;                             // reach: starts and budgets
  bool no_header_comment = false;
  std::string shard;  // "K/N", empty: the whole grid
};

// Library messages name the sweep's parameters; the user typed these flags.
const FlagNames kFlagOf = {{"grid", "--grid"},
                           {"optimize", "--optimize"},
                           {"output", "--output"},
                           {"threads", "--threads"},
                           {"resume", "--resume"},
                           {"checkpoint_seconds", "--checkpoint-seconds"},
                           {"scan_points", "--scan-points"},
                           {"harmonics", "--harmonics"},
                           {"starts", "--starts"},
                           {"hops", "--hops"},
                           {"rho_max", "--rho-max"},
                           {"alpha", "--alpha"},
                           {"shard", "--shard"}};

// The option giving a grid parameter's value: "--rho-max" for rho_max.
std::string FlagOf(const GridAxis& axis) {
  std::string flag = "--" + axis.name();
  std::replace(flag.begin(), flag.end(), '_', '-');
  return flag;
}

// P2, P3 and reach choose the whole force: no force option applies.
bool ChoosesTheForce(SweepOptimize mode) {
  return mode == SweepOptimize::kForcing || mode == SweepOptimize::kFourier ||
         mode == SweepOptimize::kReach;
}

// The modes that use an option ("none": no --optimize).
const std::vector<OptionUse> kOptionUses = {
    {"--A", {"none", "phi0"}},
    {"--c", {"none", "phi0"}},
    {"--phi0", {"none"}},
    {"--sin", {"none", "phi0"}},
    {"--cos", {"none", "phi0"}},
    {"--stability", {"none", "phi0", "forcing", "fourier"}},
    {"--rho-max", {"phi0", "forcing", "fourier", "reach"}},
    {"--stable-only", {"phi0", "forcing", "fourier", "reach"}},
    {"--scan-points", {"phi0"}},
    {"--bound", {"forcing", "fourier", "reach"}},
    {"--harmonics", {"fourier"}},
    {"--starts", {"forcing", "fourier", "reach"}},
    {"--hops", {"forcing", "reach"}},
    {"--global-algorithm", {"forcing", "fourier", "reach"}},
    {"--local-algorithm", {"forcing", "fourier", "reach"}},
    {"--global-evaluations", {"forcing", "fourier", "reach"}},
    {"--alpha", {"reach"}},
    {"--from-rest-starts", {"reach"}},
    {"--reach-starts", {"reach"}},
    {"--reach-evaluations", {"reach"}},
    {"--reach-local-evaluations", {"reach"}},
};

// The options this mode does not use; one of them given would be silently ignored: refused.
std::vector<std::string> ModeUnusedOptions(const SweepCliOptions& opt, const CLI::App& cmd) {
  const char* mode = SweepOptimizeName(opt.sweep.optimize);
  if (const OptionUse* use = GivenUnusedOption(cmd, kOptionUses, mode)) {
    std::string modes;
    for (const char* m : use->runs) {
      if (m == nullptr) continue;
      modes += (modes.empty() ? "" : ", ") + (std::strcmp(m, "none") == 0
                                                  ? std::string("no --optimize")
                                                  : std::string("--optimize ") + m);
    }
    throw std::invalid_argument(fmt::format(
        "{} is invalid {}: expected it only with {}", use->option,
        opt.sweep.optimize == SweepOptimize::kNone ? std::string("without --optimize")
                                                   : std::string("with --optimize ") + mode,
        modes));
  }
  return UnusedOptions(kOptionUses, mode);
}

// An option that gives a value the grid also gives, or that the optimiser chooses itself.
void RejectConflicts(const SweepCliOptions& opt, const CLI::App& cmd) {
  const SweepOptions& s = opt.sweep;
  for (const GridAxis& axis : s.grid.axes) {
    const std::string flag = FlagOf(axis);
    const CLI::Option* option = cmd.get_option_no_throw(flag);
    if (option != nullptr && option->count() > 0) {
      throw std::invalid_argument(
          fmt::format("{} = {} is invalid with --grid {}: expected the value from only one of them",
                      flag, option->as<std::string>(), axis.ToString()));
    }
    if (axis.parameter == ModelParameter::krho_max && cmd.count("--stable-only") > 0) {
      throw std::invalid_argument(fmt::format(
          "--stable-only (rho_max = 1) is invalid with --grid {}: expected the value from only "
          "one of them",
          axis.ToString()));
    }
  }
  if (!ChoosesTheForce(s.optimize)) return;
  for (const char* flag : {"--A", "--c", "--phi0", "--sin", "--cos"}) {
    const CLI::Option* option = cmd.get_option_no_throw(flag);
    if (option != nullptr && option->count() > 0) {
      throw std::invalid_argument(
          fmt::format("{} is invalid with --optimize {}: expected no force option (the "
                      "optimiser chooses the force)",
                      flag, SweepOptimizeName(s.optimize)));
    }
  }
}

// The force at every point from --A, --c, --phi0, --sin, --cos (not needed by P2 and P3).
void BuildForcing(SweepCliOptions& opt) {
  SweepOptions& s = opt.sweep;
  const Grid& g = s.grid;
  if (ChoosesTheForce(s.optimize)) return;
  // A gridded A or c needs no option: the grid gives its value at every point.
  if (g.Has(ModelParameter::kc) && std::isnan(opt.forcing.c)) opt.forcing.c = 0.0;
  const bool phase_given_elsewhere = g.Has(ModelParameter::kphi0) ||
                                     g.Has(ModelParameter::kalpha) ||
                                     s.optimize == SweepOptimize::kPhase;
  if (std::isnan(opt.forcing.c)) {
    throw std::invalid_argument("option --c is missing: give the mean force c (or --grid c=...)");
  }
  const bool amplitude_elsewhere = g.Has(ModelParameter::kA) || g.Has(ModelParameter::ksin, 1);
  if (amplitude_elsewhere && opt.forcing.fourier_option->count() == 0 &&
      opt.forcing.A_option->count() == 0) {
    s.forcing = Forcing::Harmonic(0.0, opt.forcing.c,
                                  opt.forcing.phi0_option->count() > 0 ? opt.forcing.phi0 : 0.0);
    if (!phase_given_elsewhere && opt.forcing.phi0_option->count() == 0) {
      throw std::invalid_argument(
          "option --phi0 is missing: give the impact phase phi0 [rad] "
          "(or --grid phi0=..., --grid alpha=..., --optimize phi0)");
    }
  } else {
    s.forcing = opt.forcing.Build(!phase_given_elsewhere);
  }
  if ((s.optimize == SweepOptimize::kPhase || g.Has(ModelParameter::kalpha)) &&
      opt.forcing.phi0_option->count() > 0) {
    throw std::invalid_argument(
        fmt::format("--phi0 = {} is invalid with {}: expected no --phi0 (the sweep finds phi0)",
                    opt.forcing.phi0,
                    s.optimize == SweepOptimize::kPhase ? "--optimize phi0" : "--grid alpha"));
  }
}

// The defaults of `optimize --problem reach` that differ from the sweep's: the seed is the
// robust gait (docs/model.md section 12) unless the command line says otherwise.
const std::pair<const char*, double> kReachDefaults[] = {
    {"--rho-max", kRobustRhoMax},
    {"--margin-stroke", kRobustMarginStroke},
    {"--stick-margin", kRobustStickMargin},
};

// True when the value of `flag` comes from its default: not given, not gridded, not implied.
bool Defaulted(const CLI::App& cmd, const Grid& grid, const std::string& flag) {
  for (const GridAxis& axis : grid.axes) {
    if (FlagOf(axis) == flag) return false;
  }
  return cmd.count(flag) == 0 && (flag != "--rho-max" || cmd.count("--stable-only") == 0);
}

// The optimisers' options from the command line (each mode reads its own).
void SetOptimizerOptions(SweepCliOptions& opt, const CLI::App& cmd) {
  SweepOptions& s = opt.sweep;
  if (s.optimize == SweepOptimize::kReach) {
    for (const auto& [flag, value] : kReachDefaults) {
      if (!Defaulted(cmd, s.grid, flag)) continue;
      if (std::strcmp(flag, "--rho-max") == 0) opt.search.gait.rho_max = value;
      if (std::strcmp(flag, "--margin-stroke") == 0) s.params.margin_stroke = value;
      if (std::strcmp(flag, "--stick-margin") == 0) s.params.stick_margin = value;
    }
    RequireInRange("--reach-evaluations", opt.from_rest.reach_evaluations, 1, kMaxStageEvaluations);
    RequireInRange("--reach-local-evaluations", opt.from_rest.reach_local_evaluations, 0,
                   kMaxStageEvaluations);
    s.reach = opt.from_rest.Reach(opt.search.gait.force_bound, opt.alpha);
    s.reach.max_seconds = SweepReachOptions().max_seconds;  // the budgets bound each point
  }
  if (opt.global_evaluations_option->count() > 0) {
    if (opt.search.global_algorithm == kMultistart) {
      throw std::invalid_argument(
          "--global-evaluations is invalid with --global-algorithm multistart: expected an "
          "NLopt global algorithm with it (multistart has no evaluation budget)");
    }
    RequireInRange("--global-evaluations", opt.search.global_evaluations, 10, kMaxStageEvaluations);
  }
  SearchRequest search = opt.search;
  if (opt.starts_option->count() > 0) search.starts = opt.starts;
  s.phase.gait.rho_max = search.gait.rho_max;
  s.design = ForcingOptionsFor(search);
  s.fourier = FourierOptionsFor(search);
}

// The comment line: every option that determines the content, with the value this run uses.
// Left out: how and where the sweep runs, the options this mode does not use, and the
// defaults of options a grid replaces.
std::string ProvenanceLine(const SweepCliOptions& opt, const CLI::App& cmd,
                           std::vector<std::string> exclude) {
  for (const GridAxis& axis : opt.sweep.grid.axes) exclude.push_back(FlagOf(axis));
  Provenance p = OutputProvenance(cmd, exclude);
  if (opt.sweep.optimize == SweepOptimize::kReach) {
    for (auto& [name, value] : p.options) {
      for (const auto& [flag, robust] : kReachDefaults) {
        if (name == flag && Defaulted(cmd, opt.sweep.grid, flag)) value = FormatNumber(robust);
      }
    }
  }
  return p.CommandLine();
}

int RunSweepCommand(SweepCliOptions& opt, const CLI::App& cmd) {
  SweepOptions& s = opt.sweep;
  RequireInRange("--scan-points", s.phase.scan_points, kMinScanPoints, kMaxScanPoints);
  s.grid.axes.clear();
  for (const std::string& spec : opt.grids) s.grid.axes.push_back(ParseGridAxis(spec));
  s.grid.Validate();
  if (!opt.optimize.empty()) s.optimize = ParseSweepOptimize(opt.optimize);
  if (!opt.shard.empty()) std::tie(s.shard, s.shards) = ParseShard(opt.shard);
  RejectConflicts(opt, cmd);
  BuildForcing(opt);
  const std::vector<std::string> unused = ModeUnusedOptions(opt, cmd);
  SetOptimizerOptions(opt, cmd);
  s.comments.clear();
  if (!opt.no_header_comment) s.comments.push_back(ProvenanceLine(opt, cmd, unused));
  s.threads = CapThreads(s.threads, "capsubot sweep");
  const bool shown = ProgressShown();
  ProgressBar bar("points");
  const SweepProgressCallback progress = GridProgress(bar);
  Ranks ranks;  // under mpirun: rank 0 runs the sweep, the others compute blocks of points
  if (ranks.worker()) return ranks.Serve(SweepBlocks(s), s.threads);  // rank 0 validates
  const SweepSummary summary = RunSweep(s, progress, ranks.backend());
  if (shown) {
    fmt::print(stderr,
               "capsubot sweep: {} points, {} rows written to {} in {:.3f} s on {} threads{}\n",
               summary.points, summary.rows, s.output, summary.seconds, summary.threads,
               summary.points_resumed > 0
                   ? fmt::format(" ({} points resumed from the checkpoint)", summary.points_resumed)
                   : std::string());
  }
  return 0;
}

int Run(SweepCliOptions& opt, const CLI::App& cmd) {
  try {
    return RunSweepCommand(opt, cmd);
  } catch (const SweepResumableError& e) {
    throw WriteError(WithFlagNames(e.what(), kFlagOf) +
                     ": run the same command with --resume to continue");
  } catch (const WriteError& e) {
    throw WriteError(WithFlagNames(e.what(), kFlagOf));
  } catch (const IoError& e) {
    throw IoError(WithFlagNames(e.what(), kFlagOf));
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(WithFlagNames(e.what(), kFlagOf));
  }
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
  cmd->add_option("--grid", opt->grids,
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
  AddForcingOptions(*cmd, opt->forcing);
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
  AddParamsOptions(*cmd, opt->sweep.params);
  cmd->add_option(
         "--output,-o", opt->sweep.output,
         "the CSV file to write (required); - writes to standard output (no --resume then)")
      ->required()
      ->type_name("FILE");
  cmd->add_flag("--stability", opt->sweep.stability,
                "add the columns spectral_radius (of the impact map, docs/model.md section 8), "
                "lambda_re, lambda_im (its largest multiplier), stable (1 when < 1) and loss "
                "(fold, flip or torus when unstable)");
  std::string modes;
  for (SweepOptimize mode : SweepOptimizeModes()) {
    modes += (modes.empty() ? "" : "|") + std::string(SweepOptimizeName(mode));
  }
  CLI::Option* optimize =
      cmd->add_option(
             "--optimize", opt->optimize,
             "the best gait at every point: phi0 (P1: the impact phase for the given force "
             "shape; adds column phi0), forcing (P2: A, c, phi0 with A + c <= --bound; "
             "adds A, c, phi0), fourier (P3: a --harmonics K force with max |F| <= "
             "--bound; adds c, a1..aK, b1..bK) or reach (the fastest motion from rest, as "
             "`optimize --problem reach`: A, c, phi0, alpha, mean_velocity, ..., the robust "
             "seed's seed_v_mean and seed_mean_velocity_from_rest; seconds per point); adds a "
             "status column")
          ->type_name(modes);
  CLI::Option* rho_max =
      cmd->add_option("--rho-max", opt->search.gait.rho_max,
                      "with --optimize: maximise over orbits whose spectral radius is at most "
                      "rho_max > 0 (docs/model.md sections 8, 12); inf: no stability requirement")
          ->capture_default_str()
          ->type_name(kFloatOrInf)
          ->needs(optimize);
  cmd->add_flag_callback(
         "--stable-only", [opt] { opt->search.gait.rho_max = 1.0; },
         "with --optimize: the same as --rho-max 1 (valid and stable orbits only)")
      ->excludes(rho_max)
      ->needs(optimize);
  cmd->add_option("--scan-points", opt->sweep.phase.scan_points,
                  fmt::format("with --optimize phi0: points of the optimiser's initial scan of "
                              "phi0, {} to {}",
                              kMinScanPoints, kMaxScanPoints))
      ->capture_default_str()
      ->needs(optimize);
  cmd->add_option("--bound", opt->search.gait.force_bound,
                  "with --optimize forcing|fourier|reach: the force bound A + c (max |F|) <= "
                  "bound <= T0 (default: T0)");
  cmd->add_option("--harmonics", opt->search.harmonics,
                  "with --optimize fourier: the number K of harmonics")
      ->capture_default_str();
  opt->starts_option = cmd->add_option(
      "--starts", opt->starts,
      "with --optimize forcing|fourier|reach: local polishes of the multistart, >= 1 "
      "(default: 10 for forcing and reach's seed, 20 for fourier)");
  cmd->add_option("--hops", opt->search.hops,
                  "with --optimize forcing|reach: basin-hopping restarts after the starts")
      ->capture_default_str();
  cmd->add_option("--global-algorithm", opt->search.global_algorithm,
                  "with --optimize forcing|fourier|reach: multistart or an NLopt global "
                  "algorithm (GN_ISRES, GN_ORIG_DIRECT, GN_ORIG_DIRECT_L, GN_AGS)")
      ->capture_default_str();
  cmd->add_option("--local-algorithm", opt->search.local_algorithm,
                  "with --optimize forcing|fourier|reach: the local polish (LN_COBYLA, "
                  "LD_SLSQP, LD_MMA, LD_CCSAQ)")
      ->capture_default_str();
  opt->global_evaluations_option = cmd->add_option(
      "--global-evaluations", opt->search.global_evaluations,
      fmt::format("with --optimize forcing|fourier|reach: evaluation budget of an NLopt global "
                  "algorithm (not multistart), 10 to {}",
                  kMaxStageEvaluations));
  cmd->add_option("--alpha", opt->alpha,
                  "with --optimize reach: a fixed mass ratio 0 < alpha < 1 (default: alpha is "
                  "optimised too)");
  // reach: the seed's check from rest and the search's evaluation budgets, which bound each
  // point (no wall-clock limit: the rows must not depend on the machine's speed).
  AddFromRestStartsOption(*cmd, opt->from_rest);
  AddReachBudgetOptions(*cmd, opt->from_rest);
  cmd->add_flag("--no-header-comment", opt->no_header_comment,
                "write no comment lines before the header (for tools that cannot skip '#' "
                "lines; pandas: comment='#', gnuplot: skips them by default)");
  cmd->add_flag("--resume", opt->sweep.resume,
                "continue an interrupted sweep from <output>.checkpoint (same options "
                "required; the checkpoint's checksums are verified); without it a sweep "
                "always starts again");
  cmd->add_option("--checkpoint-seconds", opt->sweep.checkpoint_seconds,
                  "minimum time [s] between two checkpoints (each one fsyncs the partial file); "
                  "0: after every block of rows")
      ->capture_default_str();
  cmd->add_option("--shard", opt->shard,
                  "compute only shard K of N (0 <= K < N): the grid points p with p % N = K; "
                  "the file gets a line '# shard K/N of T points'; `capsubot merge OUT "
                  "SHARD_FILES...` joins the N files into the file of the whole sweep; 0/1 "
                  "writes the file of the whole sweep (docs/cluster.md)")
      ->type_name("K/N");
  cmd->add_option("--threads", opt->sweep.threads,
                  "worker threads (default 0: all cores, std::thread::hardware_concurrency); "
                  "more than 4 per core is lowered to that, with a note")
      ->capture_default_str();
  AddProgressOptions(*cmd);
  SetExamples(*cmd, {{"the orbit and its stability at 4 phases x 2 restitutions, to "
                      "standard output",
                      "sweep --grid phi0=-3:-2.4:4 --grid e=0.5,1 --A 0.05 --c 0.02 "
                      "--T0 0.1 --stability -o -"},
                     {"P2 at every point of a 17 x 11 grid, shard 0 of 3 (1/3 and 2/3 "
                      "elsewhere, then `capsubot merge`; --progress for lines in a Slurm log)",
                      "sweep --grid T0=0.01:1:17:log --grid e=0:1:11 --optimize forcing "
                      "--shard 0/3 -o part0.csv"}});
  return {cmd, [opt, cmd] { return Run(*opt, *cmd); }, [] { return true; }};
}

}  // namespace capsubot::app
