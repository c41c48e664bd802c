// basins: the attractor reached from every start of a plane of starts (docs/model.md sections
// 12 and 13), as `capsubot basins`: its CSV map as NumPy columns and the attractors of its
// --json.

#include <pybind11/stl.h>

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "capsubot/attract/start_grid.hpp"
#include "capsubot/job/basins_job.hpp"
#include "capsubot/model/limits.hpp"
#include "capsubot/report/attractors_json.hpp"

namespace capsubot::python {
namespace {

py::dict BasinsDict(std::optional<double> A, std::optional<double> c, std::optional<double> phi0,
                    std::optional<std::vector<double>> cos, std::optional<std::vector<double>> sin,
                    std::optional<std::string> waveform, std::optional<std::vector<double>> levels,
                    std::optional<std::vector<double>> switches, double T0, double e, double alpha,
                    const std::string& starts, const std::string& plane, double psi, double u_min,
                    double u_max, int transient, int record, int max_period, double state_tolerance,
                    double converged_tolerance, double chatter_velocity,
                    std::int64_t max_events_per_period, int threads) {
  const py::dict provenance = JobProvenance(
      "basins",
      py::dict(py::arg("A") = A, py::arg("c") = c, py::arg("phi0") = phi0, py::arg("cos") = cos,
               py::arg("sin") = sin, py::arg("waveform") = waveform, py::arg("levels") = levels,
               py::arg("switches") = switches, py::arg("T0") = T0, py::arg("e") = e,
               py::arg("alpha") = alpha, py::arg("starts") = starts, py::arg("plane") = plane,
               py::arg("psi") = psi, py::arg("u_min") = u_min, py::arg("u_max") = u_max,
               py::arg("transient") = transient, py::arg("record") = record,
               py::arg("max_period") = max_period, py::arg("state_tolerance") = state_tolerance,
               py::arg("converged_tolerance") = converged_tolerance,
               py::arg("chatter_velocity") = chatter_velocity,
               py::arg("max_events_per_period") = max_events_per_period));
  BasinsJobOptions o;
  AttractorsJobOptions& map = o.map;
  map.robot = {ForceSpec{A, c, phi0, cos, sin, waveform, levels, switches}.Build(), Params{T0, e},
               alpha};
  map.starts = ParseStartGrid("starts", starts);
  MotionOptions& mo = map.attractor.motion;
  mo.transient = transient;
  mo.record = record;
  mo.max_period = max_period;
  mo.state_tolerance = state_tolerance;
  mo.converged_tolerance = converged_tolerance;
  mo.chatter_velocity = chatter_velocity;
  mo.max_events_per_period = max_events_per_period;
  map.attractor.threads = CapThreads(threads);
  o.plane = StartPlaneNamed(plane, VelocityPlane{psi, u_min, u_max});
  const OutputFolder folder;
  map.run = WholeStartMap{folder.File("basins.csv"), ""};
  const BasinsJobResult r = RunWithoutGil([&](SignalCheck& check) {
    map.attractor.interrupt = check.AsInterrupt();
    return RunBasinsJob(o);
  });
  py::dict d = ToPython(json::BasinsJobJson(r));
  d["columns"] = CsvColumns(folder.File("basins.csv"));
  d["provenance"] = provenance;
  return d;
}

constexpr const char* kBasinsDoc =
    "Basins of attraction (capsubot documentation, model sections 12 and 13): the long-run "
    "motion of every start of a grid, labelled by attractor (1 = reached from most starts), as "
    "`capsubot basins`. Plane 'x0-psi': starts from rest as in attractors(); plane 'x0-u0': "
    "the inner body at x0 with relative velocity u0, the capsule at rest, at forcing phase "
    "psi.\n\n"
    "Arguments (keyword only, named as the options of `capsubot basins`):\n"
    "    phi0    phase of the force F = A sin(psi + phi0) + c at the starts' phases [rad]\n"
    "            (required for the harmonic force; default 0 for a Fourier force)\n";

constexpr const char* kBasinsArgsDoc =
    "    starts  grid of starts 'NXxNY' (x0 x psi, or x0 x u0)\n"
    "    plane   'x0-psi' (starts from rest) or 'x0-u0'\n"
    "    psi     forcing phase of the starts in the x0-u0 plane [rad]\n"
    "    u_min, u_max  the range of u0 of the x0-u0 plane [omega L], u_min < u_max; u0 = u_min\n"
    "            + (j + 0.5)(u_max - u_min)/NY\n"
    "    transient, record, max_period, state_tolerance, converged_tolerance,\n"
    "            chatter_velocity, max_events_per_period  each start's long-run motion, as in\n"
    "            attractors()\n";

constexpr const char* kBasinsReturnsDoc =
    "\nReturns the dict of `capsubot basins --json` (starts, attractors, mean_velocity, "
    "event_limit_starts, force: as attractors()) plus columns, the CSV map `capsubot basins -o` "
    "writes as NumPy arrays, one row per start (x0 major): x0, psi (or u0), attractor (int64), "
    "period, impacts_right, impacts_left, mean_velocity (float64, NaN where the motion has "
    "none), status (str); and provenance {program, version, command, options: the arguments}.\n\n"
    "Raises ValueError for bad input (the message names the argument, its value and the "
    "rule). Runs without the GIL; Ctrl-C interrupts it after the starts being simulated.\n\n";

}  // namespace

void BindBasins(py::module_& m) {
  const std::string doc = std::string(kBasinsDoc) + ForceArgsDoc() + ModelArgsDoc() +
                          MassRatioArgDoc() + kBasinsArgsDoc + ThreadsArgDoc() + kBasinsReturnsDoc +
                          kUnits;
  const MotionOptions mo;
  const VelocityPlane velocity;
  DefRobotFunction(m, "basins", &BasinsDict, doc.c_str(), py::arg("alpha"),
                   py::arg("starts") = kDefaultBasinStarts,
                   py::arg("plane") = StartPlaneName(RestPlane{}), py::arg("psi") = velocity.psi,
                   py::arg("u_min") = velocity.u_min, py::arg("u_max") = velocity.u_max,
                   py::arg("transient") = mo.transient, py::arg("record") = mo.record,
                   py::arg("max_period") = mo.max_period,
                   py::arg("state_tolerance") = mo.state_tolerance,
                   py::arg("converged_tolerance") = mo.converged_tolerance,
                   py::arg("chatter_velocity") = mo.chatter_velocity,
                   py::arg("max_events_per_period") = mo.max_events_per_period,
                   py::arg("threads") = AttractorOptions{}.threads);
}

}  // namespace capsubot::python
