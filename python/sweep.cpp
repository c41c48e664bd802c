// sweep: the orbit and its validity (and stability), or the optimum of P1, P2, P3 or the reach
// search, at every point of a grid of parameters (docs/sweep.md), as `capsubot sweep`: its CSV
// as NumPy columns.

#include <fmt/format.h>
#include <pybind11/stl.h>

#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "capsubot/io/io.hpp"
#include "capsubot/job/reach_effort_settings.hpp"
#include "capsubot/job/sweep_job.hpp"
#include "capsubot/job/sweep_setting_tables.hpp"
#include "capsubot/job/sweep_settings.hpp"
#include "capsubot/model/limits.hpp"
#include "sweep_keywords.hpp"

namespace capsubot::python {
namespace {

// The job of the settings `s` and the grid's axes `grid`, run; ValueError in the module's names.
py::dict SweepDict(SweepSettings& s, const std::vector<std::string>& grid,
                   const py::dict& arguments) {
  const py::dict provenance = JobProvenance("sweep", arguments);
  const OutputFolder folder;
  try {
    for (const std::string& spec : grid) s.grid.axes.push_back(ParseGridAxis(spec));
    s.file.output = folder.File("sweep.csv");
    const SweepJobOptions job =
        SweepJobFrom(s, SettingNames{kSweepKeywords, SettingNames::Style::kKeywords});
    RunWithoutGil([&](SignalCheck&) { return RunSweepJob(job); });
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(WithFlagNames(e.what(), kSweepKeywords));
  }
  py::dict d;
  d["columns"] = CsvColumns(folder.File("sweep.csv"));
  d["provenance"] = provenance;
  return d;
}

// A flag argument: given when true.
void TakeFlag(std::set<std::string>& given, const char* name, bool value, bool& field) {
  if (!value) return;
  field = true;
  given.insert(name);
}

constexpr const char* kSweepDoc =
    "The orbit and its validity (capsubot documentation, model sections 4-5), the best gait of "
    "problem P1, P2 or P3 (section 7) or the fastest motion from rest (section 13) at every "
    "point of a grid of parameters, as `capsubot sweep`: its CSV as NumPy columns.\n\n"
    "Arguments (keyword only, named as the options of `capsubot sweep`; None: the option not "
    "given, the mode's default; optimize=None: the orbit of the force at every point):\n";

// The arguments, from the library's tables of the sweep's settings (the meanings --help shows),
// but the few the command line declares by hand too.
std::string SweepArgumentsDoc() {
  const SweepSettings d;
  const FlagNames& k = kSweepKeywords;
  constexpr DefaultInDoc kShown = DefaultInDoc::kSignature;  // None: the mode's default
  return ArgumentLines("grid",
                       "list of axes (the first slowest): 'name=lo:hi:n' (n equally spaced "
                       "values, lo and hi may be pi or -pi), 'name=lo:hi:n:log' or "
                       "'name=v1,v2,...'; name a model parameter (A, c, phi0, T0, e, margin, "
                       "margin_stroke, stick_margin, alpha, rho_max, bound, a1.., b1..); alpha "
                       "finds every orbit of the robot") +
         TableArgumentLines(SweepModeSettings(), d, k, {"optimize"}, kShown) +
         ArgumentLines("A, c, phi0, cos, sin",
                       "the force, except its gridded parts (orbit and phi0 modes)") +
         ModelArgsDoc() + MarginArgsDoc() +
         "            (reach: margin_stroke and stick_margin default to 0.02)\n" +
         TableArgumentLines(SweepModeSettings(), d, k, {"stability"}, kShown) +
         TableArgumentLines(SweepGaitSettings(), d.search.gait, k, {"rho_max"}, kShown) +
         ArgumentLines("stable_only", "with optimize: the same as rho_max = 1") +
         TableArgumentLines(SweepModeSettings(), d, k, {"scan_points"}, kShown) +
         TableArgumentLines(SweepGaitSettings(), d.search.gait, k, {"bound"}, kShown) +
         TableArgumentLines(SweepSearchSettings(), d.search, k, {"harmonics"}, kShown) +
         ArgumentLines("starts",
                       "with optimize forcing|fourier|reach: local polishes of the multistart, "
                       ">= 1 (default: 10 for forcing and reach's seed, 20 for fourier)") +
         TableArgumentLines(SweepSearchSettings(), d.search, k,
                            {"hops", "global_algorithm", "local_algorithm", "global_evaluations"},
                            kShown) +
         TableArgumentLines(SweepModeSettings(), d, k, {"alpha"}, kShown) +
         ArgumentLines("from_rest_starts, reach_starts",
                       "with optimize reach: the grids 'NXxNPSI' of the seed's check from rest "
                       "and of the starts inside the search") +
         TableArgumentLines(ReachEffortSettings(), ReachEffort{}, k,
                            {"reach_evaluations", "reach_local_evaluations"}, kShown) +
         ThreadsArgDoc() + "\n";
}

constexpr const char* kSweepReturnsDoc =
    "Returns a dict: columns (the CSV of `capsubot sweep` as NumPy arrays, one element per grid "
    "point (per orbit with a grid over alpha), the header's names: the gridded parameters, "
    "then phi1, alpha, u, v_plus, I, v_mean, x_min, x_max, valid, violations, ... as the "
    "command writes them; int64 for whole numbers, float64 with NaN for an empty cell, str for "
    "names) and provenance {program, version, command, options: the arguments}.\n\n"
    "Raises ValueError for bad input (the message names the argument, its value and the rule, "
    "as the command line's names the option). Runs without the GIL.\n\n";

// The function: its arguments packed, the command's, and the provenance of all of them.
py::dict Sweep(const std::vector<std::string>& grid, std::optional<std::string> optimize,
               std::optional<double> A, std::optional<double> c, std::optional<double> phi0,
               std::optional<std::vector<double>> cos, std::optional<std::vector<double>> sin,
               std::optional<double> T0, std::optional<double> e, std::optional<double> margin,
               std::optional<double> margin_stroke, std::optional<double> stick_margin,
               bool stability, std::optional<double> rho_max, bool stable_only,
               std::optional<int> scan_points, std::optional<double> bound,
               std::optional<int> harmonics, std::optional<int> starts, std::optional<int> hops,
               std::optional<std::string> global_algorithm,
               std::optional<std::string> local_algorithm, std::optional<int> global_evaluations,
               std::optional<double> alpha, std::optional<std::string> from_rest_starts,
               std::optional<std::string> reach_starts, std::optional<int> reach_evaluations,
               std::optional<int> reach_local_evaluations, int threads) {
  if (stable_only && rho_max) {
    throw std::invalid_argument(fmt::format(
        "stable_only conflicts with rho_max = {}: stable_only=True means rho_max = 1; give one "
        "of them",
        *rho_max));
  }
  SweepSettings s;  // the arguments given (None, or False: not given)
  s.optimize = optimize.value_or("");
  TakeGiven(s.given, "A", A, s.A);
  TakeGiven(s.given, "c", c, s.c);
  TakeGiven(s.given, "phi0", phi0, s.phi0);
  TakeGiven(s.given, "sin", sin, s.sin);
  TakeGiven(s.given, "cos", cos, s.cos);
  TakeGiven(s.given, "T0", T0, s.params.T0);
  TakeGiven(s.given, "e", e, s.params.e);
  TakeGiven(s.given, "margin", margin, s.margins.clearance);
  TakeGiven(s.given, "margin_stroke", margin_stroke, s.margins.clearance_stroke);
  TakeGiven(s.given, "stick_margin", stick_margin, s.margins.stick);
  TakeFlag(s.given, "stability", stability, s.stability);
  TakeGiven(s.given, "rho_max", rho_max, s.search.gait.rho_max);
  TakeFlag(s.given, "stable_only", stable_only, s.stable_only);
  TakeGiven(s.given, "scan_points", scan_points, s.scan_points);
  TakeSearch(
      s.given,
      {bound, harmonics, starts, hops, global_evaluations, global_algorithm, local_algorithm},
      s.search);
  TakeGiven(s.given, "alpha", alpha, s.alpha);
  TakeGiven(s.given, "from_rest_starts", from_rest_starts, s.from_rest_starts);
  TakeGiven(s.given, "reach_starts", reach_starts, s.reach_starts);
  TakeGiven(s.given, "reach_evaluations", reach_evaluations, s.reach_evaluations);
  TakeGiven(s.given, "reach_local_evaluations", reach_local_evaluations, s.reach_local_evaluations);
  s.file.threads = CapThreads(threads);
  const py::dict arguments(
      py::arg("A") = A, py::arg("c") = c, py::arg("phi0") = phi0, py::arg("cos") = cos,
      py::arg("sin") = sin, py::arg("T0") = T0, py::arg("e") = e, py::arg("margin") = margin,
      py::arg("margin_stroke") = margin_stroke, py::arg("stick_margin") = stick_margin,
      py::arg("stability") = stability, py::arg("rho_max") = rho_max,
      py::arg("stable_only") = stable_only, py::arg("scan_points") = scan_points,
      py::arg("bound") = bound, py::arg("harmonics") = harmonics, py::arg("starts") = starts,
      py::arg("hops") = hops, py::arg("global_algorithm") = global_algorithm,
      py::arg("local_algorithm") = local_algorithm,
      py::arg("global_evaluations") = global_evaluations, py::arg("alpha") = alpha,
      py::arg("from_rest_starts") = from_rest_starts, py::arg("reach_starts") = reach_starts,
      py::arg("reach_evaluations") = reach_evaluations,
      py::arg("reach_local_evaluations") = reach_local_evaluations);
  py::dict d = SweepDict(s, grid, arguments);
  py::dict options = d["provenance"]["options"];
  options["grid"] = grid;
  options["optimize"] = optimize;
  return d;
}

}  // namespace

void BindSweep(py::module_& m) {
  const std::string doc = std::string(kSweepDoc) + SweepArgumentsDoc() + kSweepReturnsDoc + kUnits;
  m.def("sweep", &Sweep, doc.c_str(), py::kw_only(), py::arg("grid"),
        py::arg("optimize") = py::none(), py::arg("A") = py::none(), py::arg("c") = py::none(),
        py::arg("phi0") = py::none(), py::arg("cos") = py::none(), py::arg("sin") = py::none(),
        py::arg("T0") = py::none(), py::arg("e") = py::none(), py::arg("margin") = py::none(),
        py::arg("margin_stroke") = py::none(), py::arg("stick_margin") = py::none(),
        py::arg("stability").noconvert() = false, py::arg("rho_max") = py::none(),
        py::arg("stable_only").noconvert() = false, py::arg("scan_points") = py::none(),
        py::arg("bound") = py::none(), py::arg("harmonics") = py::none(),
        py::arg("starts") = py::none(), py::arg("hops") = py::none(),
        py::arg("global_algorithm") = py::none(), py::arg("local_algorithm") = py::none(),
        py::arg("global_evaluations") = py::none(), py::arg("alpha") = py::none(),
        py::arg("from_rest_starts") = py::none(), py::arg("reach_starts") = py::none(),
        py::arg("reach_evaluations") = py::none(), py::arg("reach_local_evaluations") = py::none(),
        py::arg("threads") = GridFileOptions{}.threads);
}

}  // namespace capsubot::python
