// capsubot design: a real robot in SI units; the inner mass (and motor frequency) of its
// fastest robust one-impact gait, with speed, power and cost of transport, and of the fastest
// motion reached from rest in each direction. The command line (and --config:
// capsubot/config/design_config.hpp) fills the options of the design job (library:
// capsubot/job/design_job.hpp), which does it in one call; its text and JSON are the report
// stage's.

#include <fmt/format.h>

#include <algorithm>
#include <cstdint>
#include <map>
#include <memory>
#include <nlohmann/json.hpp>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "capsubot/cli/attract_options.hpp"
#include "capsubot/cli/command.hpp"
#include "capsubot/cli/design_config_options.hpp"
#include "capsubot/cli/from_rest_options.hpp"
#include "capsubot/cli/help_format.hpp"
#include "capsubot/cli/progress.hpp"
#include "capsubot/cli/provenance.hpp"
#include "capsubot/cli/result_output.hpp"
#include "capsubot/cli/setting_options.hpp"
#include "capsubot/cli/shard_option.hpp"
#include "capsubot/cli/strict_values.hpp"
#include "capsubot/cluster/ranks.hpp"
#include "capsubot/io/io.hpp"
#include "capsubot/job/design_job.hpp"
#include "capsubot/job/design_settings.hpp"
#include "capsubot/report/design_json.hpp"
#include "capsubot/report/design_text.hpp"
#include "commands.hpp"
#include "design_flags.hpp"

namespace capsubot::cli {
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
  std::vector<double> band_levels = DesignOneMode{}.band_levels;  // the speed bands' levels
  DesignDriveChoice drive;  // --drive, --force-max, --harmonics, --pulse-levels
};

// The command line's outputs that only some runs write.
const std::vector<SettingUse> kOutputUses = {{"json", {"", "from-rest", "drive"}},
                                             {"output", {"", "from-rest", "grid", "drive"}},
                                             {"shard", {"grid"}},
                                             {"resume", {"grid"}}};

DesignRunChoice ChoiceOf(const DesignCliOptions& opt) {
  const std::string& drive = opt.drive.drive;  // never empty when given (UseStrictValues)
  return {drive.empty() ? std::nullopt : std::optional<std::string>(drive), !opt.grids.empty(),
          opt.part_b};
}

// The options the run does not use: their defaults do not shape its output.
std::vector<std::string> UnusedOptionsOf(const DesignCliOptions& opt) {
  const SettingNames names{kDesignFlags};
  std::vector<std::string> unused;
  for (const auto* uses : {&DesignSettingUses(), &kOutputUses}) {
    for (const std::string& field : UnusedSettings(*uses, ChoiceOf(opt).Run())) {
      unused.push_back(names.Name(field));
    }
  }
  return unused;
}

// An option the chosen run does not use would be silently ignored: refuse it, naming both.
void RejectUnusedOptions(const DesignCliOptions& opt, const CLI::App& cmd) {
  const SettingNames names{kDesignFlags};
  const auto run_name = [&names](const std::string& r) { return DesignRunName(r, names); };
  ChoiceOf(opt).RejectUnused(GivenFields(cmd, kDesignFlags), names, run_name, kOutputUses);
}

using Settings = DesignSettingTexts;

