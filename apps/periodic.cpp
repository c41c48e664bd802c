// capsubot periodic: a periodic motion of any kind by Newton shooting on the p-th iterate of
// the stroboscopic map, with its multipliers (docs/model.md section 13).

#include <fmt/format.h>

#include <memory>
#include <stdexcept>

#include "capsubot/cli/attract_options.hpp"
#include "capsubot/cli/help_format.hpp"
#include "capsubot/cli/provenance.hpp"
#include "capsubot/cli/result_output.hpp"
#include "capsubot/cli/setting_options.hpp"
#include "capsubot/job/periodic_job.hpp"
#include "capsubot/job/periodic_start_spec.hpp"
#include "capsubot/job/shooting_settings.hpp"
#include "capsubot/report/periodic_json.hpp"
#include "capsubot/report/periodic_text.hpp"
#include "commands.hpp"

namespace capsubot::cli {
namespace {

struct PeriodicCommandOptions {
  RobotOptions robot;
  ShootingOptions shooting;
  StartStateOptions start_state;  // --x0, --u0, --v0, --psi
  std::string from_rest;
  int transient = 0;
  ResultOutput output;
  CLI::Option* transient_option = nullptr;
};

const FlagNames kShootingFlags = DashedFlags("max_period step chatter_velocity");

// The start --from-rest or --x0, --u0, --v0, --psi give, with --transient when given (else
// the start's default).
PeriodicStart Start(const PeriodicCommandOptions& opt) {
  PeriodicStartSpec spec{opt.start_state.Spec(), std::nullopt, std::nullopt, std::nullopt};
  if (!opt.from_rest.empty()) spec.from_rest = ParseRestStart("--from-rest", opt.from_rest);
  if (opt.transient_option->count() > 0) spec.transient = opt.transient;
  return spec.Build("--from-rest X0,PSI", kStartFlags);
}

int Run(const PeriodicCommandOptions& opt, const CLI::App& cmd) {
  PeriodicJobOptions o;
  o.robot = opt.robot.Model();
  o.start = Start(opt);
  o.shooting = opt.shooting;
  CheckResultOutput(opt.output.path);
  opt.output.Write(cmd, RunPeriodicJob(o), json::PeriodicJobJson, text::PeriodicJobText);
  return 0;
}

}  // namespace

Command AddPeriodicCommand(CLI::App& app) {
  auto opt = std::make_shared<PeriodicCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "periodic",
      "A periodic motion of any kind (several impacts, both walls, period p) found exactly by "
      "Newton's method on the p-th iterate of the stroboscopic map (docs/model.md section 13), "
      "with its multipliers. Start from a state (--x0 --u0 --v0 at forcing phase --psi, no "
      "transient unless --transient is given) or from rest (--from-rest X0,PSI after "
      "--transient periods).");
  AddRobotOptions(*cmd, opt->robot, false);
  opt->start_state.Add(*cmd);
  cmd->add_option("--from-rest", opt->from_rest,
                  "start from rest at x0 = X0 and forcing phase PSI, then run --transient periods")
      ->type_name("X0,PSI");
  opt->transient_option =
      cmd->add_option("--transient", opt->transient,
                      "periods simulated before shooting (default 200 with --from-rest, else 0)");
  AddSettings(*cmd, opt->shooting, ShootingSettings(), kShootingFlags);
  opt->output.Add(*cmd,
                  "print one JSON object: status, period, impacts_right, impacts_left, "
                  "mean_velocity, state {x, u, v, psi}, mode, dimension, multipliers [[re, im], "
                  "...], spectral_radius, stable, distance_to_plus_one, distance_to_minus_one, "
                  "distance_to_unit_circle, residual, iterations, provenance",
                  "the motion");
  SetExamples(*cmd, {{"that motion found exactly by Newton's method from the start at "
                      "rest x0 = 0.5, psi = 1",
                      "periodic --A 0.34063197373861814 --c 0.06410131873607934 "
                      "--phi0 -3.1181183398453047 --alpha 0.6435592358295166 --T0 1 "
                      "--e 1 --from-rest 0.5,1"}});
  return {cmd,
          [opt, cmd] { return RunNamingFlags(MotionFlagNames(), [&] { return Run(*opt, *cmd); }); },
          {}};
}

}  // namespace capsubot::cli
