// capsubot bifurcation: brute-force bifurcation diagram with the state carried along, up and
// down, plus the analytic one-impact orbits (docs/model.md section 13).

#include "capsubot/bifurcation.hpp"

#include <fmt/format.h>

#include <cmath>
#include <memory>

#include "attract_options.hpp"
#include "capsubot/io.hpp"
#include "commands.hpp"

namespace capsubot::app {
namespace {

struct BifurcationCommandOptions {
  RobotOptions robot;
  BifurcationOptions diagram;
  std::string param;
  std::string direction = "both";
  std::string start = "0.5,0";
  std::string output, summary;
  bool no_analytic = false;
};

int Run(BifurcationCommandOptions& opt) {
  const Forcing forcing = opt.robot.forcing.Build();
  BifurcationOptions o = opt.diagram;
  o.param = ParseBifurcationParam(opt.param, &o.harmonic);
  o.motion = opt.robot.motion;
  o.start = ParseRestStart("--start", opt.start);
  o.analytic = !opt.no_analytic && !opt.summary.empty();
  if (opt.direction != "up" && opt.direction != "down" && opt.direction != "both") {
    throw std::invalid_argument(
        fmt::format("--direction = {} is invalid: expected up, down or both", opt.direction));
  }
  o.up = opt.direction != "down";
  o.down = opt.direction != "up";
  double alpha = opt.robot.alpha;
  if (o.param == BifurcationParam::kAlpha) alpha = o.from;  // the swept value decides
  if (std::isnan(alpha)) {
    throw std::invalid_argument("option --alpha is missing: give the mass ratio of the robot");
  }
  {
    AtomicFile probe(opt.output, "-o");  // fail on an unwritable path before the long run
  }
  const BifurcationDiagram d =
      ComputeBifurcation(forcing, opt.robot.params, alpha, o, TerminalProgress("parameter values"));
  AtomicFile impacts(opt.output, "-o");
  impacts.stream() << "param,direction,period_index,wall,phase,velocity\n";
  for (const ImpactPoint& p : d.impacts) {
    impacts.stream() << FormatNumber(p.param) << ',' << SweepDirectionName(p.direction) << ','
                     << p.period_index << ',' << (p.right ? "right" : "left") << ','
                     << FormatNumber(p.phase) << ',' << FormatNumber(p.velocity) << '\n';
  }
  std::unique_ptr<AtomicFile> summary;
  if (!opt.summary.empty()) {
    summary = std::make_unique<AtomicFile>(opt.summary, "--summary");
    auto& s = summary->stream();
    s << "param,direction,period,impacts_right,impacts_left,mean_velocity,largest_multiplier,"
         "largest_multiplier_im,spectral_radius,status\n";
    for (const BifurcationPoint& p : d.summary) {
      s << FormatNumber(p.param) << ',' << SweepDirectionName(p.direction) << ',' << p.motion.period
        << ',' << p.motion.impacts_right << ',' << p.motion.impacts_left << ','
        << FormatNumber(p.motion.mean_velocity) << ',' << FormatNumber(p.multiplier_re) << ','
        << FormatNumber(p.multiplier_im) << ',' << FormatNumber(p.spectral_radius) << ','
        << MotionStatusName(p.motion.status) << '\n';
    }
  }
  impacts.Commit();
  if (summary) summary->Commit();
  fmt::print(
      "bifurcation diagram over {} = {:g} .. {:g} ({} values, {}): {} impacts written to "
      "{}{}\n",
      opt.param, o.from, o.to, o.steps, opt.direction, d.impacts.size(), opt.output,
      summary ? fmt::format(", {} summary rows to {}", d.summary.size(), opt.summary)
              : std::string());
  return 0;
}

}  // namespace

Command AddBifurcationCommand(CLI::App& app) {
  auto opt = std::make_shared<BifurcationCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "bifurcation",
      "Bifurcation diagram by brute force (docs/model.md section 13): the parameter is stepped "
      "over its range with the state carried from each value to the next, up and then down, so "
      "coexisting attractors show as hysteresis. At each value: a transient, then the impacts of "
      "the record (-o) and a summary row (--summary) with the period, impacts, mean velocity and "
      "largest multiplier (Newton shooting), plus the valid analytic one-impact orbits "
      "(direction = analytic).");
  AddRobotOptions(*cmd, opt->robot);
  cmd->get_option("--alpha")->required(false)->description(
      "mass ratio m2/(m1+m2) of the robot, 0 < alpha < 1 (not needed with --param alpha)");
  cmd->add_option("--param", opt->param,
                  "the parameter: A, c, alpha, T0, e, phi0, or a Fourier coefficient a1, b1, "
                  "a2, ... (a_k, b_k of the force given by --sin/--cos; a1 and b1 of the "
                  "harmonic force are 0 and A)")
      ->required();
  cmd->add_option("--from", opt->diagram.from, "first value of the parameter")->required();
  cmd->add_option("--to", opt->diagram.to, "last value of the parameter")->required();
  cmd->add_option("--steps", opt->diagram.steps, "values of the parameter, both ends included")
      ->capture_default_str();
  cmd->add_option("--direction", opt->direction, "up, down or both (up, then down)")
      ->capture_default_str();
  cmd->add_option("--start", opt->start,
                  "start of each sweep: from rest at x0 = X0, forcing phase PSI")
      ->type_name("X0,PSI")
      ->capture_default_str();
  cmd->add_option("-o,--output", opt->output,
                  "CSV of every recorded impact: param, direction, period_index, wall, phase, "
                  "velocity")
      ->required();
  cmd->add_option("--summary", opt->summary,
                  "CSV, one row per value and direction: param, direction, period, "
                  "impacts_right, impacts_left, mean_velocity, largest_multiplier (real part), "
                  "largest_multiplier_im, spectral_radius, status; plus the analytic orbits");
  cmd->add_flag("--no-analytic", opt->no_analytic,
                "leave the analytic one-impact orbits out of the summary");
  AddThreadsOption(*cmd, opt->diagram.threads);
  return {cmd, [opt] { return Run(*opt); }};
}

}  // namespace capsubot::app
