// capsubot simulate: the exact event-driven simulation (docs/model.md sections 3 and 10), from a
// given state or from right after the impact of the analytic orbit (--from-orbit).

#include <fmt/format.h>

#include <cmath>
#include <memory>
#include <optional>

#include "capsubot/io.hpp"
#include "capsubot/orbit_start.hpp"
#include "capsubot/simulator.hpp"
#include "capsubot/validity.hpp"
#include "commands.hpp"
#include "report.hpp"

namespace capsubot::app {
namespace {

struct SimulateOptions {
  ForcingOptions forcing;
  Params params;
  SimOptions sim;
  bool from_orbit = false;
  bool json = false;
  std::string events;
  std::string trajectory;
  int samples_per_period = 100;
  CLI::Option* alpha_option = nullptr;
  CLI::Option* x0_option = nullptr;
  CLI::Option* u0_option = nullptr;
  CLI::Option* v0_option = nullptr;
};

// Streams events and samples to the CSV files as they come (no storage of the run).
class CsvObserver : public SimObserver {
 public:
  CsvObserver(AtomicFile* events, AtomicFile* trajectory)
      : events_(events), trajectory_(trajectory) {
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

 private:
  AtomicFile* events_;
  AtomicFile* trajectory_;
};

// The figures of a span of the run (the record, or the transient) as JSON keys of `j`.
void AddTallyJson(nlohmann::json& j, const SimTally& t) {
  j["displacement"] = t.displacement;
  j["v_mean"] = t.v_mean;
  j["impacts_right"] = t.impacts_right;
  j["impacts_left"] = t.impacts_left;
  j["stops"] = t.stops;
  j["breakaways"] = t.breakaways;
  j["sticks"] = t.sticks;
  j["releases"] = t.releases;
  j["events"] = t.events;
  j["energy"] = {{"motor_work", t.energy.motor_work},
                 {"motor_work_positive", t.energy.motor_work_positive},
                 {"friction_loss", t.energy.friction_loss},
                 {"impact_loss", t.energy.impact_loss}};
}

int Run(SimulateOptions& opt) {
  opt.params.Validate();
  const Forcing forcing = opt.forcing.Build();
  const bool has_state =
      opt.x0_option->count() + opt.u0_option->count() + opt.v0_option->count() > 0;
  SimOptions sim = opt.sim;
  std::optional<Solution> orbit;
  if (opt.from_orbit) {
    if (has_state || opt.alpha_option->count() > 0) {
      throw std::invalid_argument(
          "--from-orbit takes the state and alpha from the analytic orbit: do not give "
          "--alpha, --x0, --u0 or --v0 with it");
    }
    orbit = Solve(forcing, opt.params);
    const Orbit& o = orbit->orbit;
    if (!o.ok()) {
      throw std::invalid_argument(
          fmt::format("--from-orbit: no one-impact orbit exists for this force, T0 and e ({})",
                      StatusName(o.status)));
    }
    if (!orbit->validity.valid()) {
      std::string names;
      for (const auto& n : orbit->validity.ViolationNames())
        names += (names.empty() ? "" : ", ") + n;
      fmt::print(stderr, "capsubot simulate: note: the analytic orbit is not valid ({})\n", names);
    }
    const SimOptions start = StartAfterImpact(o);
    sim.alpha = start.alpha;
    sim.x0 = start.x0;
    sim.u0 = start.u0;
    sim.v0 = start.v0;
  } else {
    if (opt.alpha_option->count() == 0) {
      throw std::invalid_argument(
          "option --alpha is missing: give the mass ratio (or --from-orbit)");
    }
    if (opt.x0_option->count() == 0 || opt.u0_option->count() == 0 || opt.v0_option->count() == 0) {
      throw std::invalid_argument(
          "the initial state is missing: give all of --x0, --u0, --v0 (or --from-orbit)");
    }
  }
  if (opt.samples_per_period < 1) {
    throw std::invalid_argument(fmt::format(
        "--samples-per-period = {} is invalid: expected at least 1", opt.samples_per_period));
  }
  if (!opt.trajectory.empty()) sim.sample_step = kTau / opt.samples_per_period;
  sim.energy = true;  // a few hundred nanoseconds per period: nothing for one run
  sim.Validate();

  std::unique_ptr<AtomicFile> events_file, trajectory_file;
  if (!opt.events.empty()) events_file = std::make_unique<AtomicFile>(opt.events, "--events");
  if (!opt.trajectory.empty()) {
    trajectory_file = std::make_unique<AtomicFile>(opt.trajectory, "--trajectory");
  }
  CsvObserver observer(events_file.get(), trajectory_file.get());
  const bool observe = events_file || trajectory_file;
  const SimResult r = Simulate(forcing, opt.params, sim, observe ? &observer : nullptr);
  if (events_file) events_file->Commit();
  if (trajectory_file) trajectory_file->Commit();
  if (r.status == SimStatus::kEventLimit) {
    fmt::print(stderr, "capsubot simulate: note: stopped early: {}\n", r.message);
  }

  const SimState& f = r.final_state;
  if (opt.json) {
    nlohmann::json j;
    j["status"] = SimStatusName(r.status);
    j["message"] = r.message;
    j["alpha"] = sim.alpha;
    j["phi"] = f.phi;
    j["x"] = f.x;
    j["u"] = f.u;
    j["v"] = f.v;
    j["y"] = f.y;
    j["mode"] = SimModeName(f.mode);
    AddTallyJson(j, r);
    if (sim.transient > 0.0) {
      nlohmann::json t;
      t["periods"] = sim.transient;
      AddTallyJson(t, r.transient);
      j["transient"] = t;
    }
    if (orbit) j["orbit"] = SolutionJson(*orbit);
    fmt::print("{}\n", j.dump());
    return 0;
  }
  std::string t = "event-driven simulation\n";
  t += fmt::format("  force            {}\n", ForceFormula(forcing));
  t += fmt::format("  model            T0 = {:g}, e = {:g}, alpha = {:.10g}\n", opt.params.T0,
                   opt.params.e, sim.alpha);
  t += fmt::format("  start            x = {:.10g}, u = {:.10g}, v = {:.10g}{}\n", sim.x0, sim.u0,
                   sim.v0, opt.from_orbit ? "   (right after the analytic orbit's impact)" : "");
  t += fmt::format("  status           {}   (phase {:.10g} = {:.6g} periods)\n",
                   SimStatusName(r.status), f.phi, f.phi / kTau);
  if (sim.transient > 0.0) {
    t += fmt::format(
        "  transient        {:g} periods: displacement {:.10g}, mean velocity {:.10g}, {} right "
        "and {} left impacts (not in the figures below)\n",
        sim.transient, r.transient.displacement, r.transient.v_mean, r.transient.impacts_right,
        r.transient.impacts_left);
  }
  t += fmt::format("  final state      x = {:.10g}, u = {:.10g}, v = {:.10g}, y = {:.10g} ({})\n",
                   f.x, f.u, f.v, f.y, SimModeName(f.mode));
  t += fmt::format("  displacement     {:.10g}   (L)\n", r.displacement);
  t += fmt::format("  mean velocity    {:.10g}   (omega L)", r.v_mean);
  if (orbit) t += fmt::format("   analytic: {:.10g}", orbit->orbit.v_mean);
  t += "\n";
  t += fmt::format("  events           {} right impacts, {} left impacts, {} stops, {} break-aways",
                   r.impacts_right, r.impacts_left, r.stops, r.breakaways);
  if (r.sticks + r.releases > 0) {
    t += fmt::format(", {} sticks on a wall (chattering), {} releases", r.sticks, r.releases);
  }
  t += "\n";
  const Energy& en = r.energy;
  t += fmt::format(
      "  energy           motor work {:.10g} (positive part {:.10g}); losses: friction "
      "{:.10g}, impacts {:.10g}   ((m1+m2) omega^2 L^2)\n",
      en.motor_work, en.motor_work_positive, en.friction_loss, en.impact_loss);
  fmt::print("{}", t);
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
  AddParamsOptions(*cmd, opt->params, false);
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
                "phi0, T0, e (x = 1, u = -e u, v = v_plus) with its mass ratio alpha");
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
                "transient, with --transient); orbit (the analytic orbit, with --from-orbit)");
  cmd->add_option("--events", opt->events,
                  "write every event to this CSV file: phase, kind, x, u, v, y (state right "
                  "after the event), u_before, v_before, mode");
  cmd->add_option("--trajectory", opt->trajectory,
                  "write the state phi, x, u, v, y, mode sampled on a grid to this CSV file");
  cmd->add_option("--samples-per-period", opt->samples_per_period,
                  "grid of --trajectory: samples per forcing period")
      ->capture_default_str();
  cmd->add_option("--chatter-velocity", opt->sim.chatter_velocity,
                  "an impact slower than this (omega L) with the inner body pushed into the "
                  "wall ends a chattering sequence: the body then rests on the wall")
      ->capture_default_str();
  cmd->add_option("--max-events-per-period", opt->sim.max_events_per_period,
                  "work bound: the run stops (status event_limit) after this many events per "
                  "period")
      ->capture_default_str();
  return {cmd, [opt] { return Run(*opt); }};
}

}  // namespace capsubot::app
