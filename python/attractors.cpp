// attractors: the long-run motions reached from rest on a grid of starts (docs/model.md
// sections 12 and 13), as `capsubot attractors --json`; motion options shared with periodic.

#include <pybind11/stl.h>

#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "capsubot/attract/start_grid.hpp"
#include "capsubot/job/attractors_job.hpp"
#include "capsubot/model/limits.hpp"
#include "capsubot/report/attractors_json.hpp"

namespace capsubot::python {
namespace {

py::dict FindAttractorsDict(
    std::optional<double> A, std::optional<double> c, std::optional<double> phi0,
    std::optional<std::vector<double>> cos, std::optional<std::vector<double>> sin,
    std::optional<std::string> waveform, std::optional<std::vector<double>> levels,
    std::optional<std::vector<double>> switches, double T0, double e, double alpha,
    std::optional<std::string> starts, std::optional<int> n_x, std::optional<int> n_psi,
    int transient, int record, int max_period, double state_tolerance, double converged_tolerance,
    double chatter_velocity, std::int64_t max_events_per_period, int threads) {
  AttractorsJobOptions o;
  o.robot = {ForceSpec{A, c, phi0, cos, sin, waveform, levels, switches}.Build(), Params{T0, e},
             alpha};
  if (starts) {
    if (n_x || n_psi) {
      throw std::invalid_argument(
          "starts and n_x, n_psi are exclusive: give the grid as starts='NXxNPSI' or as n_x "
          "and n_psi");
    }
    o.starts = ParseStartGrid("starts", *starts);
  }
  o.starts.n_x = n_x.value_or(o.starts.n_x);
  o.starts.n_psi = n_psi.value_or(o.starts.n_psi);
  MotionOptions& mo = o.attractor.motion;
  mo.transient = transient;
  mo.record = record;
  mo.max_period = max_period;
  mo.state_tolerance = state_tolerance;
  mo.converged_tolerance = converged_tolerance;
  mo.chatter_velocity = chatter_velocity;
  mo.max_events_per_period = max_events_per_period;
  o.attractor.threads = CapThreads(threads);
  // The library asks the interrupt on this thread after every block of starts: where Ctrl-C
  // is seen.
  const AttractorsJobResult r = RunWithoutGil([&](SignalCheck& check) {
    o.attractor.interrupt = check.AsInterrupt();
    return RunAttractorsJob(o);
  });
  return py::dict(ToPython(json::AttractorsJobJson(r)));
}

constexpr const char* kAttractorsDoc =
    "What the robot does from rest (capsubot documentation, model sections 12 and 13): the exact "
    "simulator is started with shell and inner body at rest, the inner body at x0 = (i + 0.5)/n_x "
    "and the forcing at phase psi = 2 pi j/n_psi; after a transient the long-run motion of each "
    "start is classified (period, impacts, mean velocity) and equal motions are grouped into "
    "attractors: the dict `capsubot attractors --json` prints.\n\n"
    "Arguments (keyword only, named as the options of `capsubot attractors`):\n"
    "    phi0    phase of the force F = A sin(psi + phi0) + c at the starts' phases psi [rad]\n"
    "            (required for the harmonic force; default 0 for a Fourier force)\n";

// The arguments after the force and the model: the robot's mass ratio, the grid of starts, the
// long runs (their meanings from the library's tables), the threads.
std::string AttractorsArgsDoc() {
  return MassRatioArgDoc() +
         ArgumentLines("starts", "grid of starts 'NXxNPSI' (positions x phases), default '8x8'") +
         ArgumentLines("n_x, n_psi", "the grid of starts as two numbers, instead of starts") +
         MotionArgsDoc() + ThreadsArgDoc();
}

constexpr const char* kAttractorsReturnsDoc =
    "Returns a dict: starts (their number), attractors (a list of dicts, most starts first: "
    "status, period, impacts_right, impacts_left, mean_velocity (over its starts), velocity_min, "
    "velocity_max, fraction, starts, example_start {x0, psi}, one_impact_orbit, "
    "halves_difference (irregular ones)), mean_velocity (over the starts that did not "
    "hit the work bound), event_limit_starts.\n\n"
    "Raises ValueError for bad input (the message names the parameter, its value and the "
    "rule). Runs without the GIL; Ctrl-C interrupts it after the starts being simulated.\n\n";

}  // namespace

void BindAttractors(py::module_& m) {
  const std::string doc = std::string(kAttractorsDoc) + ForceArgsDoc() + ModelArgsDoc() +
                          AttractorsArgsDoc() + "\n" + kAttractorsReturnsDoc + kUnits;
  const MotionOptions mo;
  DefRobotFunction(m, "attractors", &FindAttractorsDict, doc.c_str(), py::arg("alpha"),
                   py::arg("starts") = py::none(), py::arg("n_x") = py::none(),
                   py::arg("n_psi") = py::none(), py::arg("transient") = mo.transient,
                   py::arg("record") = mo.record, py::arg("max_period") = mo.max_period,
                   py::arg("state_tolerance") = mo.state_tolerance,
                   py::arg("converged_tolerance") = mo.converged_tolerance,
                   py::arg("chatter_velocity") = mo.chatter_velocity,
                   py::arg("max_events_per_period") = mo.max_events_per_period,
                   py::arg("threads") = AttractorOptions{}.threads);
}

}  // namespace capsubot::python
