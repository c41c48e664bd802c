// capsubot optimize: the fastest gait (docs/model.md section 7) with the margins of a robust
// gait (section 12). Without --problem it runs the main job: the paper's problem P1 at
// c = A = T0/2, the fastest robust gait (P2 with the margins), and for comparison the exact
// optima without margins (valid; stable). Prints a summary (or --json); -o writes the JSON.

#include "capsubot/optimize.hpp"

#include <fmt/format.h>

#include <array>
#include <cmath>
#include <limits>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "capsubot/io.hpp"
#include "capsubot/scaling.hpp"
#include "commands.hpp"
#include "report.hpp"

namespace capsubot::app {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kForceCsvRows = 1001;
// The robust defaults of the command (docs/model.md section 12); the library's are 0 and inf.
constexpr double kDefaultMarginStroke = 0.02;
constexpr double kDefaultStickMargin = 0.02;
constexpr double kDefaultRhoMax = 0.9;

// P2's library defaults (one instance: the defaults of the options below).
const ForcingDesignOptions& P2Defaults() {
  static const ForcingDesignOptions defaults;
  return defaults;
}

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
  int global_evaluations = P2Defaults().global_evaluations;
  int hops = P2Defaults().hops;
  double rho_max = kDefaultRhoMax;
  double max_time = P2Defaults().max_time;
  bool json = false;
  std::string output;  // empty: no file
  std::string force_csv;
  CLI::App* cmd = nullptr;
};

// The runs that use an option: "" is the main job (no --problem), else a problem name.
struct OptionUse {
  const char* option;
  std::array<const char*, 3> runs;
};
const OptionUse kOptionUses[] = {
    {"--A", {"phase"}},
    {"--c", {"phase"}},
    {"--harmonics", {"fourier"}},
    {"--hops", {"", "forcing"}},
    {"--starts", {"", "forcing", "fourier"}},
    {"--bound", {"", "forcing", "fourier"}},
    {"--global-algorithm", {"", "forcing", "fourier"}},
    {"--local-algorithm", {"", "forcing", "fourier"}},
    {"--global-evaluations", {"", "forcing", "fourier"}},
};

std::string RunName(const std::string& problem) {
  return problem.empty() ? "the main job (no --problem)" : "--problem " + problem;
}

// An option the chosen run does not use would be silently ignored: refuse it, naming both.
void RejectUnusedOptions(const OptimizeCliOptions& opt) {
  for (const OptionUse& use : kOptionUses) {
    const CLI::Option* option = opt.cmd->get_option_no_throw(use.option);
    if (option == nullptr || option->count() == 0) continue;
    std::string expected;
    bool used = false;
    for (const char* run : use.runs) {
      if (run == nullptr) break;
      used = used || opt.problem == run;
      expected += (expected.empty() ? "" : " or ") + RunName(run);
    }
    if (!used) {
      throw std::invalid_argument(fmt::format("{} conflicts with {}: expected {} only with {}",
                                              use.option, RunName(opt.problem), use.option,
                                              expected));
    }
  }
  const CLI::Option* evaluations = opt.cmd->get_option_no_throw("--global-evaluations");
  if (evaluations != nullptr && evaluations->count() > 0 && opt.global_algorithm == kMultistart) {
    throw std::invalid_argument(
        "--global-evaluations conflicts with --global-algorithm multistart: expected an NLopt "
        "global algorithm with it (multistart has no evaluation budget)");
  }
}

std::string Join(const std::vector<std::string>& items, const char* none = "none") {
  std::string s;
  for (const auto& i : items) s += (s.empty() ? "" : ", ") + i;
  return s.empty() ? none : s;
}

std::vector<std::string> BindingNames(const OptimizeResult& r) {
  std::vector<std::string> names;
  for (Margin m : r.binding) names.emplace_back(MarginName(m));
  return names;
}

