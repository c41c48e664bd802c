// optimize: the fastest gait (docs/model.md section 7) with the margins of a robust gait
// (section 12), as `capsubot optimize --json`: one problem, or the main job without one.

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
constexpr double kInf = std::numeric_limits<double>::infinity();
// The robust defaults of `capsubot optimize` (docs/model.md section 12); the library's are 0
// and infinity.
constexpr double kDefaultMarginStroke = 0.02;
constexpr double kDefaultStickMargin = 0.02;
constexpr double kDefaultRhoMax = 0.9;

// The search options the caller gives, as the command line's options.
struct SearchArgs {
  std::optional<double> bound;
  int harmonics;
  std::string global_algorithm, local_algorithm;
  int global_evaluations, hops;
  std::optional<int> starts;
  double rho_max, max_time;
};

// The gait asked for: the force bound, stability, time limit and local polish.
ForcingDesignOptions GaitOptions(const SearchArgs& a, double rho_max) {
  ForcingDesignOptions d;
  d.force_bound = a.bound.value_or(kNaN);
  d.local_algorithm = a.local_algorithm;
  d.rho_max = rho_max;
  d.max_time = a.max_time;
  return d;
}

// P2: the gait asked for, searched as the arguments say.
ForcingDesignOptions DesignOptions(const SearchArgs& a, double rho_max) {
  ForcingDesignOptions d = GaitOptions(a, rho_max);
  d.global_algorithm = a.global_algorithm;
  if (a.starts) d.starts = *a.starts;
  d.global_evaluations = a.global_evaluations;
  d.hops = a.hops;
  return d;
}

FourierOptions FourierFor(const SearchArgs& a) {
  FourierOptions fo;
  fo.harmonic = GaitOptions(a, a.rho_max);
  fo.harmonics = a.harmonics;
  fo.search.global_algorithm = a.global_algorithm;
  if (a.starts) fo.search.starts = *a.starts;
  fo.search.global_evaluations = a.global_evaluations;
  return fo;
}

PhaseOptions PhaseFor(const SearchArgs& a, double rho_max) {
  PhaseOptions po;
  po.rho_max = rho_max;
  po.max_time = a.max_time;
  return po;
}

py::list BindingNames(const OptimizeResult& r) {
  py::list names;
  for (Margin m : r.binding) names.append(MarginName(m));
  return names;
}

// The object of one optimisation result: the optimum's orbit as solve shows it, with the
// optimiser's status in place of the orbit's.
py::dict ResultDict(const OptimizeResult& r, const char* problem) {
  const Forcing& f = r.solution.orbit.forcing;
  py::dict d = SolutionDict(r.solution);
  d["problem"] = problem;
  d["status"] = OptimizeStatusName(r.status);
  d["message"] = r.message;
  d["active_constraints"] = r.active_constraints;
  d["binding"] = BindingNames(r);
  d["evaluations"] = r.evaluations;
  d["algorithm"] = r.algorithm;
  if (!std::isnan(r.spectral_radius)) {
    d["spectral_radius"] = Number(r.spectral_radius);
    d["stable"] = r.spectral_radius < 1.0;
  }
  if (!f.harmonic()) {
    py::dict coefficients;
    coefficients["c"] = Number(f.mean());
    coefficients["cos"] = d["cos"];
    coefficients["sin"] = d["sin"];
    d["coefficients"] = coefficients;
  }
  return d;
}

// The model and the requirements every result of a run shares (rho_max None: none).
void AddRequirements(py::dict& d, const Params& p, double rho_max) {
  d["T0"] = Number(p.T0);
  d["e"] = Number(p.e);
  d["margin"] = Number(p.margin);
  d["margin_stroke"] = Number(p.margin_stroke);
  d["stick_margin"] = Number(p.stick_margin);
  d["rho_max"] = Number(rho_max);
}

