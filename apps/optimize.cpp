// capsubot optimize: the fastest gait (docs/model.md sections 7, 12, 13). Without --problem it
// runs the main job: the paper's problem P1 at c = A = T0/2, the fastest robust one-impact gait
// (P2, spectral radius <= 0.9) checked from rest, the fastest motion from rest (reach), which to
// build, and results/optimum.json. Every reported gait carries its check from rest.

#include "capsubot/optimize.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "capsubot/io.hpp"
#include "commands.hpp"
#include "from_rest_report.hpp"
#include "report.hpp"

namespace capsubot::app {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr int kForceCsvRows = 1001;

struct OptimizeCliOptions {
  std::string problem;  // "", phase, forcing, fourier
  double A = kNaN;      // NaN: not given
  double c = kNaN;
  CLI::Option* A_option = nullptr;
  CLI::Option* c_option = nullptr;
  Params params;
  double bound = kNaN;  // NaN: T0
  CLI::Option* bound_option = nullptr;
  int harmonics = 3;
  std::string global_algorithm = kMultistart;
  std::string local_algorithm = "LN_COBYLA";
  int starts = 0;  // used only when given: else the problem's default
  CLI::Option* starts_option = nullptr;
  int global_evaluations = ForcingDesignOptions{}.global_evaluations;
  int hops = ForcingDesignOptions{}.hops;
  double rho_max = kNaN;  // NaN: no stability requirement
  CLI::Option* stable_option = nullptr;
  bool json = false;
  std::string output = "results/optimum.json";
  CLI::Option* output_option = nullptr;
  std::string force_csv;
  FromRestCliOptions from_rest;  // the from-rest check of every gait, the reach search
  double alpha = kNaN;           // reach: a fixed mass ratio (NaN: free)
  std::string from_rest_csv;     // main job: speeds promised and reached, for the figure
};

// The robust gait of the main job: largest multiplier modulus at most this (docs/model.md
// section 12) unless --stable says otherwise.
constexpr double kRobustRhoMax = 0.9;

std::string Num(double v, int digits = 6) {
  return std::isnan(v) ? "-" : fmt::format("{:.{}g}", v, digits);
}

std::string Join(const std::vector<std::string>& items, const char* none = "none") {
  std::string s;
  for (const auto& i : items) s += (s.empty() ? "" : ", ") + i;
  return s.empty() ? none : s;
}

// The JSON object of one optimisation result (keys of issue 4, item 5): the optimum's orbit
// as `solve --json` shows it, with the optimiser's status in place of the orbit's.
nlohmann::json ResultJson(const OptimizeResult& r, const char* problem) {
  const Forcing& f = r.solution.orbit.forcing;
  nlohmann::json j = SolutionJson(r.solution);
  j["problem"] = problem;
  j["status"] = OptimizeStatusName(r.status);
  j["message"] = r.message;
  j["active_constraints"] = r.active_constraints;
  j["evaluations"] = r.evaluations;
  j["algorithm"] = r.algorithm;
  if (!std::isnan(r.spectral_radius)) {
    j["spectral_radius"] = r.spectral_radius;
    j["stable"] = r.spectral_radius < 1.0;
  }
  if (!f.harmonic()) {
    j["coefficients"] = {{"c", f.mean()}, {"cos", j["cos"]}, {"sin", j["sin"]}};
  }
  return j;
}

void WriteJson(const nlohmann::json& j, const std::string& path) {
  AtomicFile file(path, "--output");
  file.stream() << j.dump(2) << '\n';
  file.Commit();
}

void WriteForceCsv(const Forcing& f, const std::string& path) {
  AtomicFile file(path, "--force-csv");
  auto& out = file.stream();
  out << "phi,F\n";  // phi = 0 is the impact
  for (int i = 0; i < kForceCsvRows; ++i) {
    const double phi = kTau * i / (kForceCsvRows - 1);
    out << FormatNumber(phi) << ',' << FormatNumber(f.F(phi)) << '\n';
  }
  file.Commit();
}

// What an active constraint means for the gait.
const char* BindingInPlainTerms(const std::string& name) {
  namespace n = constraint_names;
  if (name == n::kLeftWall) return "the inner body just reaches the left wall (x_min = margin)";
  if (name == n::kRightWall) return "it just grazes the right wall before the impact";
  if (name == n::kStick) return "the force reaches the friction bound while the capsule rests";
  if (name == n::kForceBound) return "the force uses its whole bound";
  if (name == n::kStability) return "the gait sits on the stability limit";
  if (name == n::kMassRatioLow || name == n::kMassRatioHigh) return "alpha at its limit";
  return "";
}

// A gait in plain terms, indented.
std::string GaitText(const OptimizeResult& r) {
  const Orbit& o = r.solution.orbit;
  const Validity& v = r.solution.validity;
  std::string t;
  t += fmt::format("    force            {}\n", ForceFormula(o.forcing));
  t += fmt::format("    inner mass ratio alpha = m2/(m1+m2) = {}\n", Num(o.alpha, 5));
  t += fmt::format(
      "    speed            I = {} shell lengths per period (mean velocity {} "
      "omega L)\n",
      Num(o.I, 6), Num(o.v_mean, 5));
  t += fmt::format(
      "    impact           u = {} omega L, capsule kick v+ = {} omega L, slides "
      "until phi1 = {} rad\n",
      Num(o.u, 5), Num(o.v_plus, 5), Num(o.phi1, 5));
  t += fmt::format("    inner body       x from {} to {} (walls at 0 and 1)\n", Num(v.x_min, 4),
                   std::isnan(v.x_max) ? "1 (at the impact)" : Num(v.x_max, 6));
  t += fmt::format("    binding          {}\n", Join(r.active_constraints));
  for (const auto& name : r.active_constraints) {
    const char* plain = BindingInPlainTerms(name);
    if (*plain != '\0') t += fmt::format("                     - {}\n", plain);
  }
  if (!std::isnan(r.spectral_radius)) {
    const double rho = r.spectral_radius;
    // The stability constraint often binds: rho = 1 up to the optimiser's tolerance.
    const bool boundary = std::abs(rho - 1.0) <= 1e-6;
    t += fmt::format("    stability        spectral radius {} -> {}\n", Num(rho, 4),
                     boundary    ? "on the stability boundary: the limit of the stable gaits "
                                   "(use --stable 0.95 for a margin)"
                     : rho < 1.0 ? "stable: a real robot settles on this gait"
                                 : "unstable: a real robot would drift away from this gait");
  }
  t += fmt::format("    solver           {} ({} evaluations, status {})\n", r.algorithm,
                   r.evaluations, OptimizeStatusName(r.status));
  return t;
}

ForcingDesignOptions DesignOptions(const OptimizeCliOptions& opt, bool stable) {
  ForcingDesignOptions d;
  d.force_bound = opt.bound;
  d.global_algorithm = opt.global_algorithm;
  d.local_algorithm = opt.local_algorithm;
  if (opt.starts_option->count() > 0) d.starts = opt.starts;
  d.global_evaluations = opt.global_evaluations;
  d.hops = opt.hops;
  d.stable = stable;
  if (stable) d.rho_max = opt.rho_max;
  return d;
}

// Which gait to build, in plain words: the reach winner when it beats the robust one-impact
// gait from rest, else the robust gait.
std::string Advice(const OptimizeResult& robust, const ReachResult& reach) {
  const GaitFromRest& fr = reach.seed.from_rest;
  std::string t = "\nWhich to build:\n";
  if (std::isnan(reach.mean_velocity)) {
    return t + "  no motion from rest could be checked: see the messages above.\n";
  }
  const Attractor& top = reach.attractors.attractors.front();
  const std::string odds = top.fraction == 1.0
                               ? std::string("every start from rest ends in it")
                               : fmt::format(
                                     "{:.0f} % of the starts from rest end in its most "
                                     "common motion",
                                     100.0 * top.fraction);
  if (reach.seed_won) {
    return t + fmt::format(
                   "  the robust one-impact gait (2): it is also the fastest motion found from "
                   "rest,\n  {} omega L on average over the starts; {}.\n",
                   Num(reach.mean_velocity, 4), fr.summary);
  }
  t += fmt::format(
      "  the motion of 3 (A = {}, c = {}, alpha = {}): from rest the robot moves at {} omega L\n"
      "  on average over the starts; {}.\n",
      Num(reach.forcing.amplitude(), 4), Num(reach.forcing.mean(), 4), Num(reach.alpha, 4),
      Num(reach.mean_velocity, 4), odds);
  if (!reach.robust_to_settings) {
    t += "  Caution: under other numerical settings (see \"settings\" above) its starts hit the\n"
         "  work bound or its mean velocity moves by more than 1 %: check it with a finer\n"
         "  simulation before building.\n";
  }
  if (robust.found() && fr.checked) {
    t += fmt::format(
        "  The robust one-impact gait (2) promises {} omega L, but from rest the robot averages\n"
        "  {} omega L with it ({} of {} starts end on it).\n",
        Num(robust.solution.orbit.v_mean, 4), Num(fr.attractors.mean_velocity, 4), fr.reached,
        fr.attractors.starts);
  }
  return t;
}

int RunMainJob(const OptimizeCliOptions& opt) {
  const Params& p = opt.params;
  const double rho_max = std::isnan(opt.rho_max) ? kRobustRhoMax : opt.rho_max;
  OptimizeCliOptions stable_opt = opt;
  stable_opt.rho_max = rho_max;
  // 1. The paper's problem: c = A = T0/2, best phase.
  const OptimizeResult paper =
      OptimizePhase(Forcing::Harmonic(p.T0 / 2.0, p.T0 / 2.0, 0.0), p, PhaseOptions{});
  // 2. The fastest robust one-impact gait, A + c <= bound; checked from rest inside 3.
  // Robust margins (clearance in units of the stroke, stick margin) belong to this design as
  // soon as Params carries them; until then: spectral radius <= rho_max, clearance --margin.
  const OptimizeResult robust = OptimizeForcing(p, DesignOptions(stable_opt, true));
  // 3. The fastest motion from rest, seeded with the robust gait.
  const ReachResult reach =
      OptimizeReach(p, robust, opt.from_rest.Reach(opt.bound, ReachOptions::kNaN));
  const double bound = std::isnan(opt.bound) ? p.T0 : opt.bound;

  nlohmann::json j;
  j["T0"] = p.T0;
  j["e"] = p.e;
  j["margin"] = p.margin;
  j["force_bound"] = bound;
  j["rho_max"] = rho_max;
  j["paper"] = ResultJson(paper, "phase");
  j["paper"]["note"] = "P1: F = A sin(phi + phi0) + c with c = A = T0/2, best phi0";
  j["robust"] = ResultJson(robust, "forcing");
  j["robust"]["note"] = "P2 restricted to spectral radius <= rho_max, checked from rest";
  j["robust"]["from_rest"] = FromRestJson(reach.seed.from_rest);
  j["reach"] = ReachJson(reach);
  WriteJson(j, opt.output);
  if (!opt.force_csv.empty()) WriteForceCsv(robust.solution.orbit.forcing, opt.force_csv);
  if (!opt.from_rest_csv.empty()) {
    WriteFromRestCsv(opt.from_rest_csv, "--from-rest-csv", robust, reach);
  }
  if (opt.json) {
    fmt::print("{}\n", j.dump());
    return 0;
  }

  std::string t;
  t += fmt::format(
      "capsubot optimize: the fastest gait of the capsule robot that the robot reaches "
      "(docs/model.md sections 7, 12, 13)\n"
      "model: T0 = {:g} (friction bound mu g/(omega^2 L)), e = {:g} (restitution), clearance "
      "margin {:g}\n"
      "units: I = capsule displacement per forcing period in shell lengths L; velocity in "
      "omega L\n"
      "(T0 = 1, e = 1 are the paper's values; change them with --T0, --e, --margin)\n\n",
      p.T0, p.e, p.margin);
  t += fmt::format(
      "1. The paper's problem (P1): force F = A sin(phi + phi0) + c with c = A = T0/2 = {:g},\n"
      "   best impact phase phi0 over the whole circle.\n",
      p.T0 / 2.0);
  if (paper.found()) {
    t += "   Result: a valid gait exists.\n" + GaitText(paper);
  } else {
    const Validity& v = paper.solution.validity;
    t += fmt::format(
        "   Result: NO valid gait (status {}). For every phi0 the constructed orbit breaks a\n"
        "   condition of docs/model.md section 5. Nearest to valid: phi0 = {}, I = {}, violating\n"
        "   {}.\n",
        OptimizeStatusName(paper.status), Num(paper.solution.orbit.forcing.phi0(), 6),
        Num(paper.solution.orbit.I, 6), Join(v.ViolationNames()));
    if (v.violations == (1U << static_cast<unsigned>(Condition::kLeftWall))) {
      // Only the left wall fails. Scaling A, c, T0 by k scales 1 - x by k and leaves the
      // other conditions unchanged (docs/model.md section 6): the gait fits once k (1 - x_min)
      // <= 1.
      t += fmt::format(
          "   The inner body would have to reach x = {} (the shell spans 0..1): the force is\n"
          "   too strong for this shell. Orbit sizes scale with T0 (docs/model.md section 6): "
          "this\n"
          "   gait would fit for T0 <= {} (a shorter shell or a faster motor).\n",
          Num(v.x_min, 4), Num(p.T0 / (1.0 - v.x_min), 4));
    }
  }
  t += fmt::format(
      "\n2. The fastest robust one-impact gait (P2: A, c, phi0 free, A + c <= {:g}, spectral\n"
      "   radius <= {:g}), checked from rest on {} starts:\n",
      bound, rho_max, reach.seed.from_rest.attractors.starts);
  t += robust.found() ? GaitText(robust) + FromRestText(reach.seed.from_rest)
                      : fmt::format("   Result: none found ({})\n", robust.message);
  t += fmt::format(
      "\n3. The fastest motion from rest (any number of impacts, A + c <= {:g}, alpha free),\n"
      "   simulated from every start:\n",
      bound);
  t += ReachText(reach);
  t += Advice(robust, reach);
  t += fmt::format("\nwritten: {}\n", opt.output);
  fmt::print("{}", t);
  return 0;
}

// --problem reach: the fastest motion from rest, seeded with the robust gait.
int RunReach(const OptimizeCliOptions& opt) {
  OptimizeCliOptions stable_opt = opt;
  stable_opt.rho_max = std::isnan(opt.rho_max) ? kRobustRhoMax : opt.rho_max;
  const OptimizeResult robust = OptimizeForcing(opt.params, DesignOptions(stable_opt, true));
  const ReachResult reach =
      OptimizeReach(opt.params, robust, opt.from_rest.Reach(opt.bound, opt.alpha));
  nlohmann::json j = ReachJson(reach);
  if (opt.output_option->count() > 0) WriteJson(j, opt.output);
  if (opt.json) {
    fmt::print("{}\n", j.dump());
    return 0;
  }
  fmt::print(
      "capsubot optimize --problem reach: T0 = {:g}, e = {:g}\n  status           {}\n  "
      "{}\n{}",
      opt.params.T0, opt.params.e, OptimizeStatusName(reach.status), reach.message,
      ReachText(reach));
  return 0;
}

int RunProblem(const OptimizeCliOptions& opt) {
  const Params& p = opt.params;
  const bool stable = !std::isnan(opt.rho_max);
  OptimizeResult r;
  if (opt.problem == "phase") {
    if (std::isnan(opt.A) || std::isnan(opt.c)) {
      throw std::invalid_argument(
          "--problem phase needs the force shape: give --A and --c (F = A sin(phi + phi0) + c)");
    }
    PhaseOptions po;
    po.stable = stable;
    if (stable) po.rho_max = opt.rho_max;
    r = OptimizePhase(Forcing::Harmonic(opt.A, opt.c, 0.0), p, po);
  } else if (opt.problem == "forcing") {
    r = OptimizeForcing(p, DesignOptions(opt, stable));
  } else {  // fourier (CLI11 checks the name)
    FourierOptions fo;
    fo.harmonics = opt.harmonics;
    fo.force_bound = opt.bound;
    fo.global_algorithm = opt.global_algorithm;
    fo.local_algorithm = opt.local_algorithm;
    if (opt.starts_option->count() > 0) fo.starts = opt.starts;
    fo.global_evaluations = opt.global_evaluations;
    fo.stable = stable;
    if (stable) fo.rho_max = opt.rho_max;
    r = OptimizeFourier(p, fo);
  }
  const GaitFromRest from_rest = CheckGaitFromRest(r.solution.orbit, p, opt.from_rest.Check());
  nlohmann::json j = ResultJson(r, opt.problem.c_str());
  j["from_rest"] = FromRestJson(from_rest);
  j["T0"] = p.T0;
  j["e"] = p.e;
  j["margin"] = p.margin;
  if (opt.problem == "fourier") {
    j["baseline_I"] = r.baseline_I;
    j["gain"] = r.found() ? r.solution.orbit.I / r.baseline_I - 1.0 : kNaN;
  }
  if (!opt.force_csv.empty()) WriteForceCsv(r.solution.orbit.forcing, opt.force_csv);
  if (opt.output_option->count() > 0) WriteJson(j, opt.output);
  if (opt.json) {
    fmt::print("{}\n", j.dump());
    return 0;
  }
  std::string t;
  t += fmt::format("capsubot optimize --problem {}: T0 = {:g}, e = {:g}, margin = {:g}{}\n",
                   opt.problem, p.T0, p.e, p.margin,
                   stable ? fmt::format(", spectral radius <= {:g}", opt.rho_max) : "");
  t += fmt::format("  status           {}\n  {}\n", OptimizeStatusName(r.status), r.message);
  t += GaitText(r) + FromRestText(from_rest);
  if (opt.problem == "fourier") {
    t += fmt::format(
        "    gain over P2     {} (harmonic optimum I = {})\n",
        r.found() ? fmt::format("{:+.4g}%", 100.0 * (r.solution.orbit.I / r.baseline_I - 1.0))
                  : std::string("-"),
        Num(r.baseline_I, 8));
  }
  fmt::print("{}", t);
  return 0;
}

// A value given on the command line must be admissible itself: NaN (the library's "use T0"
// for the bound, the CLI's "not given" for A and c) or a count below 1 is not a default.
void RequireGiven(const CLI::Option* option, bool ok, const std::string& value, const char* rule) {
  if (option->count() > 0 && !ok) {
    throw std::invalid_argument(
        fmt::format("{} = {} is invalid: expected {}", option->get_name(), value, rule));
  }
}

int Run(const OptimizeCliOptions& opt) {
  RequireGiven(opt.A_option, std::isfinite(opt.A) && opt.A >= 0.0, fmt::format("{}", opt.A),
               "a finite amplitude A >= 0");
  RequireGiven(opt.c_option, std::isfinite(opt.c), fmt::format("{}", opt.c),
               "a finite mean force c");
  RequireGiven(opt.bound_option, std::isfinite(opt.bound) && opt.bound > 0.0,
               fmt::format("{}", opt.bound), "a finite bound > 0 (at most T0)");
  RequireGiven(opt.starts_option, opt.starts >= 1, fmt::format("{}", opt.starts), "starts >= 1");
  opt.params.Validate();
  if (opt.stable_option->count() > 0 && !(std::isfinite(opt.rho_max) && opt.rho_max > 0.0)) {
    throw std::invalid_argument(fmt::format(
        "--stable = {} is invalid: expected a spectral radius bound rho_max > 0", opt.rho_max));
  }
  if (opt.problem.empty()) return RunMainJob(opt);
  return opt.problem == "reach" ? RunReach(opt) : RunProblem(opt);
}

}  // namespace

