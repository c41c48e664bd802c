// capsubot orbits: every one-impact orbit of a robot whose mass ratio is fixed (docs/model.md
// section 8), with validity, mean velocity and stability.

#include <fmt/format.h>

#include <cstdint>
#include <memory>

#include "capsubot/orbit/robot_orbits.hpp"
#include "capsubot/orbit/stability.hpp"
#include "commands.hpp"
#include "help_format.hpp"
#include "provenance.hpp"
#include "report.hpp"

namespace capsubot::app {
namespace {

struct OrbitsOptions {
  ForcingOptions forcing;
  Params params;
  double alpha = std::numeric_limits<double>::quiet_NaN();
  std::int64_t max_evaluations = kRobotOrbitsMaxEvaluations;
  bool json = false;
};

// Said when the search hit its work bound: the list is then not known to be complete.
constexpr const char* kIncompleteNote =
    "the search stopped at its work bound (--max-evaluations): orbits may be missing";

int Run(const OrbitsOptions& opt, const CLI::App& cmd) {
  opt.params.Validate();
  const Forcing forcing = opt.forcing.Build(false);
  bool complete = true;
  const std::vector<Solution> found =
      FindRobotOrbits(forcing, opt.params, opt.alpha, &complete, opt.max_evaluations);
  if (opt.json) {
    nlohmann::json j = {{"orbits", json::RobotOrbitsJson(found, complete)}};
    AddProvenanceJson(j, cmd);
    fmt::print("{}\n", j.dump());
    if (!complete) fmt::print(stderr, "capsubot orbits: note: {}\n", kIncompleteNote);
    return 0;
  }
  std::string t = fmt::format("one-impact orbits of the robot with alpha = {}\n", Num(opt.alpha));
  t += fmt::format("  force   {}   (phi0 = impact phase, solved for)\n",
                   ForceFormula(forcing.WithPhase(0.0)));
  t += fmt::format("  model   T0 = {:g}, e = {:g}, margin = {:g}\n", opt.params.T0, opt.params.e,
                   opt.params.margin);
  t += fmt::format("  {} orbit(s)\n", found.size());
  if (!complete) t += fmt::format("  note: {}\n", kIncompleteNote);
  if (!found.empty()) {
    t += fmt::format("  {:>14}  {:>10}  {:>14}  {:>15}  {:>8}  {}\n", "phi0", "phi1", "v_mean",
                     "spectral_radius", "stable", "valid");
  }
  for (const Solution& s : found) {
    const Stability st = ComputeStability(s.orbit);
    std::string valid = "yes";
    if (!s.validity.valid()) {
      valid = "no:";
      for (const auto& n : s.validity.ViolationNames()) valid += " " + n;
    }
    t += fmt::format("  {:>14}  {:>10}  {:>14}  {:>15}  {:>8}  {}\n",
                     NumFixed(s.orbit.forcing.phi0(), 10), NumFixed(s.orbit.phi1, 6),
                     Num(s.orbit.v_mean, 8), Num(st.spectral_radius, 6), st.stable ? "yes" : "no",
                     valid);
  }
  fmt::print("{}", t);
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
  AddParamsOptions(*cmd, opt->params);
  cmd->add_option("--alpha", opt->alpha, "mass ratio m2/(m1+m2) of the robot, 0 < alpha < 1")
      ->required();
  Bounded(cmd->add_option("--max-evaluations", opt->max_evaluations,
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
  SetExamples(*cmd, {{"every one-impact orbit of the robot with mass ratio 0.28, none "
                      "missed",
                      "orbits --A 0.05 --c 0.02 --T0 0.1 --e 0.5 --alpha 0.28"}});
  return {cmd, [opt, cmd] { return Run(*opt, *cmd); }, {}};
}

}  // namespace capsubot::app
