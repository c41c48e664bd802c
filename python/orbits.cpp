// orbits: every one-impact orbit of a robot whose mass ratio is fixed (docs/model.md section 8),
// as `capsubot orbits --json`.

#include <fmt/format.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "capsubot/job/orbits_job.hpp"
#include "capsubot/report/orbits_text.hpp"
#include "capsubot/report/solution_json.hpp"

namespace capsubot::python {
namespace {

py::list Orbits(double alpha, std::optional<double> A, double c,
                std::optional<std::vector<double>> cos, std::optional<std::vector<double>> sin,
                double T0, double e, double margin, double margin_stroke, double stick_margin,
                std::int64_t max_evaluations) {
  OrbitsJobOptions job;
  job.robot.params = Params{T0, e};
  job.margins = Margins{margin, margin_stroke, stick_margin};
  job.robot.params.Validate();
  job.margins.Validate();
  job.robot.forcing = ForceSpec{A, c, std::nullopt, cos, sin}.Build(false);
  job.robot.alpha = alpha;
  job.max_evaluations = max_evaluations;
  job.Validate();
  const OrbitsJobResult result = RunWithoutGil([&](SignalCheck& check) {
    job.interrupt = check.AsInterrupt();
    return RunOrbitsJob(job);
  });
  const bool complete = result.complete;
  const std::vector<Solution>& found = result.orbits;
  py::list all(ToPython(json::RobotOrbitsJson(found, complete)));
  if (!complete) {
    // Said as a warning, as the command line says it on stderr.
    const std::string note = text::OrbitsIncompleteNote("max_evaluations");
    if (PyErr_WarnEx(PyExc_RuntimeWarning, note.c_str(), 1) != 0) {
      throw py::error_already_set();
    }
  }
  return all;
}

constexpr const char* kOrbitsDoc =
    "Every one-impact orbit of a given robot (mass ratio alpha fixed; capsubot documentation, "
    "model section 8): all impact phases phi0 in [-pi, pi) with alpha(phi0) = alpha, each with "
    "its validity and stability: the list `orbits` of `capsubot orbits --json`.\n\n"
    "Arguments (keyword only, named as the options of `capsubot orbits`):\n"
    "    alpha   mass ratio m2/(m1+m2) of the robot, 0 < alpha < 1\n";

constexpr const char* kOrbitsArgsDoc =
    "    max_evaluations  work bound of the search (evaluations of the orbit equation), 1 to "
    "1e9\n\n"
    "Returns a list of dicts sorted by phi0, each with the keys of solve(..., stability=True) "
    "and complete (False: the search hit its work bound and orbits may be missing; a "
    "RuntimeWarning then says so). phi0 is solved for: it is not an argument (a Fourier "
    "force's coefficients are those of phi0 = 0).\n\n"
    "Raises ValueError for bad input (the message names the parameter, its value and the "
    "rule). Runs without the GIL; Ctrl-C interrupts it.\n\n";

}  // namespace

void BindOrbits(py::module_& m) {
  const std::string doc = std::string(kOrbitsDoc) + ForceArgsDoc(false) + ModelArgsDoc() +
                          MarginArgsDoc() + kOrbitsArgsDoc + kUnits;
  m.def("orbits", &Orbits, doc.c_str(), py::kw_only(), py::arg("alpha"), py::arg("A") = py::none(),
        py::arg("c"), py::arg("cos") = py::none(), py::arg("sin") = py::none(),
        py::arg("T0") = Params{}.T0, py::arg("e") = Params{}.e,
        py::arg("margin") = Margins{}.clearance,
        py::arg("margin_stroke") = Margins{}.clearance_stroke,
        py::arg("stick_margin") = Margins{}.stick,
        py::arg("max_evaluations") = kRobotOrbitsMaxEvaluations);
}

}  // namespace capsubot::python
