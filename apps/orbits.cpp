// capsubot orbits: every one-impact orbit of a robot whose mass ratio is fixed (docs/model.md
// section 8), with validity, mean velocity and stability.

#include <fmt/format.h>

#include <cstdint>
#include <memory>

#include "capsubot/job/orbits_job.hpp"
#include "capsubot/report/orbits_text.hpp"
#include "capsubot/report/solution_json.hpp"
#include "commands.hpp"
#include "help_format.hpp"
#include "provenance.hpp"
#include "result_output.hpp"

namespace capsubot::app {
namespace {

struct OrbitsOptions {
  ForcingOptions forcing;
  OrbitsJobOptions job;
  bool json = false;
  std::string output;  // -o: the text or JSON printed; empty: standard output
};

int Run(OrbitsOptions& opt, const CLI::App& cmd) {
  opt.job.params.Validate();
  opt.job.margins.Validate();
  opt.job.forcing = opt.forcing.Build(false);
  CheckResultOutput(opt.output);
  const OrbitsJobResult result = RunOrbitsJob(opt.job);
  if (!opt.json) {
    WriteResult(opt.output, text::OrbitsJobText(result, "--max-evaluations"));
    return 0;
  }
  const nlohmann::json j = {{"orbits", json::RobotOrbitsJson(result.orbits, result.complete)}};
  WriteResult(opt.output, JsonOutput(j, JsonProvenance(cmd)));
  if (!result.complete) {
    fmt::print(stderr, "capsubot orbits: note: {}\n",
               text::OrbitsIncompleteNote("--max-evaluations"));
  }
  return 0;
}

}  // namespace

Command AddOrbitsCommand(CLI::App& app) {
  auto opt = std::make_shared<OrbitsOptions>();
  CLI::App* cmd = app.add_subcommand(
      "orbits",
      "Every one-impact orbit of a given robot (mass ratio alpha fixed, docs/model.md section 8): "
      "all impact phases phi0 in [-pi, pi) with alpha(phi0) = alpha, none missed, each with "
      "its validity, mean velocity and stability.");
  AddForcingOptions(*cmd, opt->forcing, false);
  AddParamsOptions(*cmd, opt->job.params, &opt->job.margins);
  cmd->add_option("--alpha", opt->job.alpha, "mass ratio m2/(m1+m2) of the robot, 0 < alpha < 1")
      ->required();
  Bounded(cmd->add_option("--max-evaluations", opt->job.max_evaluations,
                          "work bound of the search: evaluations of the orbit equation while "
                          "refining the circle (default 4000000, far above what the tested "
                          "forces need); when it is hit, orbits may be missing: a note says so"),
          1, kMaxOrbitEvaluations)
      ->capture_default_str();
  cmd->add_flag("--json", opt->json,
                "print one JSON object: orbits (an array with one object per orbit, sorted by "
                "phi0, with the keys of `solve --stability --json` without from_rest, and "
                "complete: false when the search hit its work bound and orbits may be missing; a "
                "note on stderr then says so) and provenance");
  AddResultOutputOption(*cmd, opt->output, "the orbits");
  SetExamples(*cmd, {{"every one-impact orbit of the robot with mass ratio 0.28, none "
                      "missed",
                      "orbits --A 0.05 --c 0.02 --T0 0.1 --e 0.5 --alpha 0.28"}});
  return {cmd, [opt, cmd] { return Run(*opt, *cmd); }, {}};
}

}  // namespace capsubot::app
