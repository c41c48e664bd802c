// capsubot solve: the one-impact orbit for a given force, with every validity condition.

#include <fmt/format.h>

#include <memory>
#include <string>
#include <vector>

#include "capsubot/cli/force_options.hpp"
#include "capsubot/cli/from_rest_options.hpp"
#include "capsubot/cli/help_format.hpp"
#include "capsubot/cli/provenance.hpp"
#include "capsubot/cli/result_output.hpp"
#include "capsubot/cli/setting_options.hpp"
#include "capsubot/io/io.hpp"
#include "capsubot/job/orbit_trajectory_settings.hpp"
#include "capsubot/job/solve_job.hpp"
#include "capsubot/report/orbit_csv.hpp"
#include "capsubot/report/solution_json.hpp"
#include "capsubot/report/solve_text.hpp"
#include "commands.hpp"

namespace capsubot::cli {
namespace {

struct SolveOptions {
  ForcingOptions forcing;
  Params params;
  Margins margins;
  bool stability = false;
  std::string trajectory;
  OrbitTrajectoryOptions grid;  // --samples of --trajectory
  ResultOutput output;
  FromRestCliOptions from_rest;  // with --stability: the orbit checked from rest
};

const FlagNames kTrajectoryFlags = DashedFlags("trajectory samples");

// What the trajectory of the orbit does not depend on: the check of the orbit's validity and
// stability (its margins; the grid of starts from rest).
const std::vector<std::string> kNotInTrajectory = {"--margin", "--margin-stroke", "--stick-margin",
                                                   "--stability", "--from-rest-starts"};

// Writes the trajectory of `orbit` to --trajectory, or says on stderr why not: no orbit.
void WriteTrajectory(const Orbit& orbit, const SolveOptions& opt, const CLI::App& cmd) {
  if (!orbit.ok()) {
    fmt::print(stderr, "capsubot solve: note: --trajectory not written: no orbit ({})\n",
               StatusName(orbit.status));
    return;
  }
  AtomicFile file(opt.trajectory, "--trajectory");
  file.stream() << OutputProvenance(cmd, kNotInTrajectory).CommentLine();
  text::WriteOrbitTrajectoryCsv(file.stream(), orbit, opt.grid);
  file.Commit();
}

int Run(const SolveOptions& opt, const CLI::App& cmd) {
  SolveJobOptions o;
  o.params = opt.params;
  o.margins = opt.margins;
  const FromRestOptions from_rest = opt.from_rest.Check();  // bad grids before any work
  o.forcing = opt.forcing.Build();
  if (opt.stability) o.stability = from_rest;
  RequireDistinctOutputs({{opt.output.path, "-o"}, {opt.trajectory, "--trajectory"}});
  CheckResultOutput(opt.output.path);
  const SolveJobResult r = RunSolveJob(o);
  if (!opt.trajectory.empty()) WriteTrajectory(r.solution.orbit, opt, cmd);
  // Without --stability the orbit is not checked from rest: its grid does not shape the output.
  const std::vector<std::string> unused =
      opt.stability ? std::vector<std::string>{} : std::vector<std::string>{"--from-rest-starts"};
  opt.output.Write(cmd, r, json::SolveJobJson, text::SolveJobText, unused);
  return 0;
}

}  // namespace

Command AddSolveCommand(CLI::App& app) {
  auto opt = std::make_shared<SolveOptions>();
  CLI::App* cmd = app.add_subcommand(
      "solve",
      "The one-impact periodic orbit (docs/model.md section 4) for a given force: stop phase phi1, "
      "mass ratio alpha, impact velocity u, step I and mean velocity, with every validity "
      "condition of section 5. Exit status 0 whenever the computation ran, valid orbit or not.");
  AddForcingOptions(*cmd, opt->forcing);
  AddParamsOptions(*cmd, opt->params, &opt->margins);
  cmd->add_flag("--json", opt->output.json,
                "print one JSON object (keys A, c, phi0, T0, e, phi1, alpha, u, v_plus, I, "
                "v_mean, x_min, x_max, valid, violations, and energy {motor_work, "
                "motor_work_positive, friction_loss, impact_loss} per period in (m1+m2) "
                "omega^2 L^2; null where a quantity does not exist)");
  cmd->add_flag(
      "--stability", opt->stability,
      "also compute the stability of the orbit (docs/model.md section 8): adds the keys "
      "multipliers (array of {re, im}, the eigenvalues of the impact map's Jacobian), "
      "spectral_radius and stable (spectral_radius < 1) to --json, and checks the orbit from "
      "rest (docs/model.md section 12): from_rest = the attractors object of "
      "`capsubot attractors --json` plus reached (starts that end on the orbit) and "
      "summary");
  AddFromRestOptions(*cmd, opt->from_rest, false);
  CLI::Option* trajectory =
      cmd->add_option("--trajectory", opt->trajectory,
                      "write phi, x, u, v over one period to this CSV file (phi = 0 just after "
                      "the impact)")
          ->type_name("FILE");
  AddSettings(*cmd, opt->grid, OrbitTrajectorySettings(), kTrajectoryFlags);
  cmd->get_option("--samples")->needs(trajectory);
  AddResultOutputOption(*cmd, opt->output.path, "the orbit");
  SetExamples(*cmd, {{"the paper's worked example: c = A = T0/2 at the paper's impact "
                      "phase (not a valid orbit)",
                      "solve --A 0.5 --c 0.5 --phi0 -2.944899971002"},
                     {"a valid, stable orbit and the multipliers of its impact map",
                      "solve --A 0.05 --c 0.02 --phi0 -2.842 --T0 0.1 --e 0.5 "
                      "--stability"}});
  return {cmd, [opt, cmd] { return Run(*opt, *cmd); }, {}};
}

}  // namespace capsubot::cli
