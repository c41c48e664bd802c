// optimize: the fastest gait (docs/model.md section 7), one problem at a time, as
// `capsubot optimize --problem ... --json`.

#include "capsubot/optimize.hpp"

#include <fmt/format.h>
#include <pybind11/stl.h>

#include <cmath>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>

#include "bindings.hpp"

namespace capsubot::python {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

// The stability requirement: None or False: none; True: rho_max = 1; a number: rho_max.
std::optional<double> RhoMax(const py::object& stable) {
  if (stable.is_none()) return std::nullopt;
  if (py::isinstance<py::bool_>(stable)) {
    return stable.cast<bool>() ? std::optional<double>(1.0) : std::nullopt;
  }
  double rho_max = kNaN;
  try {
    rho_max = stable.cast<double>();
  } catch (const py::cast_error&) {
    throw py::type_error("stable must be None, True, False or a number (the bound rho_max)");
  }
  if (!(std::isfinite(rho_max) && rho_max > 0.0)) {
    throw std::invalid_argument(fmt::format(
        "stable = {} is invalid: expected a spectral radius bound rho_max > 0 (or True, "
        "meaning 1)",
        rho_max));
  }
  return rho_max;
}

// The options of P2 and P3 that the command line sets.
void SetSearch(SearchOptions& o, std::optional<double> bound, const std::string& global_algorithm,
               const std::string& local_algorithm, int global_evaluations,
               std::optional<int> starts, std::optional<double> rho_max) {
  o.force_bound = bound.value_or(kNaN);
  o.global_algorithm = global_algorithm;
  o.local_algorithm = local_algorithm;
  o.global_evaluations = global_evaluations;
  if (starts) o.starts = *starts;
  o.stable = rho_max.has_value();
  if (rho_max) o.rho_max = *rho_max;
}

// The object of `optimize --problem P --json`: the optimum's orbit as solve shows it, with the
// optimiser's status in place of the orbit's.
py::dict ResultDict(const OptimizeResult& r, const std::string& problem, const Params& p) {
  const Forcing& f = r.solution.orbit.forcing;
  py::dict d = SolutionDict(r.solution);
  d["problem"] = problem;
  d["status"] = OptimizeStatusName(r.status);
  d["message"] = r.message;
  d["active_constraints"] = r.active_constraints;
  d["evaluations"] = r.evaluations;
  d["algorithm"] = r.algorithm;
  if (!std::isnan(r.spectral_radius)) {
    d["spectral_radius"] = Number(r.spectral_radius);
    d["stable"] = r.spectral_radius < 1.0;
  }
  if (!f.harmonic()) {
    py::dict coefficients;
    coefficients["c"] = d["c"];
    coefficients["cos"] = d["cos"];
    coefficients["sin"] = d["sin"];
    d["coefficients"] = coefficients;
  }
  d["T0"] = Number(p.T0);
  d["e"] = Number(p.e);
  d["margin"] = Number(p.margin);
  if (problem == "fourier") {
    d["baseline_I"] = Number(r.baseline_I);
    d["gain"] = Number(r.found() ? r.solution.orbit.I / r.baseline_I - 1.0 : kNaN);
  }
  return d;
}

py::dict Optimize(const std::string& problem, std::optional<double> A, std::optional<double> c,
                  double T0, double e, double margin, std::optional<double> bound, int harmonics,
                  const std::string& global_algorithm, const std::string& local_algorithm,
                  int global_evaluations, int hops, std::optional<int> starts,
                  const py::object& stable) {
  if (problem != "phase" && problem != "forcing" && problem != "fourier") {
    throw std::invalid_argument(fmt::format(
        "problem = '{}' is invalid: expected 'phase', 'forcing' or 'fourier'", problem));
  }
  if (bound && !(std::isfinite(*bound) && *bound > 0.0)) {
    throw std::invalid_argument(
        fmt::format("bound = {} is invalid: expected a finite bound > 0 (at most T0)", *bound));
  }
  const Params params{T0, e, margin};
  params.Validate();
  const std::optional<double> rho_max = RhoMax(stable);

  OptimizeResult r;
  if (problem == "phase") {
    if (!A || !c) {
      throw std::invalid_argument(
          "problem 'phase' needs the force shape: give A and c (F = A sin(phi + phi0) + c)");
    }
    PhaseOptions po;
    po.stable = rho_max.has_value();
    if (rho_max) po.rho_max = *rho_max;
    const Forcing shape = Forcing::Harmonic(*A, *c, 0.0);
    py::gil_scoped_release release;
    r = OptimizePhase(shape, params, po);
  } else if (problem == "forcing") {
    ForcingDesignOptions o;
    SetSearch(o, bound, global_algorithm, local_algorithm, global_evaluations, starts, rho_max);
    o.hops = hops;
    py::gil_scoped_release release;
    r = OptimizeForcing(params, o);
  } else {
    FourierOptions o;
    SetSearch(o, bound, global_algorithm, local_algorithm, global_evaluations, starts, rho_max);
    o.harmonics = harmonics;
    py::gil_scoped_release release;
    r = OptimizeFourier(params, o);
  }
  return ResultDict(r, problem, params);
}

constexpr const char* kOptimizeDoc =
    "The fastest one-impact gait (docs/model.md section 7) for one problem: the object "
    "`capsubot optimize --problem <problem> --json` prints.\n\n"
    "Arguments (keyword only, named as the options of `capsubot optimize`):\n"
    "    problem 'phase' (P1: the best impact phase phi0 for the force shape A, c), 'forcing'\n"
    "            (P2: the best A, c, phi0 with A + c <= bound) or 'fourier' (P3: the best\n"
    "            K-harmonic force with max |F| <= bound)\n"
    "    A, c    amplitude A >= 0 and mean c of F = A sin(phi + phi0) + c [force] (phase only)\n";

constexpr const char* kOptimizeOptionsDoc =
    "    margin  clearance d required between inner body and walls [L], 0 <= d < 0.5\n"
    "    bound   force bound (A + c, or max |F|) for forcing/fourier, 0 < bound <= T0\n"
    "            [force]; None: T0\n"
    "    harmonics  number K of harmonics of the Fourier force (fourier), 1..16\n"
    "    global_algorithm  'multistart' or an NLopt global algorithm: GN_ISRES, GN_ORIG_DIRECT,\n"
    "            GN_ORIG_DIRECT_L, GN_AGS (forcing/fourier)\n"
    "    local_algorithm  the local polish: LN_COBYLA, LD_SLSQP, LD_MMA, LD_CCSAQ\n"
    "    global_evaluations  budget of an NLopt global algorithm, >= 10\n"
    "    hops    forcing: basin-hopping restarts after the starts, >= 0\n"
    "    starts  local polishes of the multistart, >= 1; None: 10 (forcing), 20 (fourier)\n"
    "    stable  require a stable orbit: True (spectral radius <= 1) or the bound rho_max > 0;\n"
    "            None: no requirement\n\n"
    "Returns a dict: the keys of solve for the optimum (A, c, phi0, phi1, alpha, u, v_plus, "
    "I, v_mean, x_min, x_max, valid, violations; cos, sin and coefficients for fourier), "
    "problem, status ('ok', 'no_valid_orbit', 'max_evaluations', ...), message, "
    "active_constraints, evaluations, algorithm, spectral_radius and stable (when the orbit "
    "exists), T0, e, margin; for fourier also baseline_I (the P2 optimum's I) and gain. "
    "With status 'no_valid_orbit' the orbit is the point nearest to validity.\n\n"
    "Raises ValueError for bad input (the message names the parameter, its value and the "
    "rule). Runs without the GIL (other Python threads go on).\n\n";

}  // namespace

void BindOptimize(py::module_& m) {
  const std::string doc = std::string(kOptimizeDoc) + kModelArgsDoc + kOptimizeOptionsDoc + kUnits;
  m.def("optimize", &Optimize, doc.c_str(), py::kw_only(), py::arg("problem"),
        py::arg("A") = py::none(), py::arg("c") = py::none(), py::arg("T0") = Params{}.T0,
        py::arg("e") = Params{}.e, py::arg("margin") = Params{}.margin,
        py::arg("bound") = py::none(), py::arg("harmonics") = FourierOptions{}.harmonics,
        py::arg("global_algorithm") = SearchOptions{}.global_algorithm,
        py::arg("local_algorithm") = SearchOptions{}.local_algorithm,
        py::arg("global_evaluations") = SearchOptions{}.global_evaluations,
        py::arg("hops") = ForcingDesignOptions{}.hops, py::arg("starts") = py::none(),
        py::arg("stable") = py::none());
}

}  // namespace capsubot::python
