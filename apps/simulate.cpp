// capsubot simulate: the exact event-driven simulation (docs/model.md sections 3 and 10), from a
// given state or from right after the impact of the analytic orbit (--from-orbit).

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include "capsubot/cli/force_options.hpp"
#include "capsubot/cli/help_format.hpp"
#include "capsubot/cli/progress.hpp"
#include "capsubot/cli/provenance.hpp"
#include "capsubot/cli/result_output.hpp"
#include "capsubot/cli/setting_options.hpp"
#include "capsubot/io/io.hpp"
#include "capsubot/job/simulate_job.hpp"
#include "capsubot/job/simulate_settings.hpp"
#include "capsubot/job/simulate_start_spec.hpp"
#include "capsubot/model/limits.hpp"
#include "capsubot/report/simulate_csv.hpp"
#include "capsubot/report/simulate_text.hpp"
#include "capsubot/report/simulation_json.hpp"
#include "commands.hpp"

namespace capsubot::cli {
namespace {

// Runs of at least this many periods (about 0.2 s) show their progress (capsubot/cli/progress.hpp).
constexpr double kProgressPeriods = 1e5;

struct SimulateOptions {
  ForcingOptions forcing;
  SimulateJobOptions job;  // its params, run settings and trajectory grid
  SimulateFromState state;
  bool from_orbit = false;
  std::string events;
  std::string trajectory;
  ResultOutput output;
  CLI::Option* alpha_option = nullptr;
  CLI::Option* x0_option = nullptr;
  CLI::Option* u0_option = nullptr;
  CLI::Option* v0_option = nullptr;
};

// The flags of the settings the help names. The job's messages name only the start from the
// orbit by its flag (the run's settings by their fields, as the simulator's rules do).
const FlagNames kSettingFlags = DashedFlags(
    "y0 periods transient chatter_velocity max_events_per_period "
    "samples_per_period trajectory");
const FlagNames kMessageFlags = {{"from_orbit", "--from-orbit"}};

// Streams events and samples to the CSV files as they come (text::SimulateCsv), and draws the
// progress bar when given one.
class CsvProgress : public text::SimulateCsv {
 public:
  CsvProgress(AtomicFile* events, AtomicFile* trajectory, ProgressBar* bar, double periods)
      : SimulateCsv(events != nullptr ? &events->stream() : nullptr,
                    trajectory != nullptr ? &trajectory->stream() : nullptr),
        bar_(bar),
        periods_(periods) {}
  void OnPeriods(std::int64_t periods) override {
    if (bar_ == nullptr) return;
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start_;
    bar_->Update(static_cast<double>(periods), periods_, elapsed.count());
  }
  ~CsvProgress() override { Finish(); }
  CsvProgress(const CsvProgress&) = delete;
  CsvProgress& operator=(const CsvProgress&) = delete;
  // The bar's last line (100 %), however the run ended (also when it threw).
  void Finish() {
    if (bar_ != nullptr) OnPeriods(static_cast<std::int64_t>(std::ceil(periods_)));
    bar_ = nullptr;
  }

