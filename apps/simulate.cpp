// capsubot simulate: the exact event-driven simulation (docs/model.md sections 3 and 10), from a
// given state or from right after the impact of the analytic orbit (--from-orbit).

#include <fmt/format.h>

#include <chrono>
#include <cmath>
#include <memory>
#include <optional>
#include <string>

#include "capsubot/io/io.hpp"
#include "capsubot/job/simulate_job.hpp"
#include "capsubot/model/limits.hpp"
#include "capsubot/report/simulate_text.hpp"
#include "capsubot/report/simulation_json.hpp"
#include "commands.hpp"
#include "help_format.hpp"
#include "progress.hpp"
#include "provenance.hpp"
#include "result_output.hpp"

namespace capsubot::app {
namespace {

// Runs of at least this many periods (about 0.2 s) show their progress (progress.hpp).
constexpr double kProgressPeriods = 1e5;

struct SimulateOptions {
  ForcingOptions forcing;
  Params params;
  SimOptions sim;
  bool from_orbit = false;
  bool json = false;
  std::string events;
  std::string trajectory;
  std::string output;  // -o: the text or JSON printed; empty: standard output
  int samples_per_period = static_cast<int>(SimulateJobOptions{}.samples_per_period);
  CLI::Option* alpha_option = nullptr;
  CLI::Option* x0_option = nullptr;
  CLI::Option* u0_option = nullptr;
  CLI::Option* v0_option = nullptr;
};

// Streams events and samples to the CSV files as they come (no storage of the run), and
// draws the progress bar when given one.
class CsvObserver : public SimObserver {
 public:
  CsvObserver(AtomicFile* events, AtomicFile* trajectory, ProgressBar* bar, double periods)
      : events_(events), trajectory_(trajectory), bar_(bar), periods_(periods) {
    if (events_ != nullptr) events_->stream() << "phase,kind,x,u,v,y,u_before,v_before,mode\n";
    if (trajectory_ != nullptr) trajectory_->stream() << "phi,x,u,v,y,mode\n";
  }
  void OnEvent(const SimEvent& e) override {
    if (events_ == nullptr) return;
    const SimState& s = e.after;
    events_->stream() << FormatNumber(s.phi) << ',' << EventKindName(e.kind) << ','
                      << FormatNumber(s.x) << ',' << FormatNumber(s.u) << ',' << FormatNumber(s.v)
                      << ',' << FormatNumber(s.y) << ',' << FormatNumber(e.u_before) << ','
                      << FormatNumber(e.v_before) << ',' << SimModeName(s.mode) << '\n';
  }
  void OnSample(const SimState& s) override {
    if (trajectory_ == nullptr) return;
    trajectory_->stream() << FormatNumber(s.phi) << ',' << FormatNumber(s.x) << ','
                          << FormatNumber(s.u) << ',' << FormatNumber(s.v) << ','
                          << FormatNumber(s.y) << ',' << SimModeName(s.mode) << '\n';
  }
  void OnPeriods(std::int64_t periods) override {
    if (bar_ == nullptr) return;
    const std::chrono::duration<double> elapsed = std::chrono::steady_clock::now() - start_;
    bar_->Update(static_cast<double>(periods), periods_, elapsed.count());
  }
  ~CsvObserver() override { Finish(); }
  CsvObserver(const CsvObserver&) = delete;
  CsvObserver& operator=(const CsvObserver&) = delete;
  // The bar's last line (100 %), however the run ended (also when it threw).
  void Finish() {
    if (bar_ != nullptr) OnPeriods(static_cast<std::int64_t>(std::ceil(periods_)));
    bar_ = nullptr;
  }

