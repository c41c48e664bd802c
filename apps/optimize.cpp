// capsubot optimize: the fastest gait (docs/model.md section 7) with the margins of a robust
// gait (section 12), every gait checked from rest. Without --problem it runs the main job: the
// paper's problem P1 at c = A = T0/2, the fastest robust gait (P2 with the margins) checked from
// rest, the fastest motion from rest (reach, section 13), for comparison the exact optima
// without margins (valid; stable), and which gait to build. Prints a summary (or --json); -o
// writes the JSON.

#include <fmt/format.h>

#include <cmath>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "capsubot/cli/command.hpp"
#include "capsubot/cli/force_options.hpp"
#include "capsubot/cli/from_rest_options.hpp"
#include "capsubot/cli/help_format.hpp"
#include "capsubot/cli/progress.hpp"
#include "capsubot/cli/provenance.hpp"
#include "capsubot/cli/result_output.hpp"
#include "capsubot/cli/setting_options.hpp"
#include "capsubot/cli/strict_values.hpp"
#include "capsubot/io/io.hpp"
#include "capsubot/job/optimize_job.hpp"
#include "capsubot/job/optimize_settings.hpp"
#include "capsubot/job/search_settings.hpp"
#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/report/optimize_csv.hpp"
#include "capsubot/report/optimize_json.hpp"
#include "capsubot/report/optimize_text.hpp"
#include "commands.hpp"
#include "optimize_flags.hpp"