// `p` (a provenance of `cmd`) with --config FILE and the settings' flags as typed replaced by
// the value of every setting of the input (`settings`, BuildDesignInput), as flags in their
// place among the others (declaration order): the provenance names the robot itself (two
// contents of one file differ; `--g 9.81` typed or left to its default, `--m1 0.20` or
// `--m1 0.2` are alike), and it is the provenance of the same command given without the file.
Provenance WithSettings(Provenance p, const CLI::App& cmd, const DesignConfigOptions& config,
                        const Settings& settings) {
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
                           const Settings& settings) {
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

// Part (b) from the from-rest options shared with `optimize --problem reach`.
DesignFromRestPart FromRestPart(const FromRestCliOptions& cli) {
  DesignFromRestPart part;
  part.reach_starts = ParseStartGrid("--reach-starts", cli.reach_starts);
  part.from_rest_starts = ParseStartGrid("--from-rest-starts", cli.starts);
  part.reach_evaluations = cli.budgets.global_evaluations;
  part.reach_local_evaluations = cli.budgets.local_evaluations;
  part.reach_seconds = cli.budgets.max_seconds;
  part.threads = cli.threads;
  return part;
}

// The grid: its axes, and the file (-o, --shard, --resume, --threads) whose first line is the
// provenance of the robot and the grids.
DesignGridMode GridMode(const DesignCliOptions& opt, const CLI::App& cmd,
                        const std::vector<DesignGridAxis>& axes, const Settings& settings) {
  if (opt.output.empty()) {
    throw std::invalid_argument("output is missing: --grid writes its CSV to -o FILE");
  }
  DesignGridMode grid;
  grid.axes = axes;
  grid.comments.push_back(GridProvenance(opt, cmd, settings));
  grid.output = opt.output;
  if (!opt.shard.empty()) std::tie(grid.shard, grid.shards) = ParseShard(opt.shard);
  grid.resume = opt.resume;
  grid.threads = opt.from_rest.threads;
  return grid;
}

// The job's stages on the progress line, with the robots of part (a) and the evaluations of
// part (b) (capsubot/cli/progress.hpp); nothing when progress is not shown.
void ShowProgress(DesignJobOptions& options, DesignOneMode& one) {
  if (!ProgressShown()) return;
  auto stage = std::make_shared<std::string>();
  options.on_stage = [stage](const std::string& text) {
    *stage = text;
    ShowStage(text);
  };
  one.progress = CountProgress("robots");
  if (!one.from_rest) return;
  one.from_rest->progress = [stage](const std::string& step, std::int64_t done,
                                    std::int64_t total) {
    ShowStage(fmt::format("{}, {}", *stage, step),
              fmt::format("{} of at most {} from-rest evaluations", done, total));
  };
}

int RunGrid(const DesignCliOptions& opt, const CLI::App& cmd) {
  std::vector<DesignGridAxis> axes;
  for (const std::string& spec : opt.grids) axes.push_back(ParseDesignGridAxis(spec));
  Settings settings;
  DesignJobOptions options;
  options.input = BuildDesignInput(opt.config, axes, &settings);
  DesignGridMode grid = GridMode(opt, cmd, axes, settings);
  ProgressBar bar("points");
  grid.progress = GridProgress(bar);
  Ranks ranks;           // under mpirun: rank 0 runs the grid, the others compute blocks of points
  if (ranks.worker()) {  // rank 0 validates
    const DesignGridOptions blocks = DesignJobGrid(options.input, grid);
    return ranks.Serve(DesignGridBlocks(blocks), grid.threads);
  }
  grid.backend = ranks.backend();
  options.mode = std::move(grid);
  DesignJobResult r;
  try {
    r = RunDesignJob(options);
  } catch (const SweepResumableError& e) {
    throw WriteError(std::string(e.what()) + ": run the same command with --resume to continue");
  }
  if (ProgressShown()) fmt::print(stderr, "capsubot design: {}", text::DesignJobText(r));
  return 0;
}

// The fastest drive: its family, the motor's peak, the search's starts and budgets.
DesignDriveMode DriveMode(const DesignCliOptions& opt) {
  DesignDriveMode mode;
  DriveDesignOptions& d = mode.options;
  d.drive = DesignDriveFamily(opt.drive.drive, opt.drive.harmonics, opt.drive.pulse_levels,
                              SettingNames{kDesignFlags});
  d.force_max = opt.drive.force_max;
  d.effort = opt.from_rest.Effort();
  d.check = opt.from_rest.Check();
  return mode;
}

int Run(const DesignCliOptions& opt, const CLI::App& cmd) {
  RejectUnusedOptions(opt, cmd);
  if (!opt.grids.empty()) return RunGrid(opt, cmd);
  Settings settings;
  DesignJobOptions options;
  options.input = BuildDesignInput(opt.config, {}, &settings, opt.drive.drive.empty());
  if (!opt.drive.drive.empty()) {
    RequireDriveForceMax(opt.drive.force_max);
    options.mode = DriveMode(opt);
    if (ProgressShown()) options.on_stage = [](const std::string& text) { ShowStage(text); };
  } else {
    DesignOneMode one;
    if (opt.part_b) one.from_rest = FromRestPart(opt.from_rest);
    one.band_levels = opt.band_levels;
    ShowProgress(options, one);
    options.mode = std::move(one);
  }
  CheckResultOutput(opt.output);
  const DesignJobResult r = RunDesignJob(options);
  if (!opt.json) {
    WriteResult(opt.output, text::DesignJobText(r));
    return 0;
  }
  const Provenance provenance =
      WithSettings(JsonProvenance(cmd, UnusedOptionsOf(opt)), cmd, opt.config, settings);
  WriteResult(opt.output, JsonOutput(json::DesignJobJson(r), provenance));
  return 0;
}

// The options of the drive design (--drive and what sizes it).
void AddDriveOptions(CLI::App& cmd, DesignCliOptions& opt) {
  // The helps name the robot's ranges, which are the config stage's settings.
  static const FlagNames flags =
      WithDashedFlags({{"frequency_range", "--frequency-range"}, {"m2_range", "--m2-range"}},
                      DesignDriveSettings());
  AddSettings(cmd, opt.drive, DesignDriveSettings(), flags);
  cmd.get_option("--drive")->check(CLI::IsMember({"sine", "fourier", "pulse"}));
  AddDriveBudgetOptions(cmd, opt.from_rest);
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
  const DesignFromRestPart defaults;
  opt->from_rest.budgets.global_evaluations = defaults.reach_evaluations;
  opt->from_rest.budgets.local_evaluations = defaults.reach_local_evaluations;
  opt->from_rest.budgets.max_seconds = defaults.reach_seconds;
  AddFromRestOptions(*cmd, opt->from_rest, true);
  cmd->add_flag("--from-rest", opt->part_b,
                "also find the fastest motion reached from rest in each direction (part b, "
                "simulated: a few seconds; sized by the options below)");
  AddDriveOptions(*cmd, *opt);
  cmd->add_option("--band-levels", opt->band_levels,
                  "the levels of the gait's speed bands, fractions of the speed from rest in "
                  "(0, 1), comma-separated: how far mu, e and m2 move, each way, before the mean "
                  "speed from rest falls below each (docs/design.md)")
      ->delimiter(',')
      ->default_str("0.95");
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
                  "the design (with --json its JSON object) written to FILE instead of standard "
                  "output, atomically; with --grid its CSV file (built as FILE.partial with a "
                  "checkpoint, renamed at the end); - for standard output")
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
  return {cmd, [opt, cmd] { return RunNamingFlags(kDesignFlags, [&] { return Run(*opt, *cmd); }); },
          [opt] { return !opt->grids.empty(); }};
}

}  // namespace capsubot::cli
