// sweep: the orbit and its validity (and stability), or the optimum of P1, P2, P3 or the reach
// search, at every point of a grid of parameters (docs/sweep.md), as `capsubot sweep`: its CSV
// as NumPy columns.

#include <fmt/format.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "capsubot/attract/start_grid.hpp"
#include "capsubot/io/io.hpp"
#include "capsubot/job/sweep_job.hpp"
#include "capsubot/model/limits.hpp"

namespace capsubot::python {
namespace {

// The arguments a mode may read; None (or False): not given, the mode's default.
struct SweepArgs {
  std::optional<double> A, c, phi0;
  std::optional<std::vector<double>> cos, sin;
  std::optional<double> T0, e, margin, margin_stroke, stick_margin;
  bool stability = false;
  std::optional<double> rho_max;
  bool stable_only = false;
  std::optional<int> scan_points;
  std::optional<double> bound;
  std::optional<int> harmonics, starts, hops;
  std::optional<std::string> global_algorithm, local_algorithm;
  std::optional<int> global_evaluations;
  std::optional<double> alpha;
  std::optional<std::string> from_rest_starts, reach_starts;
  std::optional<int> reach_evaluations, reach_local_evaluations;
};

// Puts what a mode reads into its options (an argument given replaces the mode's default) and
// notes the names it reads: an argument given that the mode does not read is refused.
class ArgReader {
 public:
  template <class T, class V>
  void Take(const char* name, T& field, const std::optional<V>& value) {
    read_.emplace_back(name);
    if (value) field = *value;
  }
  void Take(const char* name, bool& field, bool value) {
    read_.emplace_back(name);
    field = field || value;
  }
  bool Reads(const std::string& name) const {
    return std::find(read_.begin(), read_.end(), name) != read_.end();
  }