 private:
  AtomicFile* events_;
  AtomicFile* trajectory_;
  ProgressBar* bar_;
  double periods_;
  std::chrono::steady_clock::time_point start_ = std::chrono::steady_clock::now();
};

// The start the options give: the analytic orbit (--from-orbit; CLI11 refuses --alpha, --x0,
// --u0, --v0 with it) or the state of --alpha, --x0, --u0, --v0.
SimulateStart Start(const SimulateOptions& opt) {
  if (opt.from_orbit) return SimulateFromOrbit{};
  if (opt.alpha_option->count() == 0) {
    throw std::invalid_argument("option --alpha is missing: give the mass ratio (or --from-orbit)");
  }
  if (opt.x0_option->count() == 0 || opt.u0_option->count() == 0 || opt.v0_option->count() == 0) {
    throw std::invalid_argument(
        "the initial state is missing: give all of --x0, --u0, --v0 (or --from-orbit)");
  }
  return SimulateFromState{opt.sim.alpha, opt.sim.x0, opt.sim.u0, opt.sim.v0};
}

// The notes on stderr: an analytic orbit started from that is not valid, a run stopped early.
void PrintNotes(const SimulateJobResult& r) {
  if (r.orbit && !r.orbit->validity.valid()) {
    std::string names;
    for (const auto& n : r.orbit->validity.ViolationNames()) {
      names += (names.empty() ? "" : ", ") + n;
    }
    fmt::print(stderr, "capsubot simulate: note: the analytic orbit is not valid ({})\n", names);
  }
  if (r.run.status == SimStatus::kEventLimit) {
    fmt::print(stderr, "capsubot simulate: note: stopped early: {}\n", r.run.message);
  }
}

int Run(const SimulateOptions& opt, const CLI::App& cmd) {
  SimulateJobOptions o;
  o.params = opt.params;
  o.forcing = opt.forcing.Build();
  o.start = Start(opt);
  o.sim = opt.sim;
  o.trajectory = !opt.trajectory.empty();
  o.samples_per_period = opt.samples_per_period;
  if (o.trajectory) {  // the job's rule, in the names of the options, before any file
    RequireTrajectoryRows(o.sim.transient + o.sim.periods, opt.samples_per_period,
                          "--samples-per-period", "--transient + --periods");
  }
  o.Validate();
  RequireDistinctOutputs(
      {{opt.events, "--events"}, {opt.trajectory, "--trajectory"}, {opt.output, "-o"}});
  CheckResultOutput(opt.output);
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
  CsvObserver observer(events_file.get(), trajectory_file.get(), bar ? &*bar : nullptr,
                       o.sim.periods);
  if (events_file || trajectory_file || bar) o.observer = &observer;
  const SimulateJobResult r = RunSimulateJob(o);
  observer.Finish();
  if (events_file) events_file->Commit();
  if (trajectory_file) trajectory_file->Commit();
  PrintNotes(r);
  WriteResult(opt.output, opt.json ? JsonOutput(json::SimulateJobJson(r), JsonProvenance(cmd))
                                   : text::SimulateJobText(r));
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
  AddParamsOptions(*cmd, opt->params);
  opt->alpha_option = cmd->add_option("--alpha", opt->sim.alpha,
                                      "mass ratio m2/(m1+m2), 0 < alpha < 1 (required unless "
                                      "--from-orbit)");
  opt->x0_option = cmd->add_option("--x0", opt->sim.x0,
                                   "initial position of the inner body, 0 <= x0 <= 1 (walls at "
                                   "0 and 1, units of L)");
  opt->u0_option =
      cmd->add_option("--u0", opt->sim.u0, "initial relative velocity dx/dphi (units of omega L)");
  opt->v0_option =
      cmd->add_option("--v0", opt->sim.v0, "initial capsule velocity (units of omega L)");
  cmd->add_option("--y0", opt->sim.y0, "initial capsule position (units of L)")
      ->capture_default_str();
  cmd->add_flag("--from-orbit", opt->from_orbit,
                "start right after the impact of the analytic one-impact orbit for these A, c, "
                "phi0, T0, e (x = 1, u = -e u, v = v_plus) with its mass ratio alpha")
      ->excludes(opt->alpha_option)
      ->excludes(opt->x0_option)
      ->excludes(opt->u0_option)
      ->excludes(opt->v0_option);
  cmd->add_option("--periods", opt->sim.periods,
                  "forcing periods (2 pi each) recorded after the transient, 0 < N <= 1e8")
      ->capture_default_str();
  cmd->add_option("--transient", opt->sim.transient,
                  "forcing periods run first and reported apart (JSON \"transient\"): the "
                  "counts, v_mean and energy are over the --periods after it, 0 <= N <= 1e8")
      ->capture_default_str();
  cmd->add_flag("--json", opt->json,
                "print one JSON object: status, final state phi, x, u, v, y, mode, and over the "
                "recorded periods displacement, v_mean, impacts_right, impacts_left, stops, "
                "breakaways, sticks, releases, events, energy {motor_work, motor_work_positive, "
                "friction_loss, impact_loss}; alpha; transient (the same figures over the "
                "transient, with --transient); orbit (the analytic orbit, with --from-orbit); "
                "provenance");
  AddResultOutputOption(*cmd, opt->output, "the run's summary");
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
  Bounded(cmd->add_option("--samples-per-period", opt->samples_per_period,
                          "grid of --trajectory: samples per forcing period"),
          1, kMaxSamplesPerPeriod)
      ->capture_default_str()
      ->needs(trajectory);
  cmd->add_option("--chatter-velocity", opt->sim.chatter_velocity,
                  "an impact slower than this (omega L) with the inner body pushed into the "
                  "wall ends a chattering sequence: the body then rests on the wall")
      ->capture_default_str();
  Bounded(cmd->add_option("--max-events-per-period", opt->sim.max_events_per_period,
                          "work bound: the run stops (status event_limit) after this many "
                          "events per period"),
          10, kMaxEventsPerPeriod)
      ->capture_default_str();
  AddProgressOptions(*cmd);
  SetExamples(*cmd, {{"that orbit simulated from right after its impact for 10 "
                      "periods: it returns to its start",
                      "simulate --A 0.05 --c 0.02 --phi0 -2.842 --T0 0.1 --e 0.5 "
                      "--from-orbit --periods 10"},
                     {"what a robot started at rest settles into after 2000 periods",
                      "simulate --A 0.08 --c 0.015 --phi0 0 --T0 0.1 --e 1 --alpha "
                      "0.3 --x0 0.5 --u0 0 --v0 0 --transient 2000 --periods 2"}});
  // The job names the start from the orbit by its field: the message names the flag.
  static const FlagNames kFlags = {{"from_orbit", "--from-orbit"}};
  return {cmd, [opt, cmd] { return RunNamingFlags(kFlags, [&] { return Run(*opt, *cmd); }); }, {}};
}

}  // namespace capsubot::app