// The main job: the paper's problem P1 at c = A = T0/2 (no margins), the fastest robust gait
// (P2 with the margins) and the exact optima without margins (valid; stable).
py::dict MainJob(const Params& p, const SearchArgs& a) {
  Params exact = p;
  exact.margin = exact.margin_stroke = exact.stick_margin = 0.0;
  OptimizeResult paper, robust, fastest, stable;
  {
    py::gil_scoped_release release;
    paper = OptimizePhase(Forcing::Harmonic(p.T0 / 2.0, p.T0 / 2.0, 0.0), exact, PhaseFor(a, kInf));
    robust = OptimizeForcing(p, DesignOptions(a, a.rho_max));
    fastest = OptimizeForcing(exact, DesignOptions(a, kInf));
    stable = OptimizeForcing(exact, DesignOptions(a, 1.0));
  }
  py::dict d;
  AddRequirements(d, p, a.rho_max);
  d["force_bound"] = Number(a.bound.value_or(p.T0));
  const auto add = [&d](const char* key, const OptimizeResult& r, const char* problem,
                        const char* note) {
    py::dict result = ResultDict(r, problem);
    result["note"] = note;
    d[key] = result;
  };
  add("paper", paper, "phase",
      "P1: F = A sin(phi + phi0) + c with c = A = T0/2, best phi0 over valid orbits (no "
      "margins)");
  add("robust", robust, "forcing",
      "P2: A, c, phi0 free with A + c <= force_bound, the margins and spectral radius <= "
      "rho_max");
  add("fastest", fastest, "forcing",
      "P2 without margins or stability requirement: grazes the walls");
  add("fastest_stable", stable, "forcing", "P2 without margins, spectral radius <= 1");
  return d;
}

py::dict Problem(const std::string& problem, std::optional<double> A, std::optional<double> c,
                 const Params& p, const SearchArgs& a) {
  OptimizeResult r;
  if (problem == "phase") {
    if (!A || !c) {
      throw std::invalid_argument(
          "problem 'phase' needs the force shape: give A and c (F = A sin(phi + phi0) + c)");
    }
    const Forcing shape = Forcing::Harmonic(*A, *c, 0.0);
    py::gil_scoped_release release;
    r = OptimizePhase(shape, p, PhaseFor(a, a.rho_max));
  } else if (problem == "forcing") {
    py::gil_scoped_release release;
    r = OptimizeForcing(p, DesignOptions(a, a.rho_max));
  } else {
    py::gil_scoped_release release;
    r = OptimizeFourier(p, FourierFor(a));
  }
  py::dict d = ResultDict(r, problem.c_str());
  AddRequirements(d, p, a.rho_max);
  if (problem == "fourier") {
    d["baseline_I"] = Number(r.baseline_I);
    d["gain"] = Number(r.found() ? r.solution.orbit.I / r.baseline_I - 1.0 : kNaN);
  }
  return d;
}

// An argument the chosen run does not use would be silently ignored: refuse it.
void RejectUnused(const std::string& problem, std::optional<double> A, std::optional<double> c,
                  const SearchArgs& a) {
  const auto reject = [&problem](const char* name, const char* runs) {
    throw std::invalid_argument(fmt::format(
        "{} conflicts with {}: expected {} only with {}", name,
        problem.empty() ? "the main job (problem None)" : "problem '" + problem + "'", name, runs));
  };
  if (problem != "phase" && A) reject("A", "problem 'phase'");
  if (problem != "phase" && c) reject("c", "problem 'phase'");
  if (problem == "phase" && a.bound) reject("bound", "the main job, 'forcing' or 'fourier'");
  if (problem == "phase" && a.starts) reject("starts", "the main job, 'forcing' or 'fourier'");
}

py::dict Optimize(std::optional<std::string> problem, std::optional<double> A,
                  std::optional<double> c, double T0, double e, double margin, double margin_stroke,
                  double stick_margin, std::optional<double> bound, std::optional<double> rho_max,
                  bool stable, double max_time, int harmonics, const std::string& global_algorithm,
                  const std::string& local_algorithm, int global_evaluations, int hops,
                  std::optional<int> starts) {
  const std::string name = problem.value_or("");
  if (!name.empty() && name != "phase" && name != "forcing" && name != "fourier") {
    throw std::invalid_argument(fmt::format(
        "problem = '{}' is invalid: expected 'phase', 'forcing', 'fourier' or None (the main "
        "job)",
        name));
  }
  if (stable && rho_max) {
    throw std::invalid_argument(fmt::format(
        "stable conflicts with rho_max = {}: stable=True means rho_max = 1; give one of them",
        *rho_max));
  }
  if (bound && !(std::isfinite(*bound) && *bound > 0.0)) {
    throw std::invalid_argument(
        fmt::format("bound = {} is invalid: expected a finite bound > 0 (at most T0)", *bound));
  }
  const SearchArgs args{bound,
                        harmonics,
                        global_algorithm,
                        local_algorithm,
                        global_evaluations,
                        hops,
                        starts,
                        stable ? 1.0 : rho_max.value_or(kDefaultRhoMax),
                        max_time};
  RejectUnused(name, A, c, args);
  const Params params{T0, e, margin, margin_stroke, stick_margin};
  params.Validate();
  return name.empty() ? MainJob(params, args) : Problem(name, A, c, params, args);
}

