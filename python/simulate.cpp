// simulate: the exact event-driven simulation (docs/model.md sections 3 and 10), as
// `capsubot simulate --json`, with the events and a sampled trajectory as NumPy arrays.

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "capsubot/job/simulate_job.hpp"
#include "capsubot/job/simulate_start_spec.hpp"
#include "capsubot/model/limits.hpp"
#include "capsubot/report/simulation_json.hpp"

namespace capsubot::python {
namespace {

// States in columns (the trajectory, or the states right after the events).
struct StateColumns {
  std::vector<double> phi, x, u, v, y;
  std::vector<SimMode> mode;

  void Add(const SimState& s) {
    phi.push_back(s.phi);
    x.push_back(s.x);
    u.push_back(s.u);
    v.push_back(s.v);
    y.push_back(s.y);
    mode.push_back(s.mode);
  }
};

// Thrown when the event table would pass kMaxTrajectoryRows rows (it is held in memory).
struct TableFull {};

// Collects what the command line writes to --events and --trajectory, and checks for Python
// signals as the run goes (with the check of the call that runs it, Watch).
class TableObserver : public SimObserver {
 public:
  TableObserver(bool events, bool samples) : events_(events), samples_(samples) {}
  // The signal check of the run being observed; nullptr: none.
  void Watch(SignalCheck* check) { check_ = check; }
  void OnEvent(const SimEvent& e) override {
    Poll();
    if (!events_) return;
    if (static_cast<std::int64_t>(kind.size()) >= kMaxTrajectoryRows) throw TableFull();
    kind.push_back(e.kind);
    after.Add(e.after);
    u_before.push_back(e.u_before);
    v_before.push_back(e.v_before);
  }
  void OnSample(const SimState& s) override {
    Poll();
    if (samples_) samples.Add(s);
  }
  void OnPeriods(std::int64_t) override { Poll(); }

  std::vector<EventKind> kind;
  StateColumns after;
  std::vector<double> u_before, v_before;
  StateColumns samples;

 private:
  void Poll() {
    if (check_ != nullptr) (*check_)();
  }

