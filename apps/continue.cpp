// capsubot continue: pseudo-arclength continuation of a periodic motion in one model parameter,
// with its special points (docs/continuation.md).

#include <fmt/format.h>

#include <algorithm>
#include <memory>
#include <string>

#include "attract_options.hpp"
#include "capsubot/continue/branch_switch.hpp"
#include "capsubot/continue/parameter_branch.hpp"
#include "capsubot/io/io.hpp"
#include "capsubot/report/continuation_json.hpp"
#include "commands.hpp"
#include "help_format.hpp"
#include "provenance.hpp"

namespace capsubot::app {
namespace {

struct ContinueCommandOptions {
  RobotOptions robot;
  ContinuationOptions continuation;
  PhaseState start;
  std::string param;
  bool from_orbit = false;
  bool switch_branch = false;
  bool json = false;
  std::string output;
  CLI::Option* state_options[4] = {};
};

// The branch as CSV: the '#' provenance line, header, one row per point.
void WriteBranchCsv(const Branch& b, const std::string& name, const std::string& comment,
                    const std::string& path) {
  std::size_t columns = 0;
  for (const BranchPoint& p : b.points) columns = std::max(columns, p.motion.multipliers.size());
  AtomicFile file(path, "-o");
  auto& out = file.stream();
  out << comment;
  out << name << ",x,u,v,psi,period,impacts_right,impacts_left,mean_velocity,spectral_radius";
  for (std::size_t k = 1; k <= columns; ++k) out << ",mu" << k << "_re,mu" << k << "_im";
  out << ",stable,label\n";
  for (const BranchPoint& p : b.points) {
    const PeriodicMotion& m = p.motion;
    out << FormatNumber(p.parameter) << ',' << FormatNumber(m.state.x) << ','
        << FormatNumber(m.state.u) << ',' << FormatNumber(m.state.v) << ','
        << FormatNumber(m.state.psi) << ',' << m.period << ',' << m.impacts_right << ','
        << m.impacts_left << ',' << FormatNumber(m.mean_velocity) << ','
        << FormatNumber(m.spectral_radius);
    for (std::size_t k = 0; k < columns; ++k) {
      if (k < m.multipliers.size()) {
        out << ',' << FormatNumber(m.multipliers[k].real()) << ','
            << FormatNumber(m.multipliers[k].imag());
      } else {
        out << ",,";
      }
    }
    out << ',' << (m.stable ? 1 : 0) << ',' << p.label << '\n';
  }
  file.Commit();
}

// The first located period doubling of the branch, or null.
const SpecialPoint* FirstPeriodDoubling(const Branch& b) {
  for (const SpecialPoint& sp : b.special_points) {
    if (sp.type == SpecialPointType::kPeriodDoubling && sp.located) return &sp;
  }
  return nullptr;
}

int Run(ContinueCommandOptions& opt, const CLI::App& cmd) {
  const Forcing forcing = opt.robot.forcing.Build();
  int given = 0;
  for (CLI::Option* o : opt.state_options) given += o->count() > 0 ? 1 : 0;
  if (opt.from_orbit && given > 0) {
    throw std::invalid_argument(
        "--from-orbit gives the start: do not give --x0, --u0, --v0 or --psi with it");
  }
  if (!opt.from_orbit && given < 4) {
    throw std::invalid_argument(
        "the start is missing: give all of --x0, --u0, --v0, --psi (or --from-orbit)");
  }
  opt.robot.params.Validate();
  const PhaseState start =
      opt.from_orbit ? OneImpactOrbitStart(forcing, opt.robot.params, opt.robot.alpha) : opt.start;
  RequirePhase("psi", start.psi);
  if (!opt.output.empty()) CheckWritable(opt.output, "-o");
  const Branch branch = ContinueParameter(forcing, opt.robot.params, opt.robot.alpha, opt.param,
                                          start, opt.continuation);
  if (!opt.output.empty() && branch.status == ContinuationStatus::kOk) {
    WriteBranchCsv(branch, opt.param, OutputProvenance(cmd).CommentLine(), opt.output);
  }
  const SpecialPoint* pd = opt.switch_branch ? FirstPeriodDoubling(branch) : nullptr;
  const Branch switched =
      pd == nullptr ? Branch{}
                    : SwitchAtPeriodDoubling(NamedParameterFamily(forcing, opt.robot.params,
                                                                  opt.robot.alpha, opt.param),
                                             *pd, opt.continuation);
  if (opt.json) {
    nlohmann::json j = json::BranchJson(branch, opt.param);
    if (opt.switch_branch) {
      j["switched"] = pd == nullptr ? nlohmann::json() : json::BranchJson(switched, opt.param);
    }
    AddProvenanceJson(j, cmd);
    fmt::print("{}\n", j.dump());
  } else {
    fmt::print("{}", branch.Summary(opt.param));
    if (opt.switch_branch) {
      fmt::print("{}",
                 pd == nullptr
                     ? std::string("no located period doubling: no branch to switch to\n")
                     : fmt::format("branch switched at the period doubling at {} = {:.12g}\n{}",
                                   opt.param, pd->parameter, switched.Summary(opt.param)));
    }
    if (!opt.output.empty() && branch.status == ContinuationStatus::kOk) {
      fmt::print("  written        {} points to {}\n", branch.points.size(), opt.output);
    }
  }
  return 0;
}

// The continuation's fields as the flags that set them.
const FlagNames& ContinueFlagNames() {
  static const FlagNames names = {{"from", "--from"},
                                  {"to", "--to"},
                                  {"max_points", "--max-points"},
                                  {"initial_step", "--initial-step"},
                                  {"min_step", "--min-step"},
                                  {"max_step", "--max-step"},
                                  {"max_period", "--max-period"},
                                  {"step", "--step"},
                                  {"chatter_velocity", "--chatter-velocity"},
                                  {"from_orbit", "--from-orbit"}};
  return names;
}

}  // namespace

Command AddContinueCommand(CLI::App& app) {
  auto opt = std::make_shared<ContinueCommandOptions>();
  CLI::App* cmd = app.add_subcommand(
      "continue",
      "Follow a periodic motion through a range of one model parameter by pseudo-arclength "
      "continuation of the fixed point of the stroboscopic map, with its folds, period "
      "doublings, Neimark-Sacker points, grazings, segment changes and speed extrema "
      "(docs/continuation.md). The parameter starts at the robot's value; the start is a state "
      "(--x0 --u0 --v0 --psi) or the robot's one-impact orbit (--from-orbit).");
  AddRobotOptions(*cmd, opt->robot, false);
  cmd->add_option("--param", opt->param,
                  "the parameter followed: A, c, alpha, T0, e, phi0, or a Fourier coefficient "
                  "a1..a16, b1..b16")
      ->required();
  cmd->add_option("--from", opt->continuation.from, "lower end of the range")->required();
  cmd->add_option("--to", opt->continuation.to, "upper end of the range")->required();
  opt->state_options[0] =
      cmd->add_option("--x0", opt->start.x, "start: position of the inner body");
  opt->state_options[1] = cmd->add_option("--u0", opt->start.u, "start: relative velocity");
  opt->state_options[2] = cmd->add_option("--v0", opt->start.v, "start: capsule velocity");
  opt->state_options[3] = cmd->add_option("--psi", opt->start.psi,
                                          "start: forcing phase (F = A sin(psi + phi0) + c there)")
                              ->type_name(kPhase);
  cmd->add_flag("--from-orbit", opt->from_orbit,
                "start on the robot's valid one-impact orbit with the smallest spectral radius "
                "(capsubot orbits), right after its impact");
  cmd->add_flag("--switch", opt->switch_branch,
                "also follow the period-2p branch born at the first located period doubling "
                "(predictor along the eigenvector of the multiplier -1, shooting with period 2p)");
  cmd->add_option("--max-points", opt->continuation.max_points,
                  "points of the branch, both directions together")
      ->capture_default_str();
  cmd->add_option("--initial-step", opt->continuation.initial_step, "first arclength step")
      ->capture_default_str();
  cmd->add_option("--min-step", opt->continuation.min_step,
                  "smallest arclength step: a failure there ends the branch (lost)")
      ->capture_default_str();
  cmd->add_option("--max-step", opt->continuation.max_step, "largest arclength step")
      ->capture_default_str();
  cmd->add_option("--max-period", opt->continuation.shooting.max_period,
                  "largest period searched at the start, in forcing periods")
      ->capture_default_str();
  cmd->add_option("--step", opt->continuation.shooting.step,
                  "step of the central finite differences of the Jacobians")
      ->capture_default_str();
  cmd->add_option("--chatter-velocity", opt->continuation.shooting.chatter_velocity,
                  "the simulator's chatter cut-off (omega L)")
      ->capture_default_str();
  cmd->add_option("-o,--output", opt->output,
                  "CSV of the branch: parameter, x, u, v, psi, period, impacts_right, "
                  "impacts_left, mean_velocity, spectral_radius, muK_re, muK_im, stable, label")
      ->type_name("FILE");
  cmd->add_flag("--json", opt->json,
                "print one JSON object: parameter, status, ends, points, special_points, "
                "provenance");
  SetExamples(*cmd,
              {{"a stable one-impact gait followed in alpha: born in a period doubling, "
                "fastest at alpha = 0.2399, ended by a fold at 0.29035",
                "continue --A 0.05 --c 0.02 --phi0 -2.842 --T0 0.1 --e 0.5 "
                "--alpha 0.2792869076315278 --from-orbit --param alpha --from 0.2 --to 0.3"}});
  return {
      cmd,
      [opt, cmd] { return RunNamingFlags(ContinueFlagNames(), [&] { return Run(*opt, *cmd); }); },
      {}};
}

}  // namespace capsubot::app