namespace capsubot::cli {
namespace {

struct OptimizeCliOptions {
  OptimizeSettings settings;     // the job's settings, bound to their flags
  int starts = 0;                // --starts (settings.search.starts when given)
  FromRestCliOptions from_rest;  // the from-rest check of every gait, the reach search
  std::string T0_range;          // reach: "LO:HI", the motor's frequency free (empty: fixed)
  bool json = false;
  std::string output;  // empty: no file
  std::string force_csv;
  std::string from_rest_csv;  // main job: speeds promised and reached, for the figure
  CLI::App* cmd = nullptr;
};

// The command line's outputs that only some problems write.
const std::vector<SettingUse> kOutputUses = {{"from_rest_csv", {""}}};

// The options the chosen problem does not use: their defaults do not shape its output (left
// out of the provenance).
std::vector<std::string> UnusedOptionsOf(const OptimizeCliOptions& opt) {
  const SettingNames names{kOptimizeFlags};
  std::vector<std::string> unused;
  for (const std::string& field : UnusedOptimizeSettings(opt.settings)) {
    unused.push_back(names.Name(field));
  }
  for (const std::string& field : UnusedSettings(kOutputUses, opt.settings.problem)) {
    unused.push_back(names.Name(field));
  }
  return unused;
}

// --T0-range LO:HI as (T0_min, T0_max); (NaN, NaN) when not given. The library checks the
// numbers; this reads the syntax.
std::pair<double, double> ParseT0Range(const std::string& text) {
  if (text.empty()) return {kNaN, kNaN};
  const std::size_t colon = text.find(':');
  double lo = kNaN, hi = kNaN;
  try {
    std::size_t used_lo = 0, used_hi = 0;
    if (colon == std::string::npos) throw std::invalid_argument("no colon");
    lo = std::stod(text.substr(0, colon), &used_lo);
    hi = std::stod(text.substr(colon + 1), &used_hi);
    if (used_lo != colon || used_hi != text.size() - colon - 1) throw std::invalid_argument("");
  } catch (const std::exception&) {
    throw std::invalid_argument(
        fmt::format("--T0-range = {} is invalid: expected LO:HI, two numbers 0 < LO < HI", text));
  }
  if (!(lo > 0.0 && lo < hi && std::isfinite(hi))) {
    throw std::invalid_argument(
        fmt::format("--T0-range = {} is invalid: expected LO:HI, two numbers 0 < LO < HI", text));
  }
  return {lo, hi};
}

// The settings as the command line gives them: the flags given, the syntax of --T0-range and
// --starts, the from-rest options.
OptimizeSettings SettingsOf(const OptimizeCliOptions& opt) {
  OptimizeSettings s = opt.settings;
  s.given = GivenFields(*opt.cmd, kOptimizeFlags);
  if (s.Given("starts")) s.search.starts = opt.starts;
  if (s.problem == "reach") std::tie(s.T0_min, s.T0_max) = ParseT0Range(opt.T0_range);
  s.from_rest_starts = opt.from_rest.starts;
  s.reach_starts = opt.from_rest.reach_starts;
  s.reach = opt.from_rest.budgets;
  s.threads = opt.from_rest.threads;
  return s;
}

// The files asked for, opened before any work (a bad path fails at once) and committed
// when their content is complete; null: not asked for.
std::unique_ptr<AtomicFile> OpenIfAsked(const std::string& path, const char* option) {
  return path.empty() ? nullptr : std::make_unique<AtomicFile>(path, option);
}

int Run(const OptimizeCliOptions& opt) {
  const OptimizeSettings settings = SettingsOf(opt);
  const SettingNames names{kOptimizeFlags};
  RejectUnusedSettings(
      kOutputUses, settings.given, settings.problem,
      [&names](const std::string& problem) { return OptimizeProblemName(problem, names); }, names);
  OptimizeJobOptions job = OptimizeJobFrom(settings, names);
  job.on_stage = [](const std::string& stage) { ShowStage(stage); };
  RequireDistinctOutputs(
      {{opt.output, "-o"}, {opt.force_csv, "--force-csv"}, {opt.from_rest_csv, "--from-rest-csv"}});
  RequireOutputApartFromJson(opt.output, "-o", opt.json);
  RequireOutputApartFromJson(opt.force_csv, "--force-csv", opt.json);
  RequireOutputApartFromJson(opt.from_rest_csv, "--from-rest-csv", opt.json);
  const auto json_file = OpenIfAsked(opt.output, "-o");
  const auto force_csv = OpenIfAsked(opt.force_csv, "--force-csv");
  const auto from_rest_csv = OpenIfAsked(opt.from_rest_csv, "--from-rest-csv");

  const OptimizeJobResult result = RunOptimizeJob(job);
  const Provenance provenance = OutputProvenance(*opt.cmd, UnusedOptionsOf(opt));
  if (force_csv != nullptr) {
    force_csv->stream() << provenance.CommentLine();
    text::WriteForceCsv(RecommendedForcing(result), force_csv->stream());
    force_csv->Commit();
  }
  if (from_rest_csv != nullptr) {
    from_rest_csv->stream() << provenance.CommentLine();
    text::WriteFromRestCsv(std::get<MainJobResult>(result), from_rest_csv->stream());
    from_rest_csv->Commit();
  }
  nlohmann::json j = json::OptimizeJobJson(result);
  j["provenance"] = JsonProvenance(*opt.cmd, UnusedOptionsOf(opt)).Json();
  if (json_file != nullptr) {
    json_file->stream() << j.dump(2) << '\n';
    json_file->Commit();
  }
  if (opt.json) {
    fmt::print("{}\n", j.dump());
  } else {
    fmt::print("{}{}", text::OptimizeJobText(result),
               opt.output.empty() ? "" : fmt::format("\nwritten: {}\n", opt.output));
  }
  return 0;
}

// The gait asked for and the search of P1-P3: --bound, --rho-max/--stable, --max-time,
// --harmonics, the algorithms and their budgets.
void AddSearchOptions(CLI::App& cmd, OptimizeCliOptions& opt) {
  SearchRequest& search = opt.settings.search;
  AddSettings(cmd, search.gait, GaitBoundSettings(), kOptimizeFlags);
  CLI::Option* rho_max = cmd.get_option("--rho-max")->type_name(kFloatOrInf);
  cmd.add_flag_callback(
         "--stable", [&search] { search.gait.rho_max = 1.0; },
         "the same as --rho-max 1: stable orbits, up to marginal stability")
      ->excludes(rho_max);
  AddSettings(cmd, search, SearchSettings(), kOptimizeFlags);
  cmd.get_option("--max-time")->type_name(kFloatOrInf);
  cmd.add_option("--starts", opt.starts,
                 fmt::format("number of local polishes of the multistart, 1 to {} (default: 10 for "
                             "forcing, 20 for fourier)",
                             kMaxStarts));
}

// What is printed and written: --json, -o, --force-csv, --from-rest-csv.
void AddOutputOptions(CLI::App& cmd, OptimizeCliOptions& opt) {
  cmd.add_flag("--json", opt.json,
               "print one JSON object: status, I, v_mean, A, c, phi0, phi1, alpha, u, v_plus, "
               "x_min, x_max, stroke, clearance, active_constraints, binding, evaluations, "
               "algorithm, the margins and rho_max (+ coefficients for fourier, "
               "spectral_radius when the orbit exists, from_rest: the gait checked from rest; "
               "null where a quantity does not exist); --problem reach prints the reach object; "
               "the main job prints one object with paper, robust (with from_rest), reach, "
               "fastest, fastest_stable");
  cmd.add_option("-o,--output", opt.output,
                 "also write the JSON object (indented) to this file, atomically; nothing is "
                 "written without it")
      ->type_name("FILE");
  cmd.add_option("--force-csv", opt.force_csv,
                 "write the optimal force F(phi) over one period (phi = 0 at the impact, "
                 "columns phi,F) to this CSV file (main job: the robust gait's force; reach: the "
                 "winner's)")
      ->type_name("FILE");
  cmd.add_option("--from-rest-csv", opt.from_rest_csv,
                 "main job: write the robust gait's promised mean velocity and the attractors "
                 "reached from rest (robust gait and fastest motion from rest) to this CSV file "
                 "(columns gait,row,mean_velocity,fraction,period,impacts_right,impacts_left,"
                 "one_impact_orbit)")
      ->type_name("FILE");
}

}  // namespace

Command AddOptimizeCommand(CLI::App& app) {
  auto opt = std::make_shared<OptimizeCliOptions>();
  CLI::App* cmd = app.add_subcommand(
      "optimize",
      "The fastest gait (docs/model.md section 7) with the margins of a robust gait (section "
      "12), every gait checked from rest. Without --problem: the main job: the paper's problem "
      "(best phase at c = A = T0/2), the fastest robust gait with A + c <= T0 checked from "
      "rest, the fastest motion from rest (section 13), the exact optima without margins "
      "(valid, stable) for comparison, and which gait to build. With --problem: one problem. "
      "Prints a summary (or --json); -o also writes the JSON. Exit status 0 whenever the "
      "computation ran, valid gait found or not.");
  OptimizeSettings& settings = opt->settings;
  const SettingTable<OptimizeSettings>& table = OptimizeProblemSettings();
  AddSettings(*cmd, settings, table, kOptimizeFlags, {"problem"});
  cmd->get_option("--problem")
      ->transform(CLI::Transformer(
                      std::map<std::string, std::string>{
                          {"P1", "phase"}, {"P2", "forcing"}, {"P3", "fourier"}},
                      CLI::ignore_case)
                      .description(""))
      ->check(CLI::IsMember({"phase", "forcing", "fourier", "reach"}).description(""))
      ->type_name("phase|forcing|fourier|reach")  // the help and the completion show these
      ->description(cmd->get_option("--problem")->get_description() +
                    "; P1, P2 and P3 name the first three");
  AddSettings(*cmd, settings, table, kOptimizeFlags, {"A", "c"});
  AddParamsOptions(*cmd, settings.params, &settings.search.gait.margins);
  AddFromRestOptions(*cmd, opt->from_rest, true);
  AddDriveBudgetOptions(*cmd, opt->from_rest);
  AddSettings(*cmd, settings, table, kOptimizeFlags, {"alpha"});
  cmd->add_option("--T0-range", opt->T0_range,
                  "reach: the motor's frequency free, LO:HI: T0 = mu g/(omega^2 L) in [LO, HI] "
                  "(holding --T0), the force bound tied to T0, the speed in units of "
                  "sqrt(mu g L), v_mean/sqrt(T0), maximised (docs/reach.md, Frequency)")
      ->type_name("LO:HI");
  AddSettings(*cmd, settings, table, kOptimizeFlags, {"waveform", "pulse_levels"});
  cmd->get_option("--waveform")
      ->check(CLI::IsMember({"sine", "fourier", "pulse"}).description(""))
      ->type_name("sine|fourier|pulse");
  cmd->add_option("--band-levels", settings.band_levels,
                  "main job: the levels of the speed bands, fractions of the speed from rest in "
                  "(0, 1), comma-separated: how far T0, e and alpha move, each way, before the "
                  "mean speed from rest falls below each (docs/optimize.md)")
      ->delimiter(',')
      ->default_str("0.95");
  AddSearchOptions(*cmd, *opt);
  AddOutputOptions(*cmd, *opt);
  opt->cmd = cmd;
  AddProgressOptions(*cmd);
  SetExamples(*cmd, {{"the main job: the paper's problem, the fastest robust gait, "
                      "the fastest motion from rest (takes about a minute)",
                      "optimize -o optimum.json"},
                     {"P2 alone: the fastest gait with A + c <= T0 whose spectral "
                      "radius is at most 0.95",
                      "optimize --problem forcing --T0 1 --rho-max 0.95"}});
  return {
      cmd, [opt] { return RunNamingFlags(kOptimizeRenamedFields, [&] { return Run(*opt); }); }, {}};
}

}  // namespace capsubot::cli
