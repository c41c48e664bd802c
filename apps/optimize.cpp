// capsubot optimize: the fastest gait (docs/model.md section 7) with the margins of a robust
// gait (section 12), every gait checked from rest. Without --problem it runs the main job: the
// paper's problem P1 at c = A = T0/2, the fastest robust gait (P2 with the margins) checked from
// rest, the fastest motion from rest (reach, section 13), for comparison the exact optima
// without margins (valid; stable), and which gait to build. Prints a summary (or --json); -o
// writes the JSON.

#include "capsubot/optimize/optimize.hpp"

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <vector>

#include "capsubot/continue/gait_robustness.hpp"
#include "capsubot/io/io.hpp"
#include "capsubot/orbit/scaling.hpp"
#include "cli.hpp"
#include "commands.hpp"
#include "from_rest_report.hpp"
#include "help_format.hpp"
#include "progress.hpp"
#include "provenance.hpp"
#include "report.hpp"

namespace capsubot::app {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr int kForceCsvRows = 1001;

struct OptimizeCliOptions {
  std::string problem;  // "", phase, forcing, fourier, reach
  double A = kNaN;      // NaN: not given
  double c = kNaN;
  CLI::Option* A_option = nullptr;
  CLI::Option* c_option = nullptr;
  Params params;
  SearchRequest search;  // the bound, stability, time limit and search effort
  CLI::Option* bound_option = nullptr;
  int starts = 0;  // used only when given: else the problem's default
  CLI::Option* starts_option = nullptr;
  bool json = false;
  std::string output;  // empty: no file
  std::string force_csv;
  FromRestCliOptions from_rest;  // the from-rest check of every gait, the reach search
  double alpha = kNaN;           // reach: a fixed mass ratio (NaN: free)
  std::string from_rest_csv;     // main job: speeds promised and reached, for the figure
  CLI::App* cmd = nullptr;
};

// The runs that use an option: "" is the main job (no --problem), else a problem name. The P2
// options apply to reach through its seed, the robust gait.
const std::vector<OptionUse> kOptionUses = {
    {"--A", {"phase"}},
    {"--c", {"phase"}},
    {"--harmonics", {"fourier"}},
    {"--hops", {"", "forcing", "reach"}},
    {"--starts", {"", "forcing", "fourier", "reach"}},
    {"--bound", {"", "forcing", "fourier", "reach"}},
    {"--global-algorithm", {"", "forcing", "fourier", "reach"}},
    {"--local-algorithm", {"", "forcing", "fourier", "reach"}},
    {"--global-evaluations", {"", "forcing", "fourier", "reach"}},
    {"--alpha", {"reach"}},
    {"--reach-starts", {"", "reach"}},
    {"--reach-evaluations", {"", "reach"}},
    {"--reach-local-evaluations", {"", "reach"}},
    {"--reach-seconds", {"", "reach"}},
    {"--from-rest-csv", {""}},
};

std::string RunName(const std::string& problem) {
  return problem.empty() ? "the main job (no --problem)" : "--problem " + problem;
}

// The options the chosen run does not use: their defaults do not shape its output (left out
// of the provenance).
std::vector<std::string> UnusedOptionsOf(const OptimizeCliOptions& opt) {
  std::vector<std::string> unused = UnusedOptions(kOptionUses, opt.problem);
  if (opt.search.global_algorithm == kMultistart) unused.emplace_back("--global-evaluations");
  return unused;
}

// An option the chosen run does not use would be silently ignored: refuse it, naming both.
void RejectUnusedOptions(const OptimizeCliOptions& opt) {
  if (const OptionUse* use = GivenUnusedOption(*opt.cmd, kOptionUses, opt.problem)) {
    std::string expected;
    for (const char* run : use->runs) {
      if (run == nullptr) break;
      expected += (expected.empty() ? "" : " or ") + RunName(run);
    }
    throw std::invalid_argument(fmt::format("{} conflicts with {}: expected {} only with {}",
                                            use->option, RunName(opt.problem), use->option,
                                            expected));
  }
  const CLI::Option* evaluations = opt.cmd->get_option_no_throw("--global-evaluations");
  if (evaluations != nullptr && evaluations->count() > 0 &&
      opt.search.global_algorithm == kMultistart) {
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

// The files asked for, opened before any work (a bad path fails at once) and committed
// when their content is complete; null: not asked for.
struct OutputFiles {
  std::unique_ptr<AtomicFile> json, force_csv, from_rest_csv;
};

std::unique_ptr<AtomicFile> OpenIfAsked(const std::string& path, const char* option) {
  return path.empty() ? nullptr : std::make_unique<AtomicFile>(path, option);
}

void WriteForceCsv(const Forcing& f, AtomicFile* file) {
  if (file == nullptr) return;
  auto& out = file->stream();
  out << "phi,F\n";  // phi = 0 is the impact
  for (int i = 0; i < kForceCsvRows; ++i) {
    const double phi = kTau * i / (kForceCsvRows - 1);
    out << FormatNumber(phi) << ',' << FormatNumber(f.F(phi)) << '\n';
  }
  file->Commit();
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

// The search the command line asks for.
SearchRequest Request(const OptimizeCliOptions& opt) {
  SearchRequest r = opt.search;
  if (opt.starts_option->count() > 0) r.starts = opt.starts;
  return r;
}

void Emit(nlohmann::json j, const std::string& text, const OptimizeCliOptions& opt,
          AtomicFile* json_file) {
  AddProvenanceJson(j, *opt.cmd, UnusedOptionsOf(opt));
  if (json_file != nullptr) {
    json_file->stream() << j.dump(2) << '\n';
    json_file->Commit();
  }
  if (opt.json) {
    fmt::print("{}\n", j.dump());
  } else {
    fmt::print("{}{}", text, opt.output.empty() ? "" : fmt::format("\nwritten: {}\n", opt.output));
  }
}

// How far T0, e and alpha can move before the robust gait's motion is lost, in plain words.
std::string RobustnessText(const GaitRobustness& robustness) {
  return "    robustness       how far T0, e and alpha can move before this motion is lost\n"
         "                     (its continuation, docs/continuation.md):\n" +
         robustness.Summary("                       ");
}

// Which gait to build, in plain words: the reach winner when it beats the robust gait from
// rest, else the robust gait.
std::string Advice(const OptimizeResult& robust, const ReachResult& reach) {
  const GaitFromRest& fr = reach.seed.from_rest;
  std::string t = "\nWhich to build:\n";
  if (std::isnan(reach.mean_velocity)) {
    return t + "  no motion from rest could be checked: see the messages above.\n";
  }
  const Attractor& top = reach.attractors.attractors.front();
  const std::string odds =
      top.fraction == 1.0
          ? std::string("every start from rest ends in it")
          : fmt::format("{:.0f} % of the starts from rest end in its most common motion",
                        100.0 * top.fraction);
  if (reach.seed_won) {
    return t + fmt::format(
                   "  the robust gait (2): it is also the fastest motion found from rest,\n"
                   "  {} omega L on average over the starts; {}.\n",
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
        "  The robust gait (2) promises {} omega L, but from rest the robot averages\n"
        "  {} omega L with it ({} of {} starts end on it).\n",
        Num(robust.solution.orbit.v_mean, 4), Num(fr.attractors.mean_velocity, 4), fr.reached,
        fr.attractors.starts);
  }
  return t;
}

int RunMainJob(const OptimizeCliOptions& opt, OutputFiles& files) {
  const Params& p = opt.params;
  Params exact = p;  // the exact optima: no margins
  exact.margin = exact.margin_stroke = exact.stick_margin = 0.0;
  // 1. The paper's problem as the paper poses it (valid orbits, no margins): c = A = T0/2,
  // best phase. Its force sits on the friction bound, so any stick margin would exclude it.
  ShowStage("optimize: 1/5 the paper's problem (P1)");
  const OptimizeResult paper = OptimizePhase(Forcing::Harmonic(p.T0 / 2.0, p.T0 / 2.0, 0.0), exact,
                                             PhaseOptionsFor(Request(opt).WithRhoMax(kInf)));
  // 2. The fastest robust gait, checked from rest inside 3; 3. the fastest motion from rest,
  // seeded with it; 4. the exact optima, valid and stable, for comparison.
  ShowStage("optimize: 2/5 the fastest robust gait (P2)");
  const OptimizeResult robust = OptimizeForcing(p, ForcingOptionsFor(Request(opt)));
  ShowStage("optimize: 3/5 the fastest motion from rest (simulated starts; up to a minute)");
  const ReachResult reach = OptimizeReach(
      p, robust, opt.from_rest.Reach(opt.search.gait.force_bound, ReachOptions::kNaN));
  ShowStage("optimize: 4/5 how far T0, e and alpha can move (continuation of the robust gait)");
  const GaitRobustness robustness =
      robust.found() ? ComputeGaitRobustness(robust.solution.orbit) : GaitRobustness{};
  ShowStage("optimize: 5/5 the exact optima without margins");
  const OptimizeResult fastest =
      OptimizeForcing(exact, ForcingOptionsFor(Request(opt).WithRhoMax(kInf)));
  const OptimizeResult stable =
      OptimizeForcing(exact, ForcingOptionsFor(Request(opt).WithRhoMax(1.0)));
  ShowStage("");
  const double bound = std::isnan(opt.search.gait.force_bound) ? p.T0 : opt.search.gait.force_bound;

  nlohmann::json j = json::MainJobJson(paper, robust, reach, fastest, stable, robustness, p,
                                       opt.search.gait.rho_max, bound);
  WriteForceCsv(robust.solution.orbit.forcing, files.force_csv.get());
  if (files.from_rest_csv != nullptr) WriteFromRestCsv(*files.from_rest_csv, robust, reach);

  std::string t;
  t += fmt::format(
      "capsubot optimize: the fastest gait of the capsule robot that the robot reaches "
      "(docs/model.md sections 7, 12, 13)\n"
      "model: T0 = {:g} (friction bound mu g/(omega^2 L)), e = {:g} (restitution)\n"
      "robust gait (docs/model.md section 12): clearance >= max(d = {:g}, d_s = {:g} x stroke), "
      "stick margin s = {:g}, spectral radius <= {:g}\n"
      "units: I = capsule displacement per forcing period in shell lengths L; velocity in "
      "omega L\n"
      "(change them with --T0, --e, --margin, --margin-stroke, --stick-margin, --rho-max)\n\n",
      p.T0, p.e, p.margin, p.margin_stroke, p.stick_margin, opt.search.gait.rho_max);
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
      "   above; checked from rest on {} starts.\n",
      bound, reach.seed.from_rest.attractors.starts);
  t += robust.found() ? GaitText(robust, opt.search.gait.rho_max) +
                            FromRestText(reach.seed.from_rest) + RobustnessText(robustness)
                      : fmt::format("   Result: none found ({})\n", robust.message);
  t += fmt::format(
      "\n3. The fastest motion from rest (any number of impacts, A + c <= {:g}, alpha free),\n"
      "   simulated from every start:\n",
      bound);
  t += ReachText(reach);
  t += "\n4. For comparison, the exact optima without margins (they graze the walls: a robot\n"
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
  t += Advice(robust, reach);
  Emit(j, t, opt, files.json.get());
  return 0;
}

// --problem reach: the fastest motion from rest, seeded with the robust gait.
int RunReach(const OptimizeCliOptions& opt, OutputFiles& files) {
  const Params& p = opt.params;
  ShowStage("optimize: 1/2 the robust gait that seeds the search (P2)");
  const OptimizeResult robust = OptimizeForcing(p, ForcingOptionsFor(Request(opt)));
  ShowStage("optimize: 2/2 the fastest motion from rest (simulated starts; up to a minute)");
  const ReachResult reach =
      OptimizeReach(p, robust, opt.from_rest.Reach(opt.search.gait.force_bound, opt.alpha));
  ShowStage("");
  nlohmann::json j = json::ReachProblemJson(reach, p, opt.search.gait.rho_max);
  WriteForceCsv(reach.forcing, files.force_csv.get());
  const std::string t = fmt::format(
      "capsubot optimize --problem reach: T0 = {:g}, e = {:g}; seed: the robust gait (margins "
      "d = {:g}, d_s = {:g}, s = {:g}, spectral radius <= {:g})\n  status           {}\n  {}\n{}",
      p.T0, p.e, p.margin, p.margin_stroke, p.stick_margin, opt.search.gait.rho_max,
      OptimizeStatusName(reach.status), reach.message, ReachText(reach));
  Emit(j, t, opt, files.json.get());
  return 0;
}

int RunProblem(const OptimizeCliOptions& opt, const FromRestOptions& check, OutputFiles& files) {
  const Params& p = opt.params;
  OptimizeResult r;
  ShowStage(fmt::format("optimize: --problem {}", opt.problem));
  if (opt.problem == "phase") {
    if (std::isnan(opt.A) || std::isnan(opt.c)) {
      throw std::invalid_argument(
          "--problem phase needs the force shape: give --A and --c (F = A sin(phi + phi0) + c)");
    }
    r = OptimizePhase(Forcing::Harmonic(opt.A, opt.c, 0.0), p, PhaseOptionsFor(Request(opt)));
  } else if (opt.problem == "forcing") {
    r = OptimizeForcing(p, ForcingOptionsFor(Request(opt)));
  } else {  // fourier (CLI11 checks the name)
    r = OptimizeFourier(p, FourierOptionsFor(Request(opt)));
  }
  ShowStage("optimize: the optimum checked from rest (simulated starts)");
  const GaitFromRest from_rest = CheckGaitFromRest(r.solution.orbit, p, check);
  ShowStage("");
  nlohmann::json j =
      json::ProblemJson(r, opt.problem.c_str(), from_rest, p, opt.search.gait.rho_max);
  WriteForceCsv(r.solution.orbit.forcing, files.force_csv.get());
  std::string t;
  t += fmt::format(
      "capsubot optimize --problem {}: T0 = {:g}, e = {:g}, margins d = {:g}, d_s = {:g}, "
      "s = {:g}, spectral radius <= {:g}\n",
      opt.problem, p.T0, p.e, p.margin, p.margin_stroke, p.stick_margin, opt.search.gait.rho_max);
  t += fmt::format("  status           {}\n  {}\n", OptimizeStatusName(r.status), r.message);
  t += GaitText(r, opt.search.gait.rho_max) + FromRestText(from_rest);
  if (opt.problem == "fourier") {
    t += fmt::format(
        "    gain over P2     {} (harmonic optimum I = {})\n",
        r.found() ? fmt::format("{:+.4g}%", 100.0 * (r.solution.orbit.I / r.baseline_I - 1.0))
                  : std::string("-"),
        Num(r.baseline_I, 8));
  }
  Emit(j, t, opt, files.json.get());
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
  RequireGiven(opt.bound_option,
               std::isfinite(opt.search.gait.force_bound) && opt.search.gait.force_bound > 0.0,
               fmt::format("{}", opt.search.gait.force_bound), "a finite bound > 0 (at most T0)");
  // Every size is bounded before any work starts.
  if (opt.starts_option->count() > 0) RequireInRange("--starts", opt.starts, 1, kMaxStarts);
  RequireInRange("--hops", opt.search.hops, 0, kMaxStarts);
  RequireInRange("--global-evaluations", opt.search.global_evaluations, 10, kMaxStageEvaluations);
  if (!(opt.search.gait.rho_max > 0.0)) {
    throw std::invalid_argument(fmt::format(
        "--rho-max = {} is invalid: expected rho_max > 0 (inf: no stability requirement)",
        opt.search.gait.rho_max));
  }
  if (!(opt.search.max_time > 0.0)) {
    throw std::invalid_argument(
        fmt::format("--max-time = {} is invalid: expected a time limit > 0 seconds (inf: none)",
                    opt.search.max_time));
  }
  opt.params.Validate();
  // The options of the work to come, checked before any of it starts.
  const FromRestOptions check = opt.from_rest.Check();
  if (opt.problem.empty() || opt.problem == "reach") {
    opt.from_rest.Reach(opt.search.gait.force_bound, opt.alpha).Validate();
  }
  if (opt.problem != "phase") {
    const ForcingDesignOptions design = ForcingOptionsFor(Request(opt));
    design.Validate();
    design.gait.BoundFor(opt.params);
  }
  RequireDistinctOutputs(
      {{opt.output, "-o"}, {opt.force_csv, "--force-csv"}, {opt.from_rest_csv, "--from-rest-csv"}});
  OutputFiles files;
  files.json = OpenIfAsked(opt.output, "-o");
  files.force_csv = OpenIfAsked(opt.force_csv, "--force-csv");
  files.from_rest_csv = OpenIfAsked(opt.from_rest_csv, "--from-rest-csv");
  // The CSV files start with the provenance of the JSON (the same run, the same options).
  const std::string comment = OutputProvenance(*opt.cmd, UnusedOptionsOf(opt)).CommentLine();
  for (AtomicFile* csv : {files.force_csv.get(), files.from_rest_csv.get()}) {
    if (csv != nullptr) csv->stream() << comment;
  }
  if (opt.problem.empty()) return RunMainJob(opt, files);
  return opt.problem == "reach" ? RunReach(opt, files) : RunProblem(opt, check, files);
}

}  // namespace

Command AddOptimizeCommand(CLI::App& app) {
  auto opt = std::make_shared<OptimizeCliOptions>();
  opt->params.margin_stroke = kRobustMarginStroke;
  opt->params.stick_margin = kRobustStickMargin;
  opt->search.gait.rho_max = kRobustRhoMax;  // the robust default; the library's is inf
  CLI::App* cmd = app.add_subcommand(
      "optimize",
      "The fastest gait (docs/model.md section 7) with the margins of a robust gait (section "
      "12), every gait checked from rest. Without --problem: the main job: the paper's problem "
      "(best phase at c = A = T0/2), the fastest robust gait with A + c <= T0 checked from "
      "rest, the fastest motion from rest (section 13), the exact optima without margins "
      "(valid, stable) for comparison, and which gait to build. With --problem: one problem. "
      "Prints a summary (or --json); -o also writes the JSON. Exit status 0 whenever the "
      "computation ran, valid gait found or not.");
  cmd->add_option("--problem", opt->problem,
                  "phase (P1: best phi0 for given --A, --c), forcing (P2: best A, c, phi0 with "
                  "A + c <= --bound), fourier (P3: best K-harmonic force with max |F| <= "
                  "--bound) or reach (the fastest motion from rest: A, c, alpha with A + c <= "
                  "--bound, simulated, seeded with the robust P2 gait); P1, P2 and P3 name the "
                  "first three; default: the main job")
      ->transform(CLI::Transformer(
                      std::map<std::string, std::string>{
                          {"P1", "phase"}, {"P2", "forcing"}, {"P3", "fourier"}},
                      CLI::ignore_case)
                      .description(""))
      ->check(CLI::IsMember({"phase", "forcing", "fourier", "reach"}).description(""))
      ->type_name("phase|forcing|fourier|reach");  // the help and the completion show these
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
                  "one_impact_orbit)")
      ->type_name("FILE");
  cmd->add_option("--alpha", opt->alpha,
                  "reach: a fixed mass ratio 0 < alpha < 1 (default: alpha is optimised too)");
  opt->bound_option =
      cmd->add_option("--bound", opt->search.gait.force_bound,
                      "force bound for forcing/fourier: A + c (max |F|) <= bound, 0 < bound <= T0, "
                      "same unit as A (default: T0)");
  CLI::Option* rho_max =
      cmd->add_option("--rho-max", opt->search.gait.rho_max,
                      "largest spectral radius of the impact map (docs/model.md sections 8, 12); "
                      "inf: no stability requirement")
          ->capture_default_str()
          ->type_name(kFloatOrInf);
  cmd->add_flag_callback(
         "--stable", [opt] { opt->search.gait.rho_max = 1.0; },
         "the same as --rho-max 1: stable orbits, up to marginal stability")
      ->excludes(rho_max);
  cmd->add_option("--max-time", opt->search.max_time,
                  "time limit [s] of each optimisation; when reached, the best point so far is "
                  "reported with status max_time (inf: none)")
      ->capture_default_str()
      ->type_name(kFloatOrInf);
  cmd->add_option("--harmonics", opt->search.harmonics,
                  "number K of harmonics of the Fourier force")
      ->capture_default_str();
  cmd->add_option("--global-algorithm", opt->search.global_algorithm,
                  "global stage of forcing/fourier: multistart (scan + local polishes) or an "
                  "NLopt algorithm: GN_ISRES, GN_ORIG_DIRECT, GN_ORIG_DIRECT_L, GN_AGS")
      ->capture_default_str();
  cmd->add_option("--local-algorithm", opt->search.local_algorithm,
                  "local constrained polish, NLopt name: LN_COBYLA, LD_SLSQP, LD_MMA, LD_CCSAQ "
                  "(LD_*: gradients by central differences)")
      ->capture_default_str();
  cmd->add_option("--global-evaluations", opt->search.global_evaluations,
                  fmt::format("evaluation budget of an NLopt global algorithm (not used by "
                              "multistart), 10 to {}",
                              kMaxStageEvaluations))
      ->capture_default_str();
  cmd->add_option("--hops", opt->search.hops,
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
                "spectral_radius when the orbit exists, from_rest: the gait checked from rest; "
                "null where a quantity does not exist); --problem reach prints the reach object; "
                "the main job prints one object with paper, robust (with from_rest), reach, "
                "fastest, fastest_stable");
  cmd->add_option("-o,--output", opt->output,
                  "also write the JSON object (indented) to this file, atomically; nothing is "
                  "written without it")
      ->type_name("FILE");
  cmd->add_option("--force-csv", opt->force_csv,
                  "write the optimal force F(phi) over one period (phi = 0 at the impact, "
                  "columns phi,F) to this CSV file (main job: the robust gait's force; reach: the "
                  "winner's)")
      ->type_name("FILE");
  opt->cmd = cmd;
  AddProgressOptions(*cmd);
  SetExamples(*cmd, {{"the main job: the paper's problem, the fastest robust gait, "
                      "the fastest motion from rest (takes about a minute)",
                      "optimize -o optimum.json"},
                     {"P2 alone: the fastest gait with A + c <= T0 whose spectral "
                      "radius is at most 0.95",
                      "optimize --problem forcing --T0 1 --rho-max 0.95"}});
  return {cmd, [opt] { return Run(*opt); }, {}};
}

}  // namespace capsubot::app
