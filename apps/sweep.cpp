// capsubot sweep: the orbit, its validity (and stability, or the best phase) over a 1-D or 2-D
// grid of parameters, to a CSV file (library: capsubot/sweep.hpp).

#include "capsubot/sweep.hpp"

#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

#include "commands.hpp"
#include "progress.hpp"

namespace capsubot::app {
namespace {

struct SweepCliOptions {
  std::vector<std::string> grids;
  ForcingOptions forcing;
  SweepOptions sweep;
  std::string optimize;
  CLI::App* cmd = nullptr;
};

// A gridded parameter takes its values from the grid: the same parameter given as an option
// as well contradicts it (it would be ignored).
void RejectGriddedOptions(const SweepCliOptions& opt) {
  for (const GridAxis& axis : opt.sweep.grid.axes) {
    const std::string name = std::string("--") + SweepParameterName(axis.parameter);
    const CLI::Option* option = opt.cmd->get_option_no_throw(name);
    if (option != nullptr && option->count() > 0) {
      throw std::invalid_argument(fmt::format(
          "{} = {} conflicts with --grid {}: expected one of them (the grid gives {} at every "
          "point)",
          name, option->results().front(), axis.ToString(), SweepParameterName(axis.parameter)));
    }
  }
}

int Run(SweepCliOptions& opt) {
  SweepOptions& s = opt.sweep;
  RequireInRange("--scan-points", s.phase.scan_points, kMinScanPoints, kMaxScanPoints);
  s.grid.axes.clear();
  for (const std::string& spec : opt.grids) s.grid.axes.push_back(ParseGridAxis(spec));
  s.grid.Validate();
  RejectGriddedOptions(opt);
  if (!opt.optimize.empty()) {
    if (opt.optimize != "phi0") {
      throw std::invalid_argument(fmt::format(
          "--optimize {} is invalid: expected phi0 (the impact phase, problem P1)", opt.optimize));
    }
    s.optimize_phi0 = true;
  }
  const Grid& g = s.grid;
  // A gridded A or c needs no option: the grid gives its value at every point.
  if (g.Has(SweepParameter::kc) && std::isnan(opt.forcing.c)) opt.forcing.c = 0.0;
  const bool phase_given_elsewhere =
      g.Has(SweepParameter::kphi0) || g.Has(SweepParameter::kalpha) || s.optimize_phi0;
  if (std::isnan(opt.forcing.c)) {
    throw std::invalid_argument("option --c is missing: give the mean force c (or --grid c=...)");
  }
  if (g.Has(SweepParameter::kA) && opt.forcing.fourier_option->count() == 0 &&
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
  if (s.optimize_phi0 || g.Has(SweepParameter::kalpha)) {
    if (opt.forcing.phi0_option->count() > 0) {
      throw std::invalid_argument(
          fmt::format("--phi0 = {} is invalid with {}: expected no --phi0 (the sweep finds phi0)",
                      opt.forcing.phi0, s.optimize_phi0 ? "--optimize phi0" : "--grid alpha"));
    }
  }
  s.threads = CapThreads(s.threads, "capsubot sweep");
  const bool tty = StderrIsTerminal();
  ProgressBar bar("points");
  SweepProgressCallback progress;
  if (tty) {
    progress = [&bar](const SweepProgress& p) {
      bar.Update(static_cast<double>(p.points_done), static_cast<double>(p.points_total), p.seconds,
                 static_cast<double>(p.points_resumed));
    };
  }
  const SweepSummary summary = RunSweep(s, progress);
  if (tty) {
    fmt::print(stderr,
               "capsubot sweep: {} points, {} rows written to {} in {:.3f} s on {} threads{}\n",
               summary.points, summary.rows, s.output, summary.seconds, summary.threads,
               summary.points_resumed > 0
                   ? fmt::format(" ({} points resumed from the checkpoint)", summary.points_resumed)
                   : std::string());
  }
  return 0;
}

}  // namespace

Command AddSweepCommand(CLI::App& app) {
  auto opt = std::make_shared<SweepCliOptions>();
  CLI::App* cmd = app.add_subcommand(
      "sweep",
      "The orbit and its validity (docs/model.md sections 4-5) at every point of a 1-D or 2-D grid "
      "of parameters, to a CSV file: columns <grid parameters>, phi1, alpha, u, v_plus, I, "
      "v_mean, x_min, x_max, valid, violations (empty cell: the quantity does not exist). "
      "Runs on all cores; the file is byte-identical for any --threads, written to "
      "<output>.partial and renamed at the end; --resume continues a killed sweep.");
  cmd->add_option("--grid", opt->grids,
                  "a grid name=lo:hi:n: n >= 1 equally spaced values from lo to hi inclusive "
                  "(n = 1: lo), name among A, c, phi0, T0, e, margin, alpha (lo, hi may be "
                  "pi or -pi). Give 1 or 2 grids; with 2 the first varies slowest. alpha "
                  "(robot mode) finds every orbit of the robot with that mass ratio: one row "
                  "per orbit, with columns orbits, orbit, phi0 (if that search ever hits its "
                  "work bound, the sweep stops with an error rather than write rows that may "
                  "miss orbits)")
      ->required()
      ->take_all()
      ->allow_extra_args(false);
  AddForcingOptions(*cmd, opt->forcing);
  cmd->get_option("--c")->required(false)->description(
      "mean force c of F (same unit as A), required unless c has a --grid; a directed orbit "
      "needs c > 0");
  cmd->get_option("--A")->description(
      "amplitude A >= 0 of the force F = A sin(phi + phi0) + c, in units of (m1+m2) omega^2 L "
      "(required unless A has a --grid or --sin/--cos are given)");
  cmd->get_option("--phi0")->description(
      "motor phase phi0 [rad] at the impact (phi = 0): F(phi) = A sin(phi + phi0) + c; "
      "required unless phi0 has a --grid, is optimised (--optimize phi0) or solved for "
      "(--grid alpha); default 0 for a Fourier force");
  AddParamsOptions(*cmd, opt->sweep.params);
  cmd->add_option(
         "--output,-o", opt->sweep.output,
         "the CSV file to write (required); - writes to standard output (no --resume then)")
      ->required();
  cmd->add_flag("--stability", opt->sweep.stability,
                "add the columns spectral_radius (of the impact map, docs/model.md section 8) and "
                "stable (1 when < 1)");
  CLI::Option* optimize =
      cmd->add_option("--optimize", opt->optimize,
                      "phi0: at every point, the impact phase phi0 maximising I over valid "
                      "orbits (problem P1); adds the columns phi0 (the optimum) and status");
  CLI::Option* rho_max =
      cmd->add_option("--rho-max", opt->sweep.phase.rho_max,
                      "with --optimize phi0: maximise over orbits whose spectral radius is at "
                      "most rho_max (docs/model.md sections 8, 12); inf: no stability requirement")
          ->capture_default_str()
          ->type_name(kFloatOrInf)
          ->needs(optimize);
  cmd->add_flag_callback(
         "--stable-only", [opt] { opt->sweep.phase.rho_max = 1.0; },
         "with --optimize phi0: the same as --rho-max 1 (valid and stable orbits only)")
      ->excludes(rho_max)
      ->needs(optimize);
  cmd->add_option("--scan-points", opt->sweep.phase.scan_points,
                  fmt::format("with --optimize phi0: points of the optimiser's initial scan of "
                              "phi0, {} to {}",
                              kMinScanPoints, kMaxScanPoints))
      ->capture_default_str()
      ->needs(optimize);
  cmd->add_flag("--resume", opt->sweep.resume,
                "continue an interrupted sweep from <output>.checkpoint (same options "
                "required); without it a sweep always starts again");
  cmd->add_option("--checkpoint-seconds", opt->sweep.checkpoint_seconds,
                  "minimum time [s] between two checkpoints (each one fsyncs the partial file); "
                  "0: after every block of rows")
      ->capture_default_str();
  cmd->add_option("--threads", opt->sweep.threads,
                  "worker threads (default 0: all cores, std::thread::hardware_concurrency); "
                  "more than 4 per core is lowered to that, with a note")
      ->capture_default_str();
  opt->cmd = cmd;
  return {cmd, [opt] { return Run(*opt); }};
}

}  // namespace capsubot::app
