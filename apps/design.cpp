// capsubot design: a real robot in SI units; the inner mass (and motor frequency) of its
// fastest robust one-impact gait, with speed, power and cost of transport, and of the fastest
// motion reached from rest in each direction (library: capsubot/design/design.hpp,
// capsubot/design/design_from_rest.hpp).

#include "capsubot/design/design.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <set>
#include <stdexcept>
#include <string>
#include <string_view>
#include <tuple>
#include <utility>
#include <vector>

#include "attract_options.hpp"
#include "capsubot/attract/gait_from_rest.hpp"
#include "capsubot/design/design_from_rest.hpp"
#include "capsubot/io/io.hpp"
#include "capsubot/report/design_json.hpp"
#include "capsubot/sweep/design_grid.hpp"
#include "cli.hpp"
#include "commands.hpp"
#include "design_config.hpp"
#include "from_rest_report.hpp"
#include "help_format.hpp"
#include "progress.hpp"
#include "provenance.hpp"
#include "ranks.hpp"
#include "report.hpp"

namespace capsubot::app {
namespace {

struct DesignCliOptions {
  DesignConfigOptions config;
  FromRestCliOptions from_rest;  // the from-rest search (part b): starts, budgets, time limit
  bool part_b = false;           // --from-rest: also part (b), the fastest motion from rest
  bool json = false;
  std::vector<std::string> grids;  // --grid NAME=SPEC: one design a point, to the CSV -o
  std::string output;
  std::string shard;  // "K/N", empty: the whole grid
  bool resume = false;
};

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The runs of design: "" one design, "from-rest" with part (b), "grid" one design a point.
const std::vector<OptionUse> kOptionUses = {
    {"--from-rest-starts", {"from-rest"}},
    {"--reach-starts", {"from-rest"}},
    {"--reach-evaluations", {"from-rest"}},
    {"--reach-local-evaluations", {"from-rest"}},
    {"--reach-seconds", {"from-rest"}},
    {"--threads", {"from-rest", "grid"}},
    {"--json", {"", "from-rest"}},
    {"--output", {"grid"}},
    {"--shard", {"grid"}},
    {"--resume", {"grid"}},
};

std::string RunOf(const DesignCliOptions& opt) {
  if (!opt.grids.empty()) return "grid";
  return opt.part_b ? "from-rest" : "";
}

std::string RunName(const std::string& run) {
  if (run == "grid") return "--grid";
  return run.empty() ? "one design (no --from-rest, no --grid)" : "--from-rest";
}

// An option the chosen run does not use would be silently ignored: refuse it, naming both.
void RejectUnusedOptions(const DesignCliOptions& opt, const CLI::App& cmd) {
  const std::string run = RunOf(opt);
  if (!opt.grids.empty() && opt.part_b) {
    throw std::invalid_argument(
        "--from-rest is invalid with --grid: expected one of them (a grid writes the "
        "one-impact gait of each point to the CSV -o)");
  }
  if (const OptionUse* use = GivenUnusedOption(cmd, kOptionUses, run)) {
    std::string expected;
    for (const char* r : use->runs) {
      if (r != nullptr) expected += (expected.empty() ? "" : " or ") + RunName(r);
    }
    throw std::invalid_argument(fmt::format("{} is invalid with {}: expected {} only with {}",
                                            use->option, RunName(run), use->option, expected));
  }
}

// The numbers of gaits and motions from rest for the table and the CSV are those of their JSON
// (src/report/).
using json::Dimensionless;
using json::UserUnits;

std::string Num(double value, const char* unit) {
  return std::isnan(value) ? "-" : fmt::format("{:.6g}{}", value, unit);
}

std::string MotorFormula(const MotorForce& f) {
  if (!f.fourier()) {
    return fmt::format("F_N = {:g} sin(omega t + phase) + {:g} N", f.amplitude, f.bias);
  }
  std::string s = fmt::format("F_N = {:g}", f.bias);
  for (std::size_t k = 0; k < f.sin.size(); ++k) {
    const double a = f.cos.empty() ? 0.0 : f.cos[k];
    s += fmt::format(" + {:g} cos {}s + {:g} sin {}s", a, k + 1, f.sin[k], k + 1);
  }
  return s + " N, s = omega t + phase";
}

// Shortest text that reads back as the same double ("0.7", not "0.69999999999999996").
std::string Shortest(double value) { return fmt::format("{}", value); }

// The `capsubot solve` command that reproduces the gait's orbit (round-trip numbers).
std::string SolveCommand(const Gait& g) {
  const Orbit& o = g.solution.orbit;
  const Forcing& f = o.forcing;
  std::string force;
  if (f.harmonic()) {
    force = fmt::format("--A {} --c {}", Shortest(f.amplitude()), Shortest(f.mean()));
  } else {
    std::vector<std::string> a, b;
    for (int k = 1; k <= f.harmonics(); ++k) {
      a.push_back(Shortest(f.a(k)));
      b.push_back(Shortest(f.b(k)));
    }
    force = fmt::format("--c {} --cos {} --sin {}", Shortest(f.mean()), fmt::join(a, ","),
                        fmt::join(b, ","));
  }
  return fmt::format("capsubot solve {} --phi0 {} --T0 {} --e {} --stability", force,
                     Shortest(f.phi0()), Shortest(o.T0), Shortest(o.e));
}

std::string Table(const DesignInput& in, const DesignResult& r) {
  const Gait& g = r.one_impact;
  std::string t = "robot design: the fastest robust one-impact gait\n";
  t += fmt::format(
      "  robot             m1 = {:g} kg, L = {:g} mm, mu = {:g}, g = {:g} m/s^2, e = {:g}\n", in.m1,
      1e3 * in.L, in.mu, in.g, in.e);
  t += fmt::format("  motor             {}\n", MotorFormula(in.force));
  t += fmt::format("  searched          m2 in [{:g}, {:g}] kg, f {}\n", in.M2Min(), in.M2Max(),
                   in.frequency_min == in.frequency_max
                       ? fmt::format("= {:g} Hz", in.frequency_min)
                       : fmt::format("in [{:g}, {:g}] Hz", in.frequency_min, in.frequency_max));
  t += fmt::format("  robust gait       d = {:g}, d_s = {:g}, s = {:g}, rho_max = {:g}\n",
                   in.margin, in.margin_stroke, in.stick_margin, in.rho_max);
  t += fmt::format("  status            {}: {}\n", DesignStatusName(r.status), r.message);
  if (!r.complete)
    t += "  note              an orbit search hit its work bound: orbits may be missing\n";
  if (!g.ok()) return t;
  const Orbit& o = g.solution.orbit;
  t += fmt::format("  inner mass        m2 = {}   (alpha = m2/(m1+m2) = {:.6g})\n",
                   Num(g.m2_kg, " kg"), o.alpha);
  t += fmt::format("  frequency         f = {}\n", Num(g.frequency_hz, " Hz"));
  t += fmt::format("  mean speed        {}\n", Num(g.speed_mm_s, " mm/s"));
  t += fmt::format("  step per period   {}\n", Num(g.displacement_mm, " mm"));
  t += fmt::format("  impact velocity   {}   (inner body relative to the shell)\n",
                   Num(g.impact_velocity_m_s, " m/s"));
  t += fmt::format("  motor energy      {} per period\n", Num(g.energy_mj, " mJ"));
  t += fmt::format("  mean motor power  {} net, {} positive part\n", Num(g.power_mw, " mW"),
                   Num(g.power_positive_mw, " mW"));
  t += fmt::format("  losses            friction {}, impacts {} per period\n",
                   Num(g.friction_loss_mj, " mJ"), Num(g.impact_loss_mj, " mJ"));
  t += fmt::format("  cost of transport COT = {} (>= mu = {:g}), efficiency mu/COT = {}\n",
                   Num(g.cot, ""), in.mu, Num(g.efficiency, ""));
  const auto d = Dimensionless(g);
  t += fmt::format("  dimensionless     T0 = {}, A = {}, c = {}, alpha = {}, phi0 = {}\n",
                   Num(d[0].second, ""), Num(d[1].second, ""), Num(d[2].second, ""),
                   Num(d[3].second, ""), Num(d[4].second, ""));
  t +=
      fmt::format("  orbit             x_min = {}, x_max = {}, spectral radius = {}, {} orbit(s)\n",
                  Num(g.solution.validity.x_min, ""), Num(g.solution.validity.x_max, ""),
                  Num(g.stability.spectral_radius, ""), g.orbits);
  t += fmt::format("  binding           {}\n", g.binding.empty()
                                                   ? "none (an interior maximum)"
                                                   : fmt::format("{}", fmt::join(g.binding, ", ")));
  t += fmt::format("  check             {}\n", SolveCommand(g));
  return t;
}

// Attractors listed one by one in the text (the rest are summed).
constexpr std::size_t kListedAttractors = 4;

// One direction of the from-rest design in lines of the table.
std::string FromRestLines(const DesignInput& in, const FromRestBest& b, int max_period) {
  std::string t = fmt::format("  {:<17} {}: {}\n", DirectionName(b.direction),
                              FromRestStatusName(b.status), b.message);
  if (!b.ok()) return t;
  const DesignModel& m = b.model;
  t += fmt::format("    inner mass      m2 = {}   (alpha = {:.6g}), f = {}\n", Num(b.m2_kg, " kg"),
                   m.alpha, Num(b.frequency_hz, " Hz"));
  t += fmt::format("    mean speed      {} over the starts, {} per period\n",
                   Num(b.speed_mm_s, " mm/s"), Num(b.displacement_mm, " mm"));
  t += fmt::format("    impact velocity {}\n",
                   std::isnan(b.impact_velocity_m_s)
                       ? std::string("- (the most common motion has several impacts per period)")
                       : Num(b.impact_velocity_m_s, " m/s"));
  t +=
      fmt::format("    motor           {} per period, {} net, {} positive part\n",
                  Num(b.energy_mj, " mJ"), Num(b.power_mw, " mW"), Num(b.power_positive_mw, " mW"));
  t += fmt::format("    losses          friction {}, impacts {} per period\n",
                   Num(b.friction_loss_mj, " mJ"), Num(b.impact_loss_mj, " mJ"));
  t += fmt::format("    cost            COT = {}, efficiency mu/COT = {}\n", Num(b.cot, ""),
                   Num(b.efficiency, ""));
  t +=
      fmt::format("    dimensionless   T0 = {}, A = {}, c = {}, alpha = {}\n", Num(m.params.T0, ""),
                  Num(m.forcing.harmonic() ? m.forcing.amplitude() : kNaN, ""),
                  Num(m.forcing.mean(), ""), Num(m.alpha, ""));
  const auto& list = b.attractors.attractors;
  for (std::size_t k = 0; k < list.size() && k < kListedAttractors; ++k) {
    const Attractor& a = list[k];
    t += fmt::format("    attractor {:<5} {:.0f} % of the starts: {}, {}\n", k + 1,
                     100.0 * a.fraction, AttractorWords(a, max_period),
                     Num(1e3 * m.omega * in.L * a.mean_velocity, " mm/s"));
  }
  if (list.size() > kListedAttractors) {
    double rest = 0.0;
    for (std::size_t k = kListedAttractors; k < list.size(); ++k) rest += list[k].fraction;
    t += fmt::format("    and             {} more attractors, {:.0f} % of the starts\n",
                     list.size() - kListedAttractors, 100.0 * rest);
  }
  return t;
}

// Part (b) of the table: the fastest motion from rest in each direction.
std::string FromRestTable(const DesignInput& in, const FromRestCliOptions& cli,
                          const DesignFromRestResult& r) {
  const int max_period = cli.Check().attractor.motion.max_period;
  std::string t = fmt::format(
      "robot design: the fastest motion reached from rest, each direction ({} starts from rest)\n",
      cli.starts);
  t += FromRestLines(in, r.forward, max_period);
  t += FromRestLines(in, r.backward, max_period);
  t += fmt::format(
      "  search            {} from-rest evaluations ({} rejected: event_limit), "
      "{:.1f} s{}\n",
      r.evaluations, r.rejected_evaluations, r.search_seconds,
      r.max_time ? "; the time limit (--reach-seconds) stopped a search stage" : "");
  return t;
}

// The from-rest design's settings from the options shared with `optimize --problem reach`.
DesignFromRestOptions FromRestDesignOptions(const FromRestCliOptions& cli) {
  DesignFromRestOptions o;
  std::tie(o.search.n_x, o.search.n_psi) = ParseGridSize("--reach-starts", cli.reach_starts);
  o.search.attractor.threads = cli.threads;
  const FromRestOptions grid = cli.Check();  // the grid and threads; the record stays long
  o.check.n_x = grid.n_x;
  o.check.n_psi = grid.n_psi;
  o.check.attractor.threads = grid.attractor.threads;
  o.global_evaluations = cli.reach_evaluations;
  o.local_evaluations = cli.reach_local_evaluations;
  o.max_seconds = cli.reach_seconds;
  return o;
}

// The stage of the from-rest design, shown when progress is (progress.hpp).
DesignFromRestProgress StageProgress() {
  if (!ProgressShown()) return {};
  return [](const std::string& stage, std::int64_t done, std::int64_t total) {
    ShowStage(fmt::format("design: 2/2 the fastest motion from rest, {}", stage),
              fmt::format("{} of at most {} from-rest evaluations", done, total));
  };
}

// The grid's columns (DesignGridAxis::column: m2_kg, frequency_hz, ...).
using GridColumns = std::vector<std::string>;

// Whether the user-unit key `key` of a gait is a result column: all but those a grid's column
// holds (a gridded m2 is the column m2_kg, a gridded frequency frequency_hz).
bool ResultColumn(const char* key, const GridColumns& grid) {
  return std::find(grid.begin(), grid.end(), key) == grid.end();
}

// The result columns of a design grid, after the grid's: the gait's status, its numbers in
// the user's units (ResultColumn) and dimensionless (those of its JSON), its orbits and
// binding limits.
std::vector<std::string> GaitColumns(const GridColumns& grid) {
  std::vector<std::string> columns = {"status"};
  for (const auto& [key, value] : UserUnits(Gait{})) {
    if (ResultColumn(key, grid)) columns.emplace_back(key);
  }
  for (const auto& [key, value] : Dimensionless(Gait{})) columns.emplace_back(key);
  columns.emplace_back("orbits");
  columns.emplace_back("binding");
  return columns;
}

// The cells of GaitColumns(grid).
std::string GaitCells(const Gait& g, const GridColumns& grid) {
  std::vector<std::string> cells = {GaitStatusName(g.status)};
  for (const auto& [key, value] : UserUnits(g)) {
    if (ResultColumn(key, grid)) cells.push_back(FormatNumber(value));
  }
  for (const auto& [key, value] : Dimensionless(g)) cells.push_back(FormatNumber(value));
  cells.push_back(std::to_string(g.orbits));
  cells.push_back(fmt::format("{}", fmt::join(g.binding, ";")));
  return fmt::format("{}", fmt::join(cells, ","));
}

// `p` (a provenance of `cmd`) with --config FILE and the settings' flags as typed replaced by
// the value of every setting of the input (`settings`, BuildDesignInput), as flags in their
// place among the others (declaration order): the provenance names the robot itself (two
// contents of one file differ; `--g 9.81` typed or left to its default, `--m1 0.20` or
// `--m1 0.2` are alike), and it is the provenance of the same command given without the file.
Provenance WithSettings(Provenance p, const CLI::App& cmd, const DesignConfigOptions& config,
                        const std::vector<std::pair<std::string, std::string>>& settings) {
  std::set<std::string> typed = {"--config"};
  for (const CLI::Option* option : config.options) {
    typed.insert("--" + option->get_lnames().front());
  }
  p.options.erase(
      std::remove_if(p.options.begin(), p.options.end(),
                     [&typed](const auto& option) { return typed.count(option.first) > 0; }),
      p.options.end());
  std::map<std::string, std::size_t> rank;  // long name -> declaration index
  for (const CLI::Option* option : cmd.get_options()) {
    if (!option->get_lnames().empty())
      rank.emplace("--" + option->get_lnames().front(), rank.size());
  }
  for (const auto& flag : settings) {
    const auto at = std::upper_bound(
        p.options.begin(), p.options.end(), rank.at(flag.first),
        [&rank](std::size_t r, const auto& option) { return r < rank.at(option.first); });
    p.options.insert(at, flag);
  }
  return p;
}

// The provenance of a grid: the robot's settings (those of --config as flags) and the grids;
// not the options of the from-rest search (a grid does not run it) nor those of how or where
// the file is computed (--threads, -o, --shard, --resume).
std::string GridProvenance(const DesignCliOptions& opt, const CLI::App& cmd,
                           const std::vector<std::pair<std::string, std::string>>& settings) {
  std::vector<std::string> exclude;
  for (const CLI::Option* option : cmd.get_options()) {
    if (option->get_lnames().empty()) continue;
    const std::string name = "--" + option->get_lnames().front();
    const bool setting = std::find(opt.config.options.begin(), opt.config.options.end(), option) !=
                         opt.config.options.end();
    if (!setting && name != "--config" && name != "--grid") exclude.push_back(name);
  }
  return WithSettings(CommandProvenance(cmd, exclude), cmd, opt.config, settings).CommandLine();
}

int RunGrid(const DesignCliOptions& opt, const CLI::App& cmd) {
  DesignGridOptions o;
  for (const std::string& spec : opt.grids) o.axes.push_back(ParseDesignGridAxis(spec));
  std::vector<std::pair<std::string, std::string>> settings;
  o.input = BuildDesignInput(opt.config, o.axes, &settings);
  if (opt.output.empty()) {
    throw std::invalid_argument("output is missing: --grid writes its CSV to -o FILE");
  }
  GridColumns grid;
  for (const DesignGridAxis& axis : o.axes) grid.push_back(axis.column());
  o.columns = GaitColumns(grid);
  o.row = [grid](const Gait& g) { return GaitCells(g, grid); };
  o.comments.push_back(GridProvenance(opt, cmd, settings));
  o.output = opt.output;
  if (!opt.shard.empty()) std::tie(o.shard, o.shards) = ParseShard(opt.shard);
  o.resume = opt.resume;
  o.threads = CapThreads(opt.from_rest.threads, "capsubot design");
  const bool shown = ProgressShown();
  ProgressBar bar("points");
  const SweepProgressCallback progress = GridProgress(bar);
  Ranks ranks;  // under mpirun: rank 0 runs the grid, the others compute blocks of points
  if (ranks.worker()) return ranks.Serve(DesignGridBlocks(o), o.threads);  // rank 0 validates
  SweepSummary summary;
  try {
    summary = RunDesignGrid(o, progress, ranks.backend());
  } catch (const SweepResumableError& e) {
    throw WriteError(std::string(e.what()) + ": run the same command with --resume to continue");
  }
  if (shown) {
    fmt::print(stderr, "capsubot design: {} points written to {} in {:.3f} s on {} threads\n",
               summary.points, o.output, summary.seconds, summary.threads);
  }
  return 0;
}

int Run(const DesignCliOptions& opt, const CLI::App& cmd) {
  RejectUnusedOptions(opt, cmd);
  if (!opt.grids.empty()) return RunGrid(opt, cmd);
  std::vector<std::pair<std::string, std::string>> settings;
  const DesignInput input = BuildDesignInput(opt.config, {}, &settings);
  const DesignProgress progress = CountProgress("robots");
  const bool with_from_rest = opt.part_b;
  const DesignFromRestOptions from_rest_options = FromRestDesignOptions(opt.from_rest);
  from_rest_options.Validate();  // bad options fail before any work
  ShowStage("design: 1/2 the fastest robust one-impact gait");
  const DesignResult r = Design(input, progress);
  DesignFromRestResult from_rest;
  if (with_from_rest) from_rest = DesignFromRest(input, from_rest_options, StageProgress());
  ShowStage("");
  if (opt.json) {
    nlohmann::json j = json::DesignJson(r);
    if (with_from_rest) j["from_rest_best"] = json::FromRestBestJson(input, from_rest);
    j["provenance"] = WithSettings(JsonProvenance(cmd, UnusedOptions(kOptionUses, RunOf(opt))), cmd,
                                   opt.config, settings)
                          .Json();
    fmt::print("{}\n", j.dump());
  } else {
    fmt::print("{}", Table(input, r));
    if (with_from_rest) fmt::print("{}", FromRestTable(input, opt.from_rest, from_rest));
  }
  return 0;
}

}  // namespace

Command AddDesignCommand(CLI::App& app) {
  auto opt = std::make_shared<DesignCliOptions>();
  CLI::App* cmd = app.add_subcommand(
      "design",
      "Design a real robot in SI units: for the shell (m1, gap L, friction mu) and the motor "
      "force, find the inner mass m2 (and the frequency, with --frequency-range) of the fastest "
      "robust one-impact gait, with its speed, motor power, losses and cost of transport, and "
      "of the fastest motion reached from rest in each direction (docs/design.md). Exit status 0 "
      "whenever the search ran, gait found or not.");
  AddDesignConfigOptions(*cmd, opt->config);
  // The from-rest options of `optimize --problem reach`, with the design's smaller budgets.
  const DesignFromRestOptions defaults;
  opt->from_rest.reach_evaluations = defaults.global_evaluations;
  opt->from_rest.reach_local_evaluations = defaults.local_evaluations;
  opt->from_rest.reach_seconds = defaults.max_seconds;
  AddFromRestOptions(*cmd, opt->from_rest, true);
  cmd->add_flag("--from-rest", opt->part_b,
                "also find the fastest motion reached from rest in each direction (part b, "
                "simulated: a few seconds; sized by the options below)");
  cmd->add_flag("--json", opt->json,
                "print one JSON object: status, message, one_impact {m2_kg, frequency_hz, "
                "speed_mm_s, displacement_mm, impact_velocity_m_s, energy_mj, power_mw, "
                "power_positive_mw, friction_loss_mj, impact_loss_mj, cot, efficiency, "
                "dimensionless {T0, A, c, alpha, phi0, ...}, binding}, from_rest_best (with "
                "--from-rest) {forward, backward: the same keys, forward_fraction, "
                "backward_fraction, attractors}, robots, complete, provenance");
  cmd->add_option("--grid", opt->grids,
                  "instead of one design, one CSV row per point of a grid over the robot's "
                  "inputs (repeatable: the product, the first slowest): NAME=LO:HI:N, "
                  "NAME=LO:HI:N:log or NAME=V1,V2,... with NAME one of m1, L, mu, g, e, "
                  "force-amplitude, force-bias, frequency (fixed at each point), m2 (fixed at "
                  "each point; else searched over m2-range), margin, margin-stroke, stick-margin, "
                  "rho-max (inf: no stability requirement); to the CSV file -o")
      ->type_name("NAME=SPEC");
  cmd->add_option("-o,--output", opt->output,
                  "CSV file of --grid (built as FILE.partial with a checkpoint, renamed at the "
                  "end; - for standard output)")
      ->type_name("FILE");
  cmd->add_option("--shard", opt->shard,
                  "with --grid: compute only shard K of N (0 <= K < N), the points p with "
                  "p % N = K; `capsubot merge OUT SHARD_FILES...` joins the N files; 0/1 "
                  "writes the file of the whole grid")
      ->type_name("K/N");
  cmd->add_flag("--resume", opt->resume,
                "with --grid: continue from FILE.checkpoint of the same run (killed or failed)");
  AddProgressOptions(*cmd);
  SetExamples(*cmd, {{"the example robot (examples/robot.toml): its inner mass, "
                      "speed, power and cost of transport",
                      "design --m1 0.2 --L 0.02 --mu 0.3 --e 0.7 --force-amplitude "
                      "0.5 --force-bias 0.1 --frequency 20"},
                     {"the same robot at 4 inner masses x 2 restitutions, one CSV row "
                      "a point",
                      "design --m1 0.2 --L 0.02 --mu 0.3 --force-amplitude 0.5 "
                      "--force-bias 0.1 --frequency 20 --grid m2=0.2:0.26:4:log "
                      "--grid e=0.5,0.7 -o grid.csv"}});
  // A grid is distributed under mpirun; one design runs on one process.
  return {cmd, [opt, cmd] { return Run(*opt, *cmd); }, [opt] { return !opt->grids.empty(); }};
}

}  // namespace capsubot::app