 private:
  std::vector<std::string> read_;
};

void ReadParams(ArgReader& r, const SweepArgs& a, Params& p, Margins& m) {
  r.Take("T0", p.T0, a.T0);
  r.Take("e", p.e, a.e);
  r.Take("margin", m.clearance, a.margin);
  r.Take("margin_stroke", m.clearance_stroke, a.margin_stroke);
  r.Take("stick_margin", m.stick, a.stick_margin);
}

void ReadForce(ArgReader& r, const SweepArgs& a, SweepForce& f) {
  r.Take("A", f.A, a.A);
  r.Take("c", f.c, a.c);
  r.Take("sin", f.sin, a.sin);
  r.Take("cos", f.cos, a.cos);
}

void ReadRhoMax(ArgReader& r, const SweepArgs& a, double& rho_max) {
  r.Take("stable_only", rho_max, a.stable_only ? std::optional<double>(1.0) : std::nullopt);
  r.Take("rho_max", rho_max, a.rho_max);
}

void ReadSearch(ArgReader& r, const SweepArgs& a, SearchRequest& s) {
  ReadRhoMax(r, a, s.gait.rho_max);
  r.Take("bound", s.gait.force_bound, a.bound);
  r.Take("starts", s.starts, a.starts);
  r.Take("global_algorithm", s.global_algorithm, a.global_algorithm);
  r.Take("local_algorithm", s.local_algorithm, a.local_algorithm);
  r.Take("global_evaluations", s.global_evaluations, a.global_evaluations);
}

void ReadMode(ArgReader& r, const SweepArgs& a, SweepOrbitMode& m) {
  ReadParams(r, a, m.params, m.margins);
  ReadForce(r, a, m.force);
  r.Take("phi0", m.phi0, a.phi0);
  r.Take("stability", m.stability, a.stability);
}

void ReadMode(ArgReader& r, const SweepArgs& a, SweepPhaseMode& m) {
  ReadParams(r, a, m.params, m.phase.gait.margins);
  ReadForce(r, a, m.force);
  r.Take("stability", m.stability, a.stability);
  ReadRhoMax(r, a, m.phase.gait.rho_max);
  r.Take("scan_points", m.phase.scan_points, a.scan_points);
}

void ReadMode(ArgReader& r, const SweepArgs& a, SweepForcingMode& m) {
  ReadParams(r, a, m.params, m.search.gait.margins);
  r.Take("stability", m.stability, a.stability);
  ReadSearch(r, a, m.search);
  r.Take("hops", m.search.hops, a.hops);
}

void ReadMode(ArgReader& r, const SweepArgs& a, SweepFourierMode& m) {
  ReadParams(r, a, m.params, m.search.gait.margins);
  r.Take("stability", m.stability, a.stability);
  ReadSearch(r, a, m.search);
  r.Take("harmonics", m.search.harmonics, a.harmonics);
}

void ReadMode(ArgReader& r, const SweepArgs& a, SweepReachMode& m) {
  ReadParams(r, a, m.params, m.search.gait.margins);
  ReadSearch(r, a, m.search);
  r.Take("hops", m.search.hops, a.hops);
  r.Take("alpha", m.reach.alpha, a.alpha);
  std::optional<StartGrid> check, search;
  if (a.from_rest_starts) check = ParseStartGrid("from_rest_starts", *a.from_rest_starts);
  if (a.reach_starts) search = ParseStartGrid("reach_starts", *a.reach_starts);
  r.Take("from_rest_starts", m.reach.check.n_x, check ? std::optional(check->n_x) : std::nullopt);
  r.Take("from_rest_starts", m.reach.check.n_psi,
         check ? std::optional(check->n_psi) : std::nullopt);
  r.Take("reach_starts", m.reach.search.n_x, search ? std::optional(search->n_x) : std::nullopt);
  r.Take("reach_starts", m.reach.search.n_psi,
         search ? std::optional(search->n_psi) : std::nullopt);
  r.Take("reach_evaluations", m.reach.global_evaluations, a.reach_evaluations);
  r.Take("reach_local_evaluations", m.reach.local_evaluations, a.reach_local_evaluations);
}

std::string ModeText(const std::string& name) {
  return name.empty() ? "no optimize" : "optimize " + name;
}

// Refuses an argument given that the mode `name` does not read (it would be silently
// ignored), naming the modes that read it, as the command line refuses such an option.
void RejectUnread(const std::vector<std::string>& given, const std::string& name,
                  const ArgReader& reader) {
  std::vector<std::string> modes = {""};
  for (SweepOptimize mode : SweepOptimizeModes()) modes.emplace_back(SweepOptimizeName(mode));
  for (const std::string& arg : given) {
    if (reader.Reads(arg)) continue;
    std::string readers;
    for (const std::string& other : modes) {
      SweepMode mode = SweepModeNamed(other);
      ArgReader r;
      std::visit([&](auto& m) { ReadMode(r, SweepArgs{}, m); }, mode);
      if (r.Reads(arg)) readers += (readers.empty() ? "" : ", ") + ModeText(other);
    }
    throw std::invalid_argument(fmt::format(
        "{} is invalid {}: expected it only with {}", arg,
        name.empty() ? std::string("without optimize") : "with optimize " + name, readers));
  }
}

// An argument that gives a value the grid also gives.
void RejectGridConflicts(const Grid& grid, const py::dict& arguments) {
  for (const GridAxis& axis : grid.axes) {
    const py::str name(axis.name());
    if (arguments.contains(name) && !arguments[name].is_none()) {
      throw std::invalid_argument(
          fmt::format("{} = {} is invalid with grid {}: expected the value from only one of them",
                      axis.name(), FormatNumber(arguments[name].cast<double>()), axis.ToString()));
    }
    if (axis.parameter == ModelParameter::kRhoMax && arguments["stable_only"].cast<bool>()) {
      throw std::invalid_argument(fmt::format(
          "stable_only (rho_max = 1) is invalid with grid {}: expected the value from only one "
          "of them",
          axis.ToString()));
    }
  }
}

// The job's options named as the module's arguments, where the command line names its options
// (the job names its reach budgets by their place in the options): "field = value".
std::string WithArgumentNames(std::string message) {
  const std::pair<std::string, std::string> names[] = {
      {"reach.global_evaluations = ", "reach_evaluations = "},
      {"reach.local_evaluations = ", "reach_local_evaluations = "}};
  for (const auto& [field, argument] : names) {
    for (std::size_t at = message.find(field); at != std::string::npos;
         at = message.find(field, at + argument.size())) {
      message.replace(at, field.size(), argument);
    }
  }
  return message;
}

SweepJobOptions JobOptions(const std::vector<std::string>& grid, const std::string& optimize,
                           const SweepArgs& args, const py::dict& arguments, int threads) {
  SweepJobOptions job;
  for (const std::string& spec : grid) job.grid.axes.push_back(ParseGridAxis(spec));
  job.mode = SweepModeNamed(optimize);
  if (args.stable_only && args.rho_max) {
    throw std::invalid_argument(fmt::format(
        "stable_only conflicts with rho_max = {}: stable_only=True means rho_max = 1; give one "
        "of them",
        *args.rho_max));
  }
  RejectGridConflicts(job.grid, arguments);
  ArgReader reader;
  std::visit([&](auto& m) { ReadMode(reader, args, m); }, job.mode);
  std::vector<std::string> given;
  for (const auto& [key, value] : arguments) {
    const bool flag = py::isinstance<py::bool_>(value);
    if (flag ? value.cast<bool>() : !value.is_none()) given.push_back(key.cast<std::string>());
  }
  RejectUnread(given, optimize, reader);
  if (args.global_evaluations && args.global_algorithm.value_or(kMultistart) == kMultistart) {
    throw std::invalid_argument(
        "global_evaluations is invalid with global_algorithm multistart: expected an NLopt "
        "global algorithm with it (multistart has no evaluation budget)");
  }
  job.file.threads = CapThreads(threads);
  return job;
}

py::dict SweepDict(const std::vector<std::string>& grid, std::optional<std::string> optimize,
                   const SweepArgs& args, const py::dict& arguments, int threads) {
  const py::dict provenance = JobProvenance("sweep", arguments);
  const OutputFolder folder;
  try {
    SweepJobOptions job = JobOptions(grid, optimize.value_or(""), args, arguments, threads);
    job.file.output = folder.File("sweep.csv");
    RunWithoutGil([&](SignalCheck&) { return RunSweepJob(job); });
  } catch (const std::invalid_argument& e) {
    throw std::invalid_argument(WithArgumentNames(e.what()));
  }
  py::dict d;
  d["columns"] = CsvColumns(folder.File("sweep.csv"));
  d["provenance"] = provenance;
  return d;
}

constexpr const char* kSweepDoc =
    "The orbit and its validity (capsubot documentation, model sections 4-5), the best gait of "
    "problem P1, P2 or P3 (section 7) or the fastest motion from rest (section 13) at every "
    "point of a grid of parameters, as `capsubot sweep`: its CSV as NumPy columns.\n\n"
    "Arguments (keyword only, named as the options of `capsubot sweep`; None: the option not "
    "given, the mode's default):\n"
    "    grid    list of axes (the first slowest): 'name=lo:hi:n' (n equally spaced values, lo\n"
    "            and hi may be pi or -pi), 'name=lo:hi:n:log' or 'name=v1,v2,...'; name a model\n"
    "            parameter (A, c, phi0, T0, e, margin, margin_stroke, stick_margin, alpha,\n"
    "            rho_max, bound, a1.., b1..); alpha finds every orbit of the robot\n"
    "    optimize  None (the orbit of the force), 'phi0' (P1), 'forcing' (P2), 'fourier' (P3)\n"
    "            or 'reach' (the fastest motion from rest)\n"
    "    A, c, phi0, cos, sin  the force, except its gridded parts (orbit and phi0 modes)\n"
    "    T0, e, margin, margin_stroke, stick_margin  the model and the margins of a robust gait\n"
    "            (reach: margin_stroke and stick_margin default to 0.02)\n"
    "    stability  add spectral_radius, lambda_re, lambda_im, stable and loss (not reach)\n"
    "    rho_max, stable_only  with optimize: the largest spectral radius (stable_only: 1)\n"
    "    scan_points  phi0: points of the initial scan of phi0\n"
    "    bound   forcing, fourier, reach: the force bound, 0 < bound <= T0 (None: T0)\n"
    "    harmonics  fourier: the number K of harmonics\n"
    "    starts, hops, global_algorithm, local_algorithm, global_evaluations  forcing,\n"
    "            fourier, reach: the search effort, as in optimize()\n"
    "    alpha   reach: a fixed mass ratio 0 < alpha < 1 (None: optimised too)\n"
    "    from_rest_starts, reach_starts, reach_evaluations, reach_local_evaluations  reach:\n"
    "            the grids of starts and the evaluation budgets of the search from rest\n"
    "    threads worker threads (0: all cores; more than 4 per core are lowered to that); the\n"
    "            result does not depend on it\n\n"
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
  const SweepArgs args{A,
                       c,
                       phi0,
                       cos,
                       sin,
                       T0,
                       e,
                       margin,
                       margin_stroke,
                       stick_margin,
                       stability,
                       rho_max,
                       stable_only,
                       scan_points,
                       bound,
                       harmonics,
                       starts,
                       hops,
                       global_algorithm,
                       local_algorithm,
                       global_evaluations,
                       alpha,
                       from_rest_starts,
                       reach_starts,
                       reach_evaluations,
                       reach_local_evaluations};
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
  py::dict d = SweepDict(grid, optimize, args, arguments, threads);
  py::dict options = d["provenance"]["options"];
  options["grid"] = grid;
  options["optimize"] = optimize;
  return d;
}

}  // namespace

void BindSweep(py::module_& m) {
  const std::string doc = std::string(kSweepDoc) + kUnits;
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
