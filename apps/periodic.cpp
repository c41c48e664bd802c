// capsubot periodic: a periodic motion of any kind by Newton shooting on the p-th iterate of
// the stroboscopic map, with its multipliers (docs/model.md section 13).

#include "capsubot/attract/periodic.hpp"

#include <fmt/format.h>

#include <memory>

#include "attract_options.hpp"
#include "capsubot/report/periodic_json.hpp"
#include "commands.hpp"
#include "help_format.hpp"
#include "provenance.hpp"
#include "report.hpp"

namespace capsubot::app {
namespace {

struct PeriodicCommandOptions {
  RobotOptions robot;
  ShootingOptions shooting;
  PhaseState start;
  std::string from_rest;
  bool json = false;
  CLI::Option* state_options[4] = {};
  CLI::Option* transient_option = nullptr;
};

int Run(PeriodicCommandOptions& opt, const CLI::App& cmd) {
  const Forcing forcing = opt.robot.forcing.Build();
  int given = 0;
  for (CLI::Option* o : opt.state_options) given += o->count() > 0 ? 1 : 0;
  PhaseState start = opt.start;
  ShootingOptions so = opt.shooting;
  if (!opt.from_rest.empty()) {
    if (given > 0) {
      throw std::invalid_argument(
          "--from-rest gives the start: do not give --x0, --u0, --v0 or --psi with it");
    }
    start = ParseRestStart("--from-rest", opt.from_rest);
  } else {
    if (given < 4) {
      throw std::invalid_argument(
          "the start is missing: give all of --x0, --u0, --v0, --psi (or --from-rest X0,PSI)");
    }
    if (opt.transient_option->count() == 0) so.transient = 0;  // start near the motion itself
  }
  RequirePhase("psi", start.psi);  // a start phase in radians, as phi0
  const PeriodicMotion m =
      FindPeriodicMotion(forcing, opt.robot.params, opt.robot.alpha, start, so);
  if (opt.json) {
    nlohmann::json j = json::PeriodicJson(m);
    AddProvenanceJson(j, cmd);
    fmt::print("{}\n", j.dump());
    return 0;
  }
  std::string t = "periodic motion by Newton shooting on the stroboscopic map\n";
  t += fmt::format("  force          {}\n", ForceFormula(forcing));
  t += fmt::format("  model          T0 = {}, e = {}, alpha = {}\n", opt.robot.params.T0,
                   opt.robot.params.e, opt.robot.alpha);
  t += fmt::format("  status         {} (residual {:.3g} after {} Newton iterations)\n",
                   ShootingStatusName(m.status), m.residual, m.iterations);
  t += fmt::format("  period         {}: {} right + {} left impacts per {} period{}\n", m.period,
                   m.impacts_right, m.impacts_left, m.period, m.period == 1 ? "" : "s");
  t += fmt::format("  mean velocity  {:.12g} (omega L)\n", m.mean_velocity);
  t += fmt::format("  state          x = {:.12g}, u = {:.12g}, v = {:.12g} at psi = {:.12g} ({})\n",
                   m.state.x, m.state.u, m.state.v, m.state.psi, SimModeName(m.mode));
  t += "  multipliers   ";
  for (const auto& l : m.multipliers) {
    t += fmt::format(" {:.10g}{}", l.real(),
                     l.imag() != 0.0 ? fmt::format("{:+.10g}i", l.imag()) : std::string());
  }
  t += fmt::format("   ({} free coordinates at the section)\n", m.dimension);
  if (m.status != ShootingStatus::kConverged) {
    t += "  verdict        none: Newton did not converge, so no periodic motion is known here\n";
  } else {
    t += fmt::format(
        "  verdict        {} (spectral radius {:.10g}; largest multiplier is {:.3g} "
        "from +1, {:.3g} from -1)\n",
        m.stable ? "stable" : "unstable", m.spectral_radius, m.distance_to_plus_one,
        m.distance_to_minus_one);
  }
  fmt::print("{}", t);
  return 0;
}

}  // namespace

Command AddPeriodicCommand(CLI::App& app) {
  auto opt = std::make_shared<PeriodicCommandOptions>();
  opt->shooting.transient = 200;
  CLI::App* cmd = app.add_subcommand(
      "periodic",
      "A periodic motion of any kind (several impacts, both walls, period p) found exactly by "
      "Newton's method on the p-th iterate of the stroboscopic map (docs/model.md section 13), "
      "with its multipliers. Start from a state (--x0 --u0 --v0 at forcing phase --psi, no "
      "transient unless --transient is given) or from rest (--from-rest X0,PSI after "
      "--transient periods).");
  AddRobotOptions(*cmd, opt->robot, false);
  opt->state_options[0] =
      cmd->add_option("--x0", opt->start.x, "start: position of the inner body");
  opt->state_options[1] = cmd->add_option("--u0", opt->start.u, "start: relative velocity");
  opt->state_options[2] = cmd->add_option("--v0", opt->start.v, "start: capsule velocity");
  opt->state_options[3] = cmd->add_option("--psi", opt->start.psi,
                                          "start: forcing phase (F = A sin(psi + phi0) + c there)")
                              ->type_name(kPhase);
  cmd->add_option("--from-rest", opt->from_rest,
                  "start from rest at x0 = X0 and forcing phase PSI, then run --transient periods")
      ->type_name("X0,PSI");
  opt->transient_option =
      cmd->add_option("--transient", opt->shooting.transient,
                      "periods simulated before shooting (default 200 with --from-rest, else 0)");
  cmd->add_option("--max-period", opt->shooting.max_period,
                  "largest period searched, in forcing periods")
      ->capture_default_str();
  cmd->add_option("--step", opt->shooting.step,
                  "step of the central finite differences of the Jacobian")
      ->capture_default_str();
  cmd->add_option("--chatter-velocity", opt->shooting.chatter_velocity,
                  "the simulator's chatter cut-off (omega L)")
      ->capture_default_str();
  cmd->add_flag("--json", opt->json,
                "print one JSON object: status, period, impacts_right, impacts_left, "
                "mean_velocity, state {x, u, v, psi}, mode, dimension, multipliers [[re, im], "
                "...], spectral_radius, stable, distance_to_plus_one, distance_to_minus_one, "
                "distance_to_unit_circle, residual, iterations, provenance");
  SetExamples(*cmd, {{"that motion found exactly by Newton's method from the start at "
                      "rest x0 = 0.5, psi = 1",
                      "periodic --A 0.34063197373861814 --c 0.06410131873607934 "
                      "--phi0 -3.1181183398453047 --alpha 0.6435592358295166 --T0 1 "
                      "--e 1 --from-rest 0.5,1"}});
  return {cmd,
          [opt, cmd] { return RunNamingFlags(MotionFlagNames(), [&] { return Run(*opt, *cmd); }); },
          {}};
}

}  // namespace capsubot::app