// The JSON object of one optimisation result: the optimum's orbit as `solve --json` shows it,
// with the optimiser's status in place of the orbit's.
nlohmann::json ResultJson(const OptimizeResult& r, const char* problem) {
  const Forcing& f = r.solution.orbit.forcing;
  nlohmann::json j = SolutionJson(r.solution);
  j["problem"] = problem;
  j["status"] = OptimizeStatusName(r.status);
  j["message"] = r.message;
  j["active_constraints"] = r.active_constraints;
  j["binding"] = BindingNames(r);
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

// The model and the requirements every result of a run shares (rho_max null: none).
void AddRequirementsJson(nlohmann::json& j, const Params& p, double rho_max) {
  j["T0"] = p.T0;
  j["e"] = p.e;
  j["margin"] = p.margin;
  j["margin_stroke"] = p.margin_stroke;
  j["stick_margin"] = p.stick_margin;
  j["rho_max"] = rho_max;  // nlohmann::json writes infinity as null
}

void WriteJson(const nlohmann::json& j, const std::string& path) {
  AtomicFile file(path, "-o");
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

// What an active constraint or binding margin means for the gait.
const char* InPlainTerms(const std::string& name) {
  if (name == ConditionName(Condition::kLeftWall))
    return "the inner body just reaches the left wall";
  if (name == ConditionName(Condition::kRightWall)) {
    return "it just grazes the right wall before the impact";
  }
  if (name == ConditionName(Condition::kClearance)) {
    return "it comes exactly the required clearance close to a wall";
  }
  if (name == ConditionName(Condition::kStick)) {
    return "the force reaches its limit while the capsule rests";
  }
  if (name == ConditionName(Condition::kMassRatio)) return "alpha at its limit";
  if (name == kForceBoundName) return "the force uses its whole bound";
  if (name == MarginName(Margin::kRhoMax)) return "the spectral radius sits on rho_max";
  return "";
}

// A gait in plain terms, indented.
std::string GaitText(const OptimizeResult& r, double rho_max) {
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
  t += fmt::format("    inner body       x from {} to {} (walls at 0 and 1){}\n", Num(v.x_min, 4),
                   std::isnan(v.x_max) ? "1 (at the impact)" : Num(v.x_max, 6),
                   v.clearance > 0.0 ? fmt::format(", clearance {}", Num(v.clearance, 4)) : "");
  t += fmt::format("    active           {}\n", Join(r.active_constraints));
  for (const auto& name : r.active_constraints) {
    const char* plain = InPlainTerms(name);
    if (*plain != '\0') t += fmt::format("                     - {}\n", plain);
  }
  if (r.found()) t += fmt::format("    margins binding  {}\n", Join(BindingNames(r)));
  if (!std::isnan(r.spectral_radius)) {
    const double rho = r.spectral_radius;
    // The stability requirement often binds: rho = rho_max up to the optimiser's tolerance.
    const bool boundary = std::isfinite(rho_max) && std::abs(rho - rho_max) <= 1e-6;
    t += fmt::format("    stability        spectral radius {} -> {}\n", Num(rho, 4),
                     boundary ? fmt::format("on the required bound rho_max = {:g}", rho_max)
                     : rho < 1.0
                         ? std::string("stable: a real robot settles on this gait")
                         : std::string("unstable: a real robot would drift away from this gait"));
  }
  t += fmt::format("    solver           {} ({} evaluations, status {})\n", r.algorithm,
                   r.evaluations, OptimizeStatusName(r.status));
  return t;
}

// The gait asked for, with P2's default search: what P3 asks and starts from.
ForcingDesignOptions GaitOptions(const OptimizeCliOptions& opt, double rho_max) {
  ForcingDesignOptions d;
  d.force_bound = opt.bound;
  d.local_algorithm = opt.local_algorithm;
  d.rho_max = rho_max;
  d.max_time = opt.max_time;
  return d;
}

// P2: the gait asked for, searched as the command line says.
ForcingDesignOptions DesignOptions(const OptimizeCliOptions& opt, double rho_max) {
  ForcingDesignOptions d = GaitOptions(opt, rho_max);
  d.global_algorithm = opt.global_algorithm;
  if (opt.starts_option->count() > 0) d.starts = opt.starts;
  d.global_evaluations = opt.global_evaluations;
  d.hops = opt.hops;
  return d;
}

PhaseOptions PhaseFor(const OptimizeCliOptions& opt) {
  PhaseOptions po;
  po.rho_max = opt.rho_max;
  po.max_time = opt.max_time;
  return po;
}

void Emit(const nlohmann::json& j, const std::string& text, const OptimizeCliOptions& opt) {
  if (!opt.output.empty()) WriteJson(j, opt.output);
  if (opt.json) {
    fmt::print("{}\n", j.dump());
  } else {
    fmt::print("{}{}", text, opt.output.empty() ? "" : fmt::format("\nwritten: {}\n", opt.output));
  }
}

int RunMainJob(const OptimizeCliOptions& opt) {
  const Params& p = opt.params;
  Params exact = p;  // the exact optima: no margins
  exact.margin = exact.margin_stroke = exact.stick_margin = 0.0;
  // 1. The paper's problem as the paper poses it (valid orbits, no margins): c = A = T0/2,
  // best phase. Its force sits on the friction bound, so any stick margin would exclude it.
  PhaseOptions paper_options = PhaseFor(opt);
  paper_options.rho_max = kInf;
  const OptimizeResult paper =
      OptimizePhase(Forcing::Harmonic(p.T0 / 2.0, p.T0 / 2.0, 0.0), exact, paper_options);
  // 2. The fastest robust gait; 3. the exact optima, valid and stable, for comparison.
  const OptimizeResult robust = OptimizeForcing(p, DesignOptions(opt, opt.rho_max));
  const OptimizeResult fastest = OptimizeForcing(exact, DesignOptions(opt, kInf));
  const OptimizeResult stable = OptimizeForcing(exact, DesignOptions(opt, 1.0));
  const double bound = std::isnan(opt.bound) ? p.T0 : opt.bound;

  nlohmann::json j;
  AddRequirementsJson(j, p, opt.rho_max);
  j["force_bound"] = bound;
  j["paper_phase"] = ResultJson(paper, "phase");
  j["paper_phase"]["note"] =
      "P1: F = A sin(phi + phi0) + c with c = A = T0/2, best phi0 over valid orbits (no margins)";
  j["robust"] = ResultJson(robust, "forcing");
  j["robust"]["note"] =
      "P2: A, c, phi0 free with A + c <= force_bound, the margins and spectral radius <= rho_max";
  j["fastest"] = ResultJson(fastest, "forcing");
  j["fastest"]["note"] = "P2 without margins or stability requirement: grazes the walls";
  j["fastest_stable"] = ResultJson(stable, "forcing");
  j["fastest_stable"]["note"] = "P2 without margins, spectral radius <= 1";
  if (!opt.force_csv.empty()) WriteForceCsv(robust.solution.orbit.forcing, opt.force_csv);

  std::string t;
  t += fmt::format(
      "capsubot optimize: the fastest one-impact gait of the capsule robot (docs/model.md "
      "section 7)\n"
      "model: T0 = {:g} (friction bound mu g/(omega^2 L)), e = {:g} (restitution)\n"
      "robust gait (docs/model.md section 12): clearance >= max(d = {:g}, d_s = {:g} x stroke), "
      "stick margin s = {:g}, spectral radius <= {:g}\n"
      "units: I = capsule displacement per forcing period in shell lengths L; velocity in "
      "omega L\n"
      "(change them with --T0, --e, --margin, --margin-stroke, --stick-margin, --rho-max)\n\n",
      p.T0, p.e, p.margin, p.margin_stroke, p.stick_margin, opt.rho_max);
  t += fmt::format(
      "1. The paper's problem (P1): force F = A sin(phi + phi0) + c with c = A = T0/2 = {:g},\n"
      "   best impact phase phi0 over the whole circle, valid orbits as the paper asks (no\n"
      "   margins: its force reaches the friction bound).\n",
      p.T0 / 2.0);
  if (paper.found()) {
    t += "   Result: a valid gait exists.\n" + GaitText(paper, kInf);
  } else {
    const Validity& v = paper.solution.validity;
    t += fmt::format(
        "   Result: NO valid gait (status {}). For every phi0 the constructed orbit breaks a\n"
        "   condition of docs/model.md section 5. Nearest to valid: phi0 = {}, I = {}, violating\n"
        "   {}.\n",
        OptimizeStatusName(paper.status), Num(paper.solution.orbit.forcing.phi0(), 6),
        Num(paper.solution.orbit.I, 6), Join(v.ViolationNames()));
    if (v.violations == (1U << static_cast<unsigned>(Condition::kLeftWall))) {
      // Scaling A, c, T0 by k scales 1 - x by k and leaves the other conditions unchanged
      // (docs/model.md section 6): the orbit fits once k (1 - x_min) <= 1.
      t += fmt::format(
          "   The inner body would have to reach x = {} (the shell spans 0..1): the force is\n"
          "   too strong for this shell. Orbit sizes scale with T0 (docs/model.md section 6): "
          "this\n"
          "   orbit would fit for T0 <= {} (a shorter shell or a faster motor). At T0 = {:g} a\n"
          "   weaker, differently shaped force is needed:\n",
          Num(v.x_min, 4), Num(LargestFittingT0(paper.solution, p.margin), 4), p.T0);
    }
  }
  t += fmt::format(
      "\n2. The fastest robust gait (P2): A, c and phi0 free, A + c <= {:g}, with the margins\n"
      "   above. This is the gait to build.\n",
      bound);
  t += robust.found() ? GaitText(robust, opt.rho_max)
                      : fmt::format("   Result: none found ({})\n", robust.message);
  t += "\n3. For comparison, the exact optima without margins (they graze the walls: a robot\n"
       "   with slightly different parameters does something else).\n"
       "   The fastest valid gait:\n";
  t += fastest.found() ? GaitText(fastest, kInf)
                       : fmt::format("   Result: none found ({})\n", fastest.message);
  t += "   The fastest stable gait (spectral radius <= 1, docs/model.md section 8):\n";
  t += stable.found() ? GaitText(stable, 1.0)
                      : fmt::format("   Result: none found ({})\n", stable.message);
  if (robust.found() && fastest.found()) {
    t += fmt::format(
        "\nIn short: the fastest robust gait moves {} L per period with inner mass ratio {}\n"
        "({} of the exact, wall-grazing optimum {} L per period; margins binding: {}).\n",
        Num(robust.solution.orbit.I, 5), Num(robust.solution.orbit.alpha, 4),
        fmt::format("{:.1f}%", 100.0 * robust.solution.orbit.I / fastest.solution.orbit.I),
        Num(fastest.solution.orbit.I, 5), Join(BindingNames(robust)));
  }
  Emit(j, t, opt);
  return 0;
}

int RunProblem(const OptimizeCliOptions& opt) {
  const Params& p = opt.params;
  OptimizeResult r;
  if (opt.problem == "phase") {
    if (std::isnan(opt.A) || std::isnan(opt.c)) {
      throw std::invalid_argument(
          "--problem phase needs the force shape: give --A and --c (F = A sin(phi + phi0) + c)");
    }
    r = OptimizePhase(Forcing::Harmonic(opt.A, opt.c, 0.0), p, PhaseFor(opt));
  } else if (opt.problem == "forcing") {
    r = OptimizeForcing(p, DesignOptions(opt, opt.rho_max));
  } else {  // fourier (CLI11 checks the name)
    FourierOptions fo;
    fo.harmonic = GaitOptions(opt, opt.rho_max);
    fo.harmonics = opt.harmonics;
    fo.search.global_algorithm = opt.global_algorithm;
    if (opt.starts_option->count() > 0) fo.search.starts = opt.starts;
    fo.search.global_evaluations = opt.global_evaluations;
    r = OptimizeFourier(p, fo);
  }
  nlohmann::json j = ResultJson(r, opt.problem.c_str());
  AddRequirementsJson(j, p, opt.rho_max);
  if (opt.problem == "fourier") {
    j["baseline_I"] = r.baseline_I;
    j["gain"] = r.found() ? r.solution.orbit.I / r.baseline_I - 1.0 : kNaN;
  }
  if (!opt.force_csv.empty()) WriteForceCsv(r.solution.orbit.forcing, opt.force_csv);
  std::string t;
  t += fmt::format(
      "capsubot optimize --problem {}: T0 = {:g}, e = {:g}, margins d = {:g}, d_s = {:g}, "
      "s = {:g}, spectral radius <= {:g}\n",
      opt.problem, p.T0, p.e, p.margin, p.margin_stroke, p.stick_margin, opt.rho_max);
  t += fmt::format("  status           {}\n  {}\n", OptimizeStatusName(r.status), r.message);
  t += GaitText(r, opt.rho_max);
  if (opt.problem == "fourier") {
    t += fmt::format(
        "    gain over P2     {} (harmonic optimum I = {})\n",
        r.found() ? fmt::format("{:+.4g}%", 100.0 * (r.solution.orbit.I / r.baseline_I - 1.0))
                  : std::string("-"),
        Num(r.baseline_I, 8));
  }
  Emit(j, t, opt);
  return 0;
}

// A value given on the command line must be admissible itself: NaN (the library's "use T0"
// for the bound, the CLI's "not given" for A and c) is not a default.
void RequireGiven(const CLI::Option* option, bool ok, const std::string& value, const char* rule) {
  if (option->count() > 0 && !ok) {
    throw std::invalid_argument(
        fmt::format("{} = {} is invalid: expected {}", option->get_name(), value, rule));
  }
}

int Run(const OptimizeCliOptions& opt) {
  RejectUnusedOptions(opt);
  RequireGiven(opt.A_option, std::isfinite(opt.A) && opt.A >= 0.0, fmt::format("{}", opt.A),
               "a finite amplitude A >= 0");
  RequireGiven(opt.c_option, std::isfinite(opt.c), fmt::format("{}", opt.c),
               "a finite mean force c");
  RequireGiven(opt.bound_option, std::isfinite(opt.bound) && opt.bound > 0.0,
               fmt::format("{}", opt.bound), "a finite bound > 0 (at most T0)");
  // Every size is bounded before any work starts.
  if (opt.starts_option->count() > 0) RequireInRange("--starts", opt.starts, 1, kMaxStarts);
  RequireInRange("--hops", opt.hops, 0, kMaxStarts);
  RequireInRange("--global-evaluations", opt.global_evaluations, 10, kMaxStageEvaluations);
  if (!(opt.rho_max > 0.0)) {
    throw std::invalid_argument(fmt::format(
        "--rho-max = {} is invalid: expected rho_max > 0 (inf: no stability requirement)",
        opt.rho_max));
  }
  if (!(opt.max_time > 0.0)) {
    throw std::invalid_argument(fmt::format(
        "--max-time = {} is invalid: expected a time limit > 0 seconds (inf: none)", opt.max_time));
  }
  opt.params.Validate();
  return opt.problem.empty() ? RunMainJob(opt) : RunProblem(opt);
}

}  // namespace

Command AddOptimizeCommand(CLI::App& app) {
  auto opt = std::make_shared<OptimizeCliOptions>();
  opt->params.margin_stroke = kDefaultMarginStroke;
  opt->params.stick_margin = kDefaultStickMargin;
  CLI::App* cmd = app.add_subcommand(
      "optimize",
      "The fastest gait (docs/model.md section 7) with the margins of a robust gait (section "
      "12). Without --problem: the main job: the paper's problem (best phase at c = A = T0/2), "
      "the fastest robust gait with A + c <= T0, and the exact optima without margins (valid, "
      "stable) for comparison. With --problem: one problem. Prints a summary (or --json); -o "
      "also writes the JSON. Exit status 0 whenever the computation ran, valid gait found or "
      "not.");
  cmd->add_option("--problem", opt->problem,
                  "phase (P1: best phi0 for given --A, --c), forcing (P2: best A, c, phi0 with "
                  "A + c <= --bound) or fourier (P3: best K-harmonic force with max |F| <= "
                  "--bound); default: the main job")
      ->check(CLI::IsMember({"phase", "forcing", "fourier"}));
  opt->A_option =
      cmd->add_option("--A", opt->A,
                      "amplitude A >= 0 of F = A sin(phi + phi0) + c for --problem phase, in units "
                      "of (m1+m2) omega^2 L");
  opt->c_option =
      cmd->add_option("--c", opt->c, "mean force c > 0 of F for --problem phase (same unit)");
  AddParamsOptions(*cmd, opt->params);
  opt->bound_option =
      cmd->add_option("--bound", opt->bound,
                      "force bound for forcing/fourier: A + c (max |F|) <= bound, 0 < bound <= T0, "
                      "same unit as A (default: T0)");
  CLI::Option* rho_max =
      cmd->add_option("--rho-max", opt->rho_max,
                      "largest spectral radius of the impact map (docs/model.md sections 8, 12); "
                      "inf: no stability requirement")
          ->capture_default_str()
          ->type_name(kFloatOrInf);
  cmd->add_flag_callback(
         "--stable", [opt] { opt->rho_max = 1.0; },
         "the same as --rho-max 1: stable orbits, up to marginal stability")
      ->excludes(rho_max);
  cmd->add_option("--max-time", opt->max_time,
                  "time limit [s] of each optimisation; when reached, the best point so far is "
                  "reported with status max_time (inf: none)")
      ->capture_default_str();
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
                  fmt::format("evaluation budget of an NLopt global algorithm (not used by "
                              "multistart), 10 to {}",
                              kMaxStageEvaluations))
      ->capture_default_str();
  cmd->add_option("--hops", opt->hops,
                  fmt::format("forcing: basin-hopping restarts from random perturbations of the "
                              "best point after the starts, 0 to {}",
                              kMaxStarts))
      ->capture_default_str();
  opt->starts_option = cmd->add_option(
      "--starts", opt->starts,
      fmt::format("number of local polishes of the multistart, 1 to {} (default: 10 for "
                  "forcing, 20 for fourier)",
                  kMaxStarts));
  cmd->add_flag("--json", opt->json,
                "print one JSON object: status, I, v_mean, A, c, phi0, phi1, alpha, u, v_plus, "
                "x_min, x_max, stroke, clearance, active_constraints, binding, evaluations, "
                "algorithm, the margins and rho_max (+ coefficients for fourier, "
                "spectral_radius when the orbit exists; null where a quantity does not exist); "
                "the main job prints one object with paper_phase, robust, fastest, "
                "fastest_stable");
  cmd->add_option("-o,--output", opt->output,
                  "also write the JSON object (indented) to this file, atomically; nothing is "
                  "written without it");
  cmd->add_option("--force-csv", opt->force_csv,
                  "write the optimal force F(phi) over one period (phi = 0 at the impact, "
                  "columns phi,F) to this CSV file (main job: the robust gait's force)");
  opt->cmd = cmd;
  return {cmd, [opt] { return Run(*opt); }};
}

}  // namespace capsubot::app
