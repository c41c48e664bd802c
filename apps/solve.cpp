// capsubot solve: the one-impact orbit for a given force, with every validity condition.

#include <fmt/format.h>

#include <memory>
#include <string>
#include <vector>

#include "capsubot/io/io.hpp"
#include "capsubot/job/solve_job.hpp"
#include "capsubot/report/solution_json.hpp"
#include "capsubot/report/solve_text.hpp"
#include "commands.hpp"
#include "from_rest_options.hpp"
#include "help_format.hpp"
#include "provenance.hpp"
#include "result_output.hpp"

namespace capsubot::app {
namespace {

struct SolveOptions {
  ForcingOptions forcing;
  Params params;
  Margins margins;
  bool json = false;
  bool stability = false;
  std::string trajectory;
  std::string output;  // -o: the text or JSON printed; empty: standard output
  int samples = 1001;
  FromRestCliOptions from_rest;  // with --stability: the orbit checked from rest
};

// What the trajectory of the orbit does not depend on: the check of the orbit's validity and
// stability (its margins; the grid of starts from rest).
const std::vector<std::string> kNotInTrajectory = {"--margin", "--margin-stroke", "--stick-margin",
                                                   "--stability", "--from-rest-starts"};

void WriteTrajectory(const Orbit& o, const std::string& path, int samples, const CLI::App& cmd) {
  AtomicFile file(path, "--trajectory");
  auto& out = file.stream();
  out << OutputProvenance(cmd, kNotInTrajectory).CommentLine() << "phi,x,u,v\n";
  for (int i = 0; i < samples; ++i) {
    const double phi = kTau * i / (samples - 1);
    // phi = 0 is just after the impact, phi = tau just before the next one.
    out << FormatNumber(phi) << ',' << FormatNumber(o.x(phi)) << ',' << FormatNumber(o.dx(phi))
        << ',' << FormatNumber(o.v(phi)) << '\n';
  }
  file.Commit();
}

int Run(const SolveOptions& opt, const CLI::App& cmd) {
  SolveJobOptions o;
  o.params = opt.params;
  o.margins = opt.margins;
  const FromRestOptions from_rest = opt.from_rest.Check();  // bad grids before any work
  o.forcing = opt.forcing.Build();
  if (opt.stability) o.stability = from_rest;
  RequireDistinctOutputs({{opt.output, "-o"}, {opt.trajectory, "--trajectory"}});
  CheckResultOutput(opt.output);
  const SolveJobResult r = RunSolveJob(o);
  const Orbit& orbit = r.solution.orbit;
  if (!opt.trajectory.empty()) {
    if (orbit.ok()) {
      WriteTrajectory(orbit, opt.trajectory, opt.samples, cmd);
    } else {
      fmt::print(stderr, "capsubot solve: note: --trajectory not written: no orbit ({})\n",
                 StatusName(orbit.status));
    }
  }
  // Without --stability the orbit is not checked from rest: its grid does not shape the output.
  const std::vector<std::string> unused =
      opt.stability ? std::vector<std::string>{} : std::vector<std::string>{"--from-rest-starts"};
  WriteResult(opt.output, opt.json ? JsonOutput(json::SolveJobJson(r), JsonProvenance(cmd, unused))
                                   : text::SolveJobText(r));
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
  cmd->add_flag("--json", opt->json,
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
  Bounded(cmd->add_option("--samples", opt->samples, "number of rows of --trajectory"), 2,
          kMaxTrajectoryRows)
      ->capture_default_str()
      ->needs(trajectory);
  AddResultOutputOption(*cmd, opt->output, "the orbit");
  SetExamples(*cmd, {{"the paper's worked example: c = A = T0/2 at the paper's impact "
                      "phase (not a valid orbit)",
                      "solve --A 0.5 --c 0.5 --phi0 -2.944899971002"},
                     {"a valid, stable orbit and the multipliers of its impact map",
                      "solve --A 0.05 --c 0.02 --phi0 -2.842 --T0 0.1 --e 0.5 "
                      "--stability"}});
  return {cmd, [opt, cmd] { return Run(*opt, *cmd); }, {}};
}

}  // namespace capsubot::app
