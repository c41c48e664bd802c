// optimize: the fastest gait (docs/model.md section 7) with the margins of a robust gait
// (section 12), every gait checked from rest, as `capsubot optimize --json`: one problem, the
// fastest motion from rest (reach, section 13), or the main job without one.

#include <fmt/format.h>
#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

#include "bindings.hpp"
#include "capsubot/job/optimize_job.hpp"
#include "capsubot/model/limits.hpp"
#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/report/optimize_json.hpp"

namespace capsubot::python {
namespace {

// An argument the chosen run does not use would be silently ignored: refuse it.
void RejectUnused(const std::string& problem, std::optional<double> A, std::optional<double> c,
                  std::optional<double> alpha, std::optional<int> harmonics,
                  std::optional<std::pair<double, double>> T0_range, const SearchRequest& search) {
  const auto reject = [&problem](const char* name, const char* runs) {
    throw std::invalid_argument(fmt::format(
        "{} conflicts with {}: expected {} only with {}", name,
        problem.empty() ? "the main job (problem None)" : "problem '" + problem + "'", name, runs));
  };
  if (problem != "phase" && A) reject("A", "problem 'phase'");
  if (problem != "phase" && c) reject("c", "problem 'phase'");
  if (problem != "reach" && alpha) reject("alpha", "problem 'reach'");
  if (problem != "reach" && T0_range) reject("T0_range", "problem 'reach'");
  if (problem != "fourier" && problem != "reach" && harmonics) {
    reject("harmonics", "problem 'fourier' or 'reach'");
  }
  if (problem == "phase" && !std::isnan(search.gait.force_bound)) {
    reject("bound", "the main job, 'forcing', 'fourier' or 'reach'");
  }
  if (problem == "phase" && search.starts) {
    reject("starts", "the main job, 'forcing', 'fourier' or 'reach'");
  }
  if (problem == "phase" && (!A || !c)) {
    throw std::invalid_argument(
        "problem 'phase' needs the force shape: give A and c (F = A sin(phi + phi0) + c)");
  }
}

py::dict Optimize(std::optional<std::string> problem, std::optional<double> A,
                  std::optional<double> c, double T0, double e, double margin, double margin_stroke,
                  double stick_margin, std::optional<double> bound, std::optional<double> rho_max,
                  bool stable, double max_time, std::optional<int> harmonics,
                  const std::string& global_algorithm, const std::string& local_algorithm,
                  int global_evaluations, int hops, std::optional<int> starts,
                  std::optional<double> alpha, const std::string& from_rest_starts,
                  const std::string& reach_starts, int reach_evaluations,
                  int reach_local_evaluations, double reach_seconds, int drive_evaluations,
                  int drive_polishes, int drive_local_evaluations, int drive_refine_evaluations,
                  int drive_screens, std::optional<std::pair<double, double>> T0_range,
                  int threads) {
  const std::string name = problem.value_or("");
  if (!name.empty() && name != "phase" && name != "forcing" && name != "fourier" &&
      name != "reach") {
    throw std::invalid_argument(fmt::format(
        "problem = '{}' is invalid: expected 'phase', 'forcing', 'fourier', 'reach' or None "
        "(the main job)",
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
  OptimizeJobOptions job;
  job.search.gait.force_bound = bound.value_or(kNaN);
  if (stable || rho_max) job.search.gait.rho_max = stable ? 1.0 : *rho_max;
  job.search.max_time = max_time;
  job.search.global_algorithm = global_algorithm;
  job.search.local_algorithm = local_algorithm;
  job.search.starts = starts;
  job.search.global_evaluations = global_evaluations;
  job.search.hops = hops;
  job.search.harmonics = harmonics.value_or(FourierOptions{}.harmonics);
  RejectUnused(name, A, c, alpha, harmonics, T0_range, job.search);
  job.params = Params{T0, e, margin, margin_stroke, stick_margin};
  job.check = FromRestCheck(from_rest_starts, threads);
  ReachEffort effort;
  effort.global_evaluations = reach_evaluations;
  effort.local_evaluations = reach_local_evaluations;
  effort.max_seconds = reach_seconds;
  effort.drive_evaluations = drive_evaluations;
  effort.drive_polishes = drive_polishes;
  effort.drive_local_evaluations = drive_local_evaluations;
  effort.drive_refine_evaluations = drive_refine_evaluations;
  effort.drive_screens = drive_screens;
  if (name.empty() || name == "reach") {
    const StartGrid grid = ParseStartGrid("reach_starts", reach_starts);
    effort.n_x = grid.n_x;
    effort.n_psi = grid.n_psi;
  }
  if (name.empty()) job.mode = MainJob{effort};
  if (name == "phase") job.mode = PhaseProblem{*A, *c};
  if (name == "forcing") job.mode = ForcingProblem{};
  if (name == "fourier") job.mode = FourierProblem{};
  if (name == "reach") {
    job.mode = ReachProblem{effort, alpha.value_or(kNaN),
                            harmonics ? DriveFamily::Fourier(*harmonics) : DriveFamily{},
                            T0_range ? T0_range->first : kNaN, T0_range ? T0_range->second : kNaN};
  }
  job.Validate();
  const nlohmann::json result = RunWithoutGil([&](SignalCheck& signals) {
    job.search.interrupt = signals.AsInterrupt();
    return json::OptimizeJobJson(RunOptimizeJob(job));
  });
  return py::dict(ToPython(result));
}

constexpr const char* kOptimizeDoc =
    "The fastest one-impact gait (capsubot documentation, model section 7) with the margins of a "
    "robust gait (section 12), every gait checked from rest, or the fastest motion from rest "
    "(section 13): the object `capsubot optimize [--problem <problem>] --json` prints for the "
    "same arguments (same defaults), without its provenance.\n\n"
    "Arguments (keyword only, named as the options of `capsubot optimize`):\n"
    "    problem 'phase' (P1: the best impact phase phi0 for the force shape A, c), 'forcing'\n"
    "            (P2: the best A, c, phi0 with A + c <= bound), 'fourier' (P3: the best\n"
    "            K-harmonic force with max |F| <= bound), 'reach' (the fastest motion from rest:\n"
    "            A, c, alpha with A + c <= bound, simulated, seeded with the robust P2 gait) or\n"
    "            None: the main job (P1 at c = A = T0/2 without margins, the fastest robust\n"
    "            gait checked from rest, the fastest motion from rest, and the exact optima\n"
    "            without margins, valid and stable)\n"
    "    A, c    amplitude A >= 0 and mean c of F = A sin(phi + phi0) + c [force] (phase only)\n"
    "    alpha   reach: a fixed mass ratio 0 < alpha < 1 (None: alpha is optimised too)\n";

constexpr const char* kOptimizeOptionsDoc =
    "    bound   force bound (A + c, or max |F|) for forcing/fourier, 0 < bound <= T0\n"
    "            [force]; None: T0\n"
    "    rho_max largest spectral radius of the impact map (capsubot documentation, model\n"
    "            sections 8, 12); float('inf'): no stability requirement; None: 0.9\n"
    "    stable  the same as rho_max = 1 (not with rho_max)\n"
    "    max_time  time limit [s] of each optimisation (status 'max_time' when reached), > 0\n"
    "    harmonics  number K of harmonics of the Fourier force, 1..16: fourier (None: 3), or\n"
    "            reach (None: the sine; K >= 2: the fastest Fourier drive, climbing from the\n"
    "            sine, with ladder and speed_ratio_to_sine in the result)\n"
    "    global_algorithm  'multistart' or an NLopt global algorithm: GN_ISRES, GN_ORIG_DIRECT,\n"
    "            GN_ORIG_DIRECT_L, GN_AGS (main job, forcing, fourier)\n"
    "    local_algorithm  the local polish: LN_COBYLA, LD_SLSQP, LD_MMA, LD_CCSAQ\n"
    "    global_evaluations  budget of an NLopt global algorithm, >= 10\n"
    "    hops    P2: basin-hopping restarts after the starts, >= 0\n"
    "    starts  local polishes of the multistart, >= 1; None: 10 (forcing), 20 (fourier)\n"
    "    reach_starts  grid 'NXxNPSI' of starts from rest inside the reach search (main job,\n"
    "            reach; the winner is re-checked on from_rest_starts)\n"
    "    reach_evaluations, reach_local_evaluations  from-rest evaluations of the reach\n"
    "            search's global stage (DIRECT-L, >= 1) and local polish (Sbplx, >= 0)\n"
    "    reach_seconds  wall-clock limit of the reach search [s] (the re-checks come on top);\n"
    "            when it stops the search the result depends on the machine's speed\n"
    "    drive_evaluations, drive_polishes, drive_local_evaluations  reach with harmonics >= 2:\n"
    "            the Halton points of each step K >= 2 (>= 1), its Nelder-Mead polishes (>= 1)\n"
    "            and their evaluations (>= 0)\n"
    "    drive_refine_evaluations, drive_screens  reach with harmonics >= 2 or a pulse: the\n"
    "            controlled random search after the Halton points (>= 0) and the short\n"
    "            Nelder-Mead screens before the polishes (>= 0)\n"
    "    T0_range  reach: (lo, hi), the motor's frequency free: T0 in [lo, hi] (holding T0),\n"
    "            the bound tied to T0, v_mean/sqrt(T0) maximised; frequency in the result\n"
    "Returns a dict. For a problem: the keys of solve for the optimum (A, c, phi0, phi1, "
    "alpha, u, v_plus, I, v_mean, x_min, x_max, stroke, clearance, valid, violations; cos, sin "
    "and coefficients for fourier), problem, status ('ok', 'no_valid_orbit', "
    "'max_evaluations', 'max_time', ...), message, active_constraints, binding (the margins "
    "the optimum touches), evaluations, algorithm, spectral_radius and stable (when the orbit "
    "exists), T0, e, margin, margin_stroke, stick_margin, rho_max (None: infinity), from_rest "
    "(the optimum checked from rest: the dict of attractors() plus reached and summary; None "
    "without an orbit); for fourier also baseline_I (the P2 optimum's I) and gain. With status "
    "'no_valid_orbit' the orbit is the point nearest to validity. For reach: A, c, phi0, "
    "alpha, mean_velocity (over the starts from rest), status, message, attractors, summary, "
    "spread, seed_won, robust_to_settings, evaluations, rejected_evaluations, "
    "algorithm, seed and the requirements (capsubot documentation, reach). For the main job: T0, "
    "e, the margins, rho_max, force_bound and the results paper, robust (with from_rest), "
    "reach, fastest, fastest_stable (each but reach with a note).\n\n"
    "Raises ValueError for bad input (the message names the parameter, its value and the "
    "rule). Runs without the GIL (other Python threads go on); Ctrl-C interrupts it "
    "(KeyboardInterrupt).\n\n";

}  // namespace

void BindOptimize(py::module_& m) {
  const std::string doc = std::string(kOptimizeDoc) + kModelArgsDoc + kMarginArgsDoc +
                          "            (margin_stroke and stick_margin default to 0.02 here)\n" +
                          kFromRestArgsDoc + kOptimizeOptionsDoc + kUnits;
  const ForcingDesignOptions p2;
  const ReachOptions reach;
  const Params robust = OptimizeJobOptions::RobustParams();
  m.def("optimize", &Optimize, doc.c_str(), py::kw_only(), py::arg("problem") = py::none(),
        py::arg("A") = py::none(), py::arg("c") = py::none(), py::arg("T0") = Params{}.T0,
        py::arg("e") = Params{}.e, py::arg("margin") = Params{}.margin,
        py::arg("margin_stroke") = robust.margin_stroke,
        py::arg("stick_margin") = robust.stick_margin, py::arg("bound") = py::none(),
        py::arg("rho_max") = py::none(), py::arg("stable").noconvert() = false,
        py::arg("max_time") = p2.max_time, py::arg("harmonics") = py::none(),
        py::arg("global_algorithm") = p2.effort.global_algorithm,
        py::arg("local_algorithm") = p2.local_algorithm,
        py::arg("global_evaluations") = p2.effort.global_evaluations, py::arg("hops") = p2.hops,
        py::arg("starts") = py::none(), py::arg("alpha") = py::none(),
        py::arg("from_rest_starts") = kDefaultFromRestStarts,
        py::arg("reach_starts") = kDefaultReachStarts,
        py::arg("reach_evaluations") = reach.global_evaluations,
        py::arg("reach_local_evaluations") = reach.local_evaluations,
        py::arg("reach_seconds") = reach.max_seconds,
        py::arg("drive_evaluations") = ReachEffort{}.drive_evaluations,
        py::arg("drive_polishes") = ReachEffort{}.drive_polishes,
        py::arg("drive_local_evaluations") = ReachEffort{}.drive_local_evaluations,
        py::arg("drive_refine_evaluations") = ReachEffort{}.drive_refine_evaluations,
        py::arg("drive_screens") = ReachEffort{}.drive_screens, py::arg("T0_range") = py::none(),
        py::arg("threads") = AttractorOptions{}.threads);
}

}  // namespace capsubot::python