Command AddOptimizeCommand(CLI::App& app) {
  auto opt = std::make_shared<OptimizeCliOptions>();
  CLI::App* cmd = app.add_subcommand(
      "optimize",
      "The fastest gait (docs/model.md section 7). Without --problem: the main job, run from the "
      "repository root: the paper's problem (best phase at c = A = T0/2), the fastest robust "
      "one-impact gait with A + c <= T0 checked from rest, and the fastest motion from rest; "
      "prints a summary and which to build, and writes "
      "--output. With --problem: one problem. Exit status 0 whenever the computation ran, "
      "valid gait found or not.");
  cmd->add_option("--problem", opt->problem,
                  "phase (P1: best phi0 for given --A, --c), forcing (P2: best A, c, phi0 with "
                  "A + c <= --bound) or fourier (P3: best K-harmonic force with max |F| <= "
                  "--bound) or reach (the fastest motion from rest: A, c, alpha with A + c <= "
                  "--bound, simulated, seeded with the robust P2 gait); default: the main job")
      ->check(CLI::IsMember({"phase", "forcing", "fourier", "reach"}));
  opt->A_option =
      cmd->add_option("--A", opt->A,
                      "amplitude A >= 0 of F = A sin(phi + phi0) + c for --problem phase, in units "
                      "of (m1+m2) omega^2 L");
  opt->c_option =
      cmd->add_option("--c", opt->c, "mean force c > 0 of F for --problem phase (same unit)");
  AddParamsOptions(*cmd, opt->params);
  AddFromRestOptions(*cmd, opt->from_rest, true);
  cmd->add_option("--from-rest-csv", opt->from_rest_csv,
                  "main job: write the robust gait's promised mean velocity and the attractors "
                  "reached from rest (robust gait and fastest motion from rest) to this CSV file "
                  "(columns gait,row,mean_velocity,fraction,period,impacts_right,impacts_left,"
                  "one_impact_orbit)");
  cmd->add_option("--alpha", opt->alpha,
                  "reach: a fixed mass ratio 0 < alpha < 1 (default: alpha is optimised too)");
  opt->bound_option =
      cmd->add_option("--bound", opt->bound,
                      "force bound for forcing/fourier: A + c (max |F|) <= bound, 0 < bound <= T0, "
                      "same unit as A (default: T0)");
  cmd->add_option("--harmonics", opt->harmonics, "number K of harmonics of the Fourier force")
      ->capture_default_str();
  cmd->add_option("--global-algorithm", opt->global_algorithm,
                  "global stage of forcing/fourier: multistart (scan + local polishes) or an "
                  "NLopt algorithm: GN_ISRES, GN_ORIG_DIRECT, GN_ORIG_DIRECT_L, GN_AGS")
      ->capture_default_str();
  cmd->add_option("--local-algorithm", opt->local_algorithm,
                  "local constrained polish, NLopt name: LN_COBYLA, LD_SLSQP, LD_MMA, LD_CCSAQ "
                  "(LD_*: gradients by central differences)")
      ->capture_default_str();
  cmd->add_option("--global-evaluations", opt->global_evaluations,
                  "evaluation budget of an NLopt global algorithm (not used by multistart)")
      ->capture_default_str();
  cmd->add_option("--hops", opt->hops,
                  "forcing: basin-hopping restarts from random perturbations of the best point "
                  "after the starts")
      ->capture_default_str();
  opt->starts_option = cmd->add_option("--starts", opt->starts,
                                       "number of local polishes of the multistart, >= 1 "
                                       "(default: 10 for forcing, 20 for fourier)");
  opt->stable_option =
      cmd->add_option("--stable", opt->rho_max,
                      "require a stable orbit: spectral radius of the impact map (docs/model.md "
                      "section 8) <= rho_max; the value is optional (--stable alone means "
                      "rho_max = 1). The main job always reports both")
          ->expected(0, 1)
          ->default_str("1");
  cmd->add_flag("--json", opt->json,
                "print one JSON object: status, I, v_mean, A, c, phi0, phi1, alpha, u, v_plus, "
                "x_min, x_max, active_constraints, evaluations, algorithm (+ coefficients for "
                "fourier, spectral_radius when the orbit exists; null where a quantity does not "
                "exist); the main job prints the object it writes to --output");
  opt->output_option = cmd->add_option(
      "--output", opt->output,
      "JSON file written atomically: always by the main job (a path relative to the working "
      "directory), by --problem only when given");
  opt->output_option->capture_default_str();
  cmd->add_option("--force-csv", opt->force_csv,
                  "write the optimal force F(phi) over one period (phi = 0 at the impact, "
                  "columns phi,F) to this CSV file (main job: the robust gait's force)");
  return {cmd, [opt] { return Run(*opt); }};
}

}  // namespace capsubot::app
