// bifurcation: the brute-force bifurcation diagram with the state carried along, up and down,
// plus the analytic one-impact orbits (docs/model.md section 13), as `capsubot bifurcation`:
// its two CSV files (-o, --summary) as NumPy columns.

#include <pybind11/stl.h>

#include <cstdint>
#include <optional>
#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "capsubot/job/bifurcation_job.hpp"
#include "capsubot/model/limits.hpp"

namespace capsubot::python {
namespace {

py::dict BifurcationDict(
    std::optional<double> A, std::optional<double> c, std::optional<double> phi0,
    std::optional<std::vector<double>> cos, std::optional<std::vector<double>> sin,
    std::optional<std::string> waveform, std::optional<std::vector<double>> levels,
    std::optional<std::vector<double>> switches, double T0, double e, std::optional<double> alpha,
    const std::string& param, double from, double to, int steps, const std::string& direction,
    std::pair<double, double> start, std::optional<std::string> over, bool no_analytic,
    int transient, int record, int max_period, double state_tolerance, double converged_tolerance,
    double chatter_velocity, std::int64_t max_events_per_period, int threads) {
  const py::dict provenance = JobProvenance(
      "bifurcation",
      py::dict(py::arg("A") = A, py::arg("c") = c, py::arg("phi0") = phi0, py::arg("cos") = cos,
               py::arg("sin") = sin, py::arg("waveform") = waveform, py::arg("levels") = levels,
               py::arg("switches") = switches, py::arg("T0") = T0, py::arg("e") = e,
               py::arg("alpha") = alpha, py::arg("param") = param, py::arg("from_") = from,
               py::arg("to") = to, py::arg("steps") = steps, py::arg("direction") = direction,
               py::arg("start") = start, py::arg("over") = over,
               py::arg("no_analytic") = no_analytic, py::arg("transient") = transient,
               py::arg("record") = record, py::arg("max_period") = max_period,
               py::arg("state_tolerance") = state_tolerance,
               py::arg("converged_tolerance") = converged_tolerance,
               py::arg("chatter_velocity") = chatter_velocity,
               py::arg("max_events_per_period") = max_events_per_period));
  BifurcationJobOptions job;
  job.robot.forcing = ForceSpec{A, c, phi0, cos, sin, waveform, levels, switches}.Build();
  job.robot.params = Params{T0, e};
  job.robot.alpha = alpha.value_or(kNaN);
  BifurcationOptions& o = job.diagram;
  o.param = ParseRobotParameter(param, &o.harmonic);
  o.from = from;
  o.to = to;
  o.steps = steps;
  SetBifurcationDirection(direction, o);
  o.start = RestStart(start.first, start.second);
  if (over) SetBifurcationOver(*over, o);
  o.analytic = !no_analytic;
  MotionOptions& mo = o.motion;
  mo.transient = transient;
  mo.record = record;
  mo.max_period = max_period;
  mo.state_tolerance = state_tolerance;
  mo.converged_tolerance = converged_tolerance;
  mo.chatter_velocity = chatter_velocity;
  mo.max_events_per_period = max_events_per_period;
  o.threads = CapThreads(threads);
  const OutputFolder folder;
  job.files.impacts = folder.File("impacts.csv");
  job.files.summary = folder.File("summary.csv");
  RunWithoutGil([&](SignalCheck&) { return RunBifurcationJob(job); });
  py::dict d;
  d["impacts"] = CsvColumns(job.files.impacts);
  d["summary"] = CsvColumns(job.files.summary);
  d["provenance"] = provenance;
  return d;
}

constexpr const char* kBifurcationDoc =
    "Bifurcation diagram by brute force (capsubot documentation, model section 13), as "
    "`capsubot bifurcation`: the parameter is stepped over its range with the state carried "
    "from each value to the next, up and then down, so coexisting attractors show as "
    "hysteresis. At each value: a transient, then the impacts of the record and a summary row "
    "with the period, impacts, mean velocity and largest multiplier (Newton shooting), plus "
    "the valid analytic one-impact orbits (direction 'analytic').\n\n"
    "Arguments (keyword only, named as the options of `capsubot bifurcation`; `from_` is "
    "--from):\n"
    "    phi0    phase of the force F = A sin(psi + phi0) + c [rad] (required for the harmonic\n"
    "            force; default 0 for a Fourier force)\n";

constexpr const char* kBifurcationArgsDoc =
    "    alpha   mass ratio m2/(m1+m2) of the robot, 0 < alpha < 1 (None with param 'alpha')\n"
    "    param   the parameter: A, c, alpha, T0, e, phi0, or a Fourier coefficient a1, b1, ...\n"
    "    from_, to  first and last value of the parameter (to other than from_)\n"
    "    steps   values of the parameter, both ends included, >= 2\n"
    "    direction  'up', 'down' or 'both' (up, then down)\n"
    "    start   (x0, psi): each sweep starts from rest at x0, forcing phase psi [rad]\n"
    "    over    a two-parameter study: 'NAME=lo:hi:n', 'NAME=lo:hi:n:log' or\n"
    "            'NAME=v1,v2,...'; one diagram per value, both tables get a first column NAME\n"
    "    no_analytic  leave the analytic one-impact orbits out of the summary\n"
    "    transient, record, max_period, state_tolerance, converged_tolerance,\n"
    "            chatter_velocity, max_events_per_period  the long-run motion at each value, as\n"
    "            in attractors()\n";

constexpr const char* kBifurcationReturnsDoc =
    "\nReturns a dict: impacts (the CSV of `capsubot bifurcation -o` as NumPy columns: [NAME,] "
    "param, direction (str), period_index, wall (str), phase, velocity: every recorded impact), "
    "summary (the CSV of --summary: [NAME,] param, direction, period, impacts_right, "
    "impacts_left, mean_velocity, largest_multiplier, largest_multiplier_im, spectral_radius, "
    "status; NaN where a quantity does not exist) and provenance {program, version, command, "
    "options: the arguments}.\n\n"
    "Raises ValueError for bad input (the message names the argument, its value and the "
    "rule). Runs without the GIL.\n\n";

}  // namespace

void BindBifurcation(py::module_& m) {
  const std::string doc = std::string(kBifurcationDoc) + ForceArgsDoc() + ModelArgsDoc() +
                          kBifurcationArgsDoc + ThreadsArgDoc() + kBifurcationReturnsDoc + kUnits;
  const BifurcationOptions o;
  const MotionOptions& mo = o.motion;
  DefRobotFunction(
      m, "bifurcation", &BifurcationDict, doc.c_str(), py::arg("alpha") = py::none(),
      py::arg("param"), py::arg("from_"), py::arg("to"), py::arg("steps") = o.steps,
      py::arg("direction") = "both", py::arg("start") = std::make_pair(o.start.x, o.start.psi),
      py::arg("over") = py::none(), py::arg("no_analytic").noconvert() = false,
      py::arg("transient") = mo.transient, py::arg("record") = mo.record,
      py::arg("max_period") = mo.max_period, py::arg("state_tolerance") = mo.state_tolerance,
      py::arg("converged_tolerance") = mo.converged_tolerance,
      py::arg("chatter_velocity") = mo.chatter_velocity,
      py::arg("max_events_per_period") = mo.max_events_per_period, py::arg("threads") = o.threads);
}

}  // namespace capsubot::python