 private:
  ProgressBar* bar_;
  double periods_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// The start the options give: the analytic orbit (--from-orbit; CLI11 refuses --alpha, --x0,
// --u0, --v0 with it) or the state of --alpha, --x0, --u0, --v0.
SimulateStart Start(const SimulateOptions& opt) {
  const auto part = [](const CLI::Option* option, double value) {
    return option->count() > 0 ? std::optional<double>(value) : std::nullopt;
  };
  const SimulateStartSpec spec{part(opt.alpha_option, opt.state.alpha),
                               part(opt.x0_option, opt.state.x0), part(opt.u0_option, opt.state.u0),
                               part(opt.v0_option, opt.state.v0)};
  static const FlagNames kStartFlags = DashedFlags("alpha x0 u0 v0 from_orbit");
  return spec.Build(opt.from_orbit, "--from-orbit", kStartFlags);
}

int Run(const SimulateOptions& opt, const CLI::App& cmd) {
  SimulateJobOptions o = opt.job;
  o.forcing = opt.forcing.Build();
  o.start = Start(opt);
  o.trajectory = !opt.trajectory.empty();
  if (o.trajectory) {  // the job's rule, in the names of the options, before any file
    RequireTrajectoryRows(o.sim.transient + o.sim.periods,
                          static_cast<double>(o.samples_per_period), "--samples-per-period",
                          "--transient + --periods");
  }
  o.Validate();
  RequireDistinctOutputs(
      {{opt.events, "--events"}, {opt.trajectory, "--trajectory"}, {opt.output.path, "-o"}});
  CheckResultOutput(opt.output.path);
  // Each file starts with its provenance: the events do not depend on the trajectory's grid.
  std::unique_ptr<AtomicFile> events_file, trajectory_file;
  if (!opt.events.empty()) {
    events_file = std::make_unique<AtomicFile>(opt.events, "--events");
    events_file->stream() << OutputProvenance(cmd, {"--samples-per-period"}).CommentLine();
  }
  if (o.trajectory) {
    trajectory_file = std::make_unique<AtomicFile>(opt.trajectory, "--trajectory");
    trajectory_file->stream() << OutputProvenance(cmd).CommentLine();
  }
  std::optional<ProgressBar> bar;
  if (o.sim.periods >= kProgressPeriods && ProgressShown()) bar.emplace("periods");
  CsvProgress observer(events_file.get(), trajectory_file.get(), bar ? &*bar : nullptr,
                       o.sim.periods);
  if (events_file || trajectory_file || bar) o.observer = &observer;
  const SimulateJobResult r = RunSimulateJob(o);
  observer.Finish();
  if (events_file) events_file->Commit();
  if (trajectory_file) trajectory_file->Commit();
  for (const std::string& note : text::SimulateJobNotes(r)) {
    fmt::print(stderr, "capsubot simulate: note: {}\n", note);
  }
  opt.output.Write(cmd, r, json::SimulateJobJson, text::SimulateJobText);
  return 0;
}

}  // namespace

Command AddSimulateCommand(CLI::App& app) {
  auto opt = std::make_shared<SimulateOptions>();
  CLI::App* cmd = app.add_subcommand(
      "simulate",
      "Exact event-driven simulation of the full non-smooth dynamics (docs/model.md sections 3 and "
      "10): rest, forward and backward slide; impacts on both walls, stops and break-aways "
      "located to ~1e-13 in phase. Independent of the analytic orbit: use it to confirm an "
      "orbit of `solve`. The force is F(phi) = A sin(phi + phi0) + c with phi = 0 at the start.");
  AddForcingOptions(*cmd, opt->forcing);
  AddParamsOptions(*cmd, opt->job.params);
  opt->alpha_option = cmd->add_option("--alpha", opt->state.alpha,
                                      "mass ratio m2/(m1+m2), 0 < alpha < 1 (required unless "
                                      "--from-orbit)");
  opt->x0_option = cmd->add_option("--x0", opt->state.x0,
                                   "initial position of the inner body, 0 <= x0 <= 1 (walls at "
                                   "0 and 1, units of L)");
  opt->u0_option = cmd->add_option("--u0", opt->state.u0,
                                   "initial relative velocity dx/dphi (units of omega L)");
  opt->v0_option =
      cmd->add_option("--v0", opt->state.v0, "initial capsule velocity (units of omega L)");
  const SettingTable<SimOptions>& run = SimulateRunSettings();
  AddSettings(*cmd, opt->job.sim, run, kSettingFlags, {"y0"});
  cmd->add_flag("--from-orbit", opt->from_orbit,
                "start right after the impact of the analytic one-impact orbit for these A, c, "
                "phi0, T0, e (x = 1, u = -e u, v = v_plus) with its mass ratio alpha")
      ->excludes(opt->alpha_option)
      ->excludes(opt->x0_option)
      ->excludes(opt->u0_option)
      ->excludes(opt->v0_option);
  AddSettings(*cmd, opt->job.sim, run, kSettingFlags, {"periods", "transient"});
  opt->output.Add(*cmd,
                  "print one JSON object: status, final state phi, x, u, v, y, mode, and over "
                  "the recorded periods displacement, v_mean, impacts_right, impacts_left, "
                  "stops, breakaways, sticks, releases, events, energy {motor_work, "
                  "motor_work_positive, friction_loss, impact_loss}; alpha; transient (the same "
                  "figures over the transient, with --transient); orbit (the analytic orbit, "
                  "with --from-orbit); provenance",
                  "the run's summary");
  cmd->add_option("--events", opt->events,
                  "write every event to this CSV file: phase, kind, x, u, v, y (state right "
                  "after the event), u_before, v_before, mode")
      ->type_name("FILE");
  CLI::Option* trajectory =
      cmd->add_option(
             "--trajectory", opt->trajectory,
             "write the state phi, x, u, v, y, mode sampled on a grid to this CSV file (at most "
             "10000000 rows: samples per period x (transient + periods) + 1)")
          ->type_name("FILE");
  AddSettings(*cmd, opt->job, SimulateJobSettings(), kSettingFlags);
  cmd->get_option("--samples-per-period")->needs(trajectory);
  AddSettings(*cmd, opt->job.sim, run, kSettingFlags,
              {"chatter_velocity", "max_events_per_period"});
  AddProgressOptions(*cmd);
  SetExamples(*cmd, {{"that orbit simulated from right after its impact for 10 "
                      "periods: it returns to its start",
                      "simulate --A 0.05 --c 0.02 --phi0 -2.842 --T0 0.1 --e 0.5 "
                      "--from-orbit --periods 10"},
                     {"what a robot started at rest settles into after 2000 periods",
                      "simulate --A 0.08 --c 0.015 --phi0 0 --T0 0.1 --e 1 --alpha "
                      "0.3 --x0 0.5 --u0 0 --v0 0 --transient 2000 --periods 2"}});
  return {cmd,
          [opt, cmd] { return RunNamingFlags(kMessageFlags, [&] { return Run(*opt, *cmd); }); },
          {}};
}

}  // namespace capsubot::cli
