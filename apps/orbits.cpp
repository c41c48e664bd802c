// capsubot orbits: every one-impact orbit of a robot whose mass ratio is fixed (docs/model.md
// section 8), with validity, mean velocity and stability.

#include <fmt/format.h>

#include <memory>

#include "capsubot/cli/force_options.hpp"
#include "capsubot/cli/help_format.hpp"
#include "capsubot/cli/provenance.hpp"
#include "capsubot/cli/result_output.hpp"
#include "capsubot/cli/setting_options.hpp"
#include "capsubot/job/orbits_job.hpp"
#include "capsubot/job/orbits_settings.hpp"
#include "capsubot/job/params_settings.hpp"
#include "capsubot/report/orbits_text.hpp"
#include "capsubot/report/solution_json.hpp"
#include "commands.hpp"

namespace capsubot::cli {
namespace {

struct OrbitsOptions {
  ForcingOptions forcing;
  OrbitsJobOptions job;
  ResultOutput output;
};

const FlagNames kOrbitsFlags = DashedFlags("alpha max_evaluations");

int Run(OrbitsOptions& opt, const CLI::App& cmd) {
  opt.job.robot.params.Validate();
  opt.job.margins.Validate();
  opt.job.robot.forcing = opt.forcing.Build(false);
  CheckResultOutput(opt.output.path);
  const OrbitsJobResult result = RunOrbitsJob(opt.job);
  const std::string bound = SettingNames{kOrbitsFlags}.Name("max_evaluations");
  opt.output.Write(cmd, result, json::OrbitsJobJson,
                   [&](const OrbitsJobResult& r) { return text::OrbitsJobText(r, bound.c_str()); });
  // The text ends with this note; the JSON says it by "complete": false, and on stderr.
  if (opt.output.json && !result.complete) {
    fmt::print(stderr, "capsubot orbits: note: {}\n", text::OrbitsIncompleteNote(bound.c_str()));
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
  AddParamsOptions(*cmd, opt->job.robot.params, &opt->job.margins);
  AddSettings(*cmd, opt->job.robot, MassRatioSettings(), kOrbitsFlags);
  AddSettings(*cmd, opt->job, OrbitsSettings(), kOrbitsFlags);
  cmd->get_option("--alpha")->required();
  opt->output.Add(*cmd,
                  "print one JSON object: orbits (an array with one object per orbit, sorted by "
                  "phi0, with the keys of `solve --stability --json` without from_rest, and "
                  "complete: false when the search hit its work bound and orbits may be missing; "
                  "a note on stderr then says so) and provenance",
                  "the orbits");
  SetExamples(*cmd, {{"every one-impact orbit of the robot with mass ratio 0.28, none "
                      "missed",
                      "orbits --A 0.05 --c 0.02 --T0 0.1 --e 0.5 --alpha 0.28"}});
  return {cmd, [opt, cmd] { return Run(*opt, *cmd); }, {}};
}

}  // namespace capsubot::cli