  bool events_, samples_;
  SignalCheck* check_ = nullptr;
};

py::array_t<double> Column(const std::vector<double>& values) {
  return py::array_t<double>(static_cast<py::ssize_t>(values.size()), values.data());
}

// An array of names ("impact_right", ...) for enum values: the distinct names indexed by codes.
template <typename Enum>
py::array NameColumn(const std::vector<Enum>& values, const char* (*name)(Enum)) {
  std::vector<Enum> distinct;
  py::array_t<std::int64_t> codes(static_cast<py::ssize_t>(values.size()));
  std::int64_t* code = codes.mutable_data();
  for (std::size_t i = 0; i < values.size(); ++i) {
    const auto it = std::find(distinct.begin(), distinct.end(), values[i]);
    code[i] = it - distinct.begin();
    if (it == distinct.end()) distinct.push_back(values[i]);
  }
  py::list names;
  for (Enum value : distinct) names.append(name(value));
  const py::module_ np = py::module_::import("numpy");
  return np.attr("asarray")(names, py::arg("dtype") = "str")[codes];
}

py::dict StateDict(const StateColumns& s, const char* phase_key) {
  py::dict d;
  d[phase_key] = Column(s.phi);
  d["x"] = Column(s.x);
  d["u"] = Column(s.u);
  d["v"] = Column(s.v);
  d["y"] = Column(s.y);
  d["mode"] = NameColumn(s.mode, &SimModeName);
  return d;
}

// The --events table: phase, kind, x, u, v, y, u_before, v_before, mode.
py::dict EventTable(const TableObserver& o) {
  py::dict d = StateDict(o.after, "phase");
  d["kind"] = NameColumn(o.kind, &EventKindName);
  d["u_before"] = Column(o.u_before);
  d["v_before"] = Column(o.v_before);
  return d;
}

py::dict Simulate(std::optional<double> A, std::optional<double> c, std::optional<double> phi0,
                  std::optional<std::vector<double>> cos, std::optional<std::vector<double>> sin,
                  std::optional<std::string> waveform, std::optional<std::vector<double>> levels,
                  std::optional<std::vector<double>> switches, double T0, double e,
                  std::optional<double> alpha, std::optional<double> x0, std::optional<double> u0,
                  std::optional<double> v0, double y0, bool from_orbit, double periods,
                  double transient, double chatter_velocity, std::int64_t max_events_per_period,
                  bool events, bool trajectory, long samples_per_period) {
  SimulateJobOptions o;
  o.params = Params{T0, e};
  o.forcing = ForceSpec{A, c, phi0, cos, sin, waveform, levels, switches}.Build();
  o.start = SimulateStartSpec{alpha, x0, u0, v0}.Build(from_orbit, "from_orbit=True");
  o.sim.y0 = y0;
  o.sim.periods = periods;
  o.sim.transient = transient;
  o.sim.chatter_velocity = chatter_velocity;
  o.sim.max_events_per_period = max_events_per_period;
  o.trajectory = trajectory;
  o.samples_per_period = samples_per_period;
  TableObserver observer(events, trajectory);
  o.observer = &observer;
  SimulateJobResult r;
  try {
    r = RunWithoutGil([&](SignalCheck& check) {
      observer.Watch(&check);
      SimulateJobResult result = RunSimulateJob(o);
      observer.Watch(nullptr);
      return result;
    });
  } catch (const TableFull&) {
    throw std::invalid_argument(fmt::format(
        "events = True is invalid for this run: its event table passed {} rows, the most held in "
        "memory: expected a shorter run (fewer periods)",
        kMaxTrajectoryRows));
  }
  py::dict d(ToPython(json::SimulateJobJson(r)));
  if (events) d["event_table"] = EventTable(observer);
  if (trajectory) d["trajectory"] = StateDict(observer.samples, "phi");
  return d;
}

constexpr const char* kSimulateDoc =
    "Exact event-driven simulation of the full non-smooth dynamics (capsubot documentation, "
    "model sections 3 and 10), independent of the analytic orbit: the object `capsubot simulate "
    "--json` prints. The force is F(phi) = A sin(phi + phi0) + c (or a Fourier force) with phi "
    "= 0 at the start.\n\n"
    "Arguments (keyword only, named as the options of `capsubot simulate`):\n";

constexpr const char* kSimulateArgsDoc =
    "    phi0    motor phase at the start [rad]; required with A, default 0 with sin/cos\n";

constexpr const char* kSimulateStateDoc =
    "    alpha   mass ratio m2/(m1+m2), 0 < alpha < 1 (required unless from_orbit)\n"
    "    x0, u0, v0  initial position of the inner body [L] (0 <= x0 <= 1), relative velocity\n"
    "            dx/dphi and capsule velocity [omega L] (required unless from_orbit)\n"
    "    y0      initial capsule position [L]\n"
    "    from_orbit  start right after the impact of the analytic one-impact orbit for these\n"
    "            A, c, phi0, T0, e (x = 1, u = -e u, v = v_plus) with its alpha\n"
    "    periods forcing periods (2 pi each) recorded after the transient, 0 < periods <= 1e8\n"
    "    transient  forcing periods run first and reported apart (key 'transient'): the\n"
    "            counts, v_mean and energy are over the periods after it, 0 <= transient <= 1e8\n"
    "    chatter_velocity  an impact slower than this [omega L], with the inner body pushed\n"
    "            into the wall, ends a chattering sequence: the body then rests on the wall\n"
    "    max_events_per_period  work bound: the run stops (status 'event_limit') after this\n"
    "            many events per period, 10 to 1e9\n"
    "    events  also return every event (key 'event_table')\n"
    "    trajectory  also return the state sampled on a grid of phases (key 'trajectory')\n"
    "    samples_per_period  samples per forcing period of the trajectory, 1 to 1e6, with at\n"
    "            most 1e7 samples over transient + periods\n\n"
    "Returns a dict: status ('ok', 'impact_limit', 'event_limit'), message, alpha, the final "
    "state phi (rad), x (L), u, v (omega L), y (L), mode, displacement (y(end) - y0, L), "
    "v_mean (omega L), the counts impacts_right, impacts_left, stops, breakaways, sticks, "
    "releases, events, energy (a dict motor_work, motor_work_positive, friction_loss, "
    "impact_loss in (m1+m2) omega^2 L^2, capsubot documentation, model section 11), all over the "
    "recorded periods; with transient > 0, transient (a dict periods and the same figures over the "
    "transient); with from_orbit, orbit (the dict of solve). With events: "
    "'event_table', a dict of NumPy arrays phase, kind, x, u, v, y (state right after the "
    "event), u_before, v_before, mode (the columns of --events). With trajectory: "
    "'trajectory', a dict of arrays phi, x, u, v, y, mode. The tables are kept in memory: "
    "at most 1e7 rows each.\n\n"
    "Raises ValueError for bad input (the message names the parameter, its value and the "
    "rule), RuntimeError when the state stops being finite (status 'non_finite': the command "
    "line then exits with status 1). Runs without the GIL; Ctrl-C interrupts it.\n\n";

}  // namespace

void BindSimulate(py::module_& m) {
  const SimOptions defaults;
  const std::string doc = std::string(kSimulateDoc) + ForceArgsDoc() + kSimulateArgsDoc +
                          ModelArgsDoc() + kSimulateStateDoc + kUnits;
  DefRobotFunction(m, "simulate", &Simulate, doc.c_str(), py::arg("alpha") = py::none(),
                   py::arg("x0") = py::none(), py::arg("u0") = py::none(),
                   py::arg("v0") = py::none(), py::arg("y0") = defaults.y0,
                   py::arg("from_orbit").noconvert() = false, py::arg("periods") = defaults.periods,
                   py::arg("transient") = defaults.transient,
                   py::arg("chatter_velocity") = defaults.chatter_velocity,
                   py::arg("max_events_per_period") = defaults.max_events_per_period,
                   py::arg("events").noconvert() = false, py::arg("trajectory").noconvert() = false,
                   py::arg("samples_per_period") = SimulateJobOptions{}.samples_per_period);
}

}  // namespace capsubot::python