constexpr const char* kOptimizeDoc =
    "The fastest one-impact gait (docs/model.md section 7) with the margins of a robust gait "
    "(section 12): the object `capsubot optimize [--problem <problem>] --json` prints for the "
    "same arguments (same defaults).\n\n"
    "Arguments (keyword only, named as the options of `capsubot optimize`):\n"
    "    problem 'phase' (P1: the best impact phase phi0 for the force shape A, c), 'forcing'\n"
    "            (P2: the best A, c, phi0 with A + c <= bound), 'fourier' (P3: the best\n"
    "            K-harmonic force with max |F| <= bound) or None: the main job (P1 at\n"
    "            c = A = T0/2 without margins, the fastest robust gait, and the exact optima\n"
    "            without margins, valid and stable)\n"
    "    A, c    amplitude A >= 0 and mean c of F = A sin(phi + phi0) + c [force] (phase only)\n";

constexpr const char* kOptimizeOptionsDoc =
    "    bound   force bound (A + c, or max |F|) for forcing/fourier, 0 < bound <= T0\n"
    "            [force]; None: T0\n"
    "    rho_max largest spectral radius of the impact map (docs/model.md sections 8, 12);\n"
    "            float('inf'): no stability requirement; None: 0.9\n"
    "    stable  the same as rho_max = 1 (not with rho_max)\n"
    "    max_time  time limit [s] of each optimisation (status 'max_time' when reached), > 0\n"
    "    harmonics  number K of harmonics of the Fourier force (fourier), 1..16\n"
    "    global_algorithm  'multistart' or an NLopt global algorithm: GN_ISRES, GN_ORIG_DIRECT,\n"
    "            GN_ORIG_DIRECT_L, GN_AGS (main job, forcing, fourier)\n"
    "    local_algorithm  the local polish: LN_COBYLA, LD_SLSQP, LD_MMA, LD_CCSAQ\n"
    "    global_evaluations  budget of an NLopt global algorithm, >= 10\n"
    "    hops    P2: basin-hopping restarts after the starts, >= 0\n"
    "    starts  local polishes of the multistart, >= 1; None: 10 (forcing), 20 (fourier)\n\n"
    "Returns a dict. For a problem: the keys of solve for the optimum (A, c, phi0, phi1, "
    "alpha, u, v_plus, I, v_mean, x_min, x_max, stroke, clearance, valid, violations; cos, sin "
    "and coefficients for fourier), problem, status ('ok', 'no_valid_orbit', "
    "'max_evaluations', 'max_time', ...), message, active_constraints, binding (the margins "
    "the optimum touches), evaluations, algorithm, spectral_radius and stable (when the orbit "
    "exists), T0, e, margin, margin_stroke, stick_margin, rho_max (None: infinity); for "
    "fourier also baseline_I (the P2 optimum's I) and gain. With status 'no_valid_orbit' the "
    "orbit is the point nearest to validity. For the main job: T0, e, the margins, rho_max, "
    "force_bound and the results paper, robust, fastest, fastest_stable (each with a "
    "note).\n\n"
    "Raises ValueError for bad input (the message names the parameter, its value and the "
    "rule). Runs without the GIL (other Python threads go on).\n\n";

}  // namespace

void BindOptimize(py::module_& m) {
  const std::string doc = std::string(kOptimizeDoc) + kModelArgsDoc + kMarginArgsDoc +
                          "            (margin_stroke and stick_margin default to 0.02 here)\n" +
                          kOptimizeOptionsDoc + kUnits;
  const ForcingDesignOptions p2;
  m.def("optimize", &Optimize, doc.c_str(), py::kw_only(), py::arg("problem") = py::none(),
        py::arg("A") = py::none(), py::arg("c") = py::none(), py::arg("T0") = Params{}.T0,
        py::arg("e") = Params{}.e, py::arg("margin") = Params{}.margin,
        py::arg("margin_stroke") = kDefaultMarginStroke,
        py::arg("stick_margin") = kDefaultStickMargin, py::arg("bound") = py::none(),
        py::arg("rho_max") = py::none(), py::arg("stable") = false,
        py::arg("max_time") = p2.max_time, py::arg("harmonics") = FourierOptions{}.harmonics,
        py::arg("global_algorithm") = p2.global_algorithm,
        py::arg("local_algorithm") = p2.local_algorithm,
        py::arg("global_evaluations") = p2.global_evaluations, py::arg("hops") = p2.hops,
        py::arg("starts") = py::none());
}

}  // namespace capsubot::python
