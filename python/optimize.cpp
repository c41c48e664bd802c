// optimize: the fastest gait (docs/model.md section 7) with the margins of a robust gait
// (section 12), every gait checked from rest, as `capsubot optimize --json`: one problem, the
// fastest motion from rest (reach, section 13), or the main job without one.

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <pybind11/stl.h>

#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "capsubot/job/optimize_job.hpp"
#include "capsubot/job/optimize_settings.hpp"
#include "capsubot/model/limits.hpp"
#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/report/optimize_json.hpp"
#include "optimize_keywords.hpp"

namespace capsubot::python {
namespace {

// The reach search's settings: its starts and budgets, the drive's waveform and levels.
struct ReachArgs {
  std::optional<std::string> reach_starts;
  std::optional<int> reach_evaluations, reach_local_evaluations;
  std::optional<double> reach_seconds;
  std::optional<int> drive_evaluations, drive_polishes, drive_local_evaluations,
      drive_refine_evaluations, drive_screens;
  std::optional<std::string> waveform;
  std::optional<int> pulse_levels;
};

void TakeReach(OptimizeSettings& s, const ReachArgs& a) {
  TakeGiven(s.given, "reach_starts", a.reach_starts, s.reach_starts);
  TakeGiven(s.given, "reach_evaluations", a.reach_evaluations, s.reach.global_evaluations);
  TakeGiven(s.given, "reach_local_evaluations", a.reach_local_evaluations,
            s.reach.local_evaluations);
  TakeGiven(s.given, "reach_seconds", a.reach_seconds, s.reach.max_seconds);
  TakeGiven(s.given, "drive_evaluations", a.drive_evaluations, s.reach.drive_evaluations);
  TakeGiven(s.given, "drive_polishes", a.drive_polishes, s.reach.drive_polishes);
  TakeGiven(s.given, "drive_local_evaluations", a.drive_local_evaluations,
            s.reach.drive_local_evaluations);
  TakeGiven(s.given, "drive_refine_evaluations", a.drive_refine_evaluations,
            s.reach.drive_refine_evaluations);
  TakeGiven(s.given, "drive_screens", a.drive_screens, s.reach.drive_screens);
  TakeGiven(s.given, "waveform", a.waveform, s.waveform);
  TakeGiven(s.given, "pulse_levels", a.pulse_levels, s.pulse_levels);
}

py::dict Optimize(std::optional<std::string> problem, std::optional<double> A,
                  std::optional<double> c, double T0, double e, double margin, double margin_stroke,
                  double stick_margin, std::optional<double> bound, std::optional<double> rho_max,
                  bool stable, double max_time, std::optional<int> harmonics,
                  std::optional<std::string> global_algorithm,
                  std::optional<std::string> local_algorithm, std::optional<int> global_evaluations,
                  std::optional<int> hops, std::optional<int> starts, std::optional<double> alpha,
                  const std::string& from_rest_starts, std::optional<std::string> reach_starts,
                  std::optional<int> reach_evaluations, std::optional<int> reach_local_evaluations,
                  std::optional<double> reach_seconds, std::optional<int> drive_evaluations,
                  std::optional<int> drive_polishes, std::optional<int> drive_local_evaluations,
                  std::optional<int> drive_refine_evaluations, std::optional<int> drive_screens,
                  std::optional<std::pair<double, double>> T0_range,
                  std::optional<std::string> waveform, std::optional<int> pulse_levels,
                  std::optional<std::vector<double>> band_levels, int threads) {
  if (stable && rho_max) {
    throw std::invalid_argument(fmt::format(
        "stable conflicts with rho_max = {}: stable=True means rho_max = 1; give one of them",
        *rho_max));
  }
  OptimizeSettings s;
  TakeGiven(s.given, "problem", problem, s.problem);
  TakeGiven(s.given, "A", A, s.A);
  TakeGiven(s.given, "c", c, s.c);
  s.params = Params{T0, e};
  s.search.gait.margins = Margins{margin, margin_stroke, stick_margin};
  if (stable || rho_max) s.search.gait.rho_max = stable ? 1.0 : *rho_max;
  s.search.max_time = max_time;
  TakeSearch(
      s.given,
      {bound, harmonics, starts, hops, global_evaluations, global_algorithm, local_algorithm},
      s.search);
  TakeGiven(s.given, "alpha", alpha, s.alpha);
  if (T0_range) {
    std::tie(s.T0_min, s.T0_max) = *T0_range;
    s.given.insert("T0_range");
  }
  TakeGiven(s.given, "band_levels", band_levels, s.band_levels);
  TakeReach(s, {reach_starts, reach_evaluations, reach_local_evaluations, reach_seconds,
                drive_evaluations, drive_polishes, drive_local_evaluations,
                drive_refine_evaluations, drive_screens, waveform, pulse_levels});
  s.from_rest_starts = from_rest_starts;
  s.threads = CapThreads(threads);
  OptimizeJobOptions job;
  try {
    job = OptimizeJobFrom(s, SettingNames{kOptimizeKeywords, SettingNames::Style::kKeywords});
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument(WithFlagNames(error.what(), kOptimizeKeywords));
  }
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

// The arguments of the search, with their defaults (None: the default, which the argument is
// not given; a problem that does not use an argument refuses it when given).
std::string OptimizeOptionsDoc() {
  const OptimizeSettings d;
  return fmt::format(
      "    bound   force bound (A + c, or max |F|) for forcing/fourier, 0 < bound <= T0\n"
      "            [force]; None: T0\n"
      "    rho_max largest spectral radius of the impact map (capsubot documentation, model\n"
      "            sections 8, 12); float('inf'): no stability requirement; None: {}\n"
      "    stable  the same as rho_max = 1 (not with rho_max)\n"
      "    max_time  time limit [s] of each optimisation (status 'max_time' when reached), > 0\n"
      "    harmonics  number K of harmonics of the Fourier force, 1..16: fourier (None: {}), or\n"
      "            reach (None: the sine; K >= 2: the fastest Fourier drive, climbing from the\n"
      "            sine, with ladder and speed_ratio_to_sine in the result)\n"
      "    global_algorithm  'multistart' or an NLopt global algorithm: GN_ISRES, GN_ORIG_DIRECT,\n"
      "            GN_ORIG_DIRECT_L, GN_AGS (main job, forcing, fourier, reach); None: '{}'\n"
      "    local_algorithm  the local polish: LN_COBYLA, LD_SLSQP, LD_MMA, LD_CCSAQ; None: '{}'\n"
      "    global_evaluations  budget of an NLopt global algorithm, >= 10; None: {}\n"
      "    hops    P2: basin-hopping restarts after the starts, >= 0; None: {}\n"
      "    starts  local polishes of the multistart, >= 1; None: 10 (forcing), 20 (fourier)\n"
      "    reach_starts  grid 'NXxNPSI' of starts from rest inside the reach search (main job,\n"
      "            reach; the winner is re-checked on from_rest_starts); None: '{}'\n"
      "    reach_evaluations, reach_local_evaluations  from-rest evaluations of the reach\n"
      "            search's global stage (DIRECT-L, >= 1) and local polish (Sbplx, >= 0);\n"
      "            None: {}, {}\n"
      "    reach_seconds  wall-clock limit of the reach search [s] (the re-checks come on top);\n"
      "            when it stops the search the result depends on the machine's speed; None: {}\n"
      "    drive_evaluations, drive_polishes, drive_local_evaluations  reach with harmonics >= 2\n"
      "            or a pulse: the Halton points of each step K >= 2 (>= 1), its Nelder-Mead\n"
      "            polishes (>= 1) and their evaluations (>= 0); None: {}, {}, {}\n"
      "    drive_refine_evaluations, drive_screens  reach with harmonics >= 2 or a pulse: the\n"
      "            controlled random search after the Halton points (>= 0) and the short\n"
      "            Nelder-Mead screens before the polishes (>= 0); None: {}, {}\n"
      "    T0_range  reach: (lo, hi), the motor's frequency free: T0 in [lo, hi] (holding T0),\n"
      "            the bound tied to T0, v_mean/sqrt(T0) maximised; frequency in the result\n"
      "    waveform  reach: the drives searched, 'sine', 'fourier' (the default with harmonics)\n"
      "            or 'pulse' (pulse_levels constant levels, 2..16; None: {})\n"
      "    band_levels  main job: the levels of the speed bands, fractions of the speed from\n"
      "            rest in (0, 1); None: {}\n",
      d.search.gait.rho_max, FourierOptions{}.harmonics, d.search.global_algorithm,
      d.search.local_algorithm, d.search.global_evaluations, d.search.hops, d.reach_starts,
      d.reach.global_evaluations, d.reach.local_evaluations, d.reach.max_seconds,
      d.reach.drive_evaluations, d.reach.drive_polishes, d.reach.drive_local_evaluations,
      d.reach.drive_refine_evaluations, d.reach.drive_screens, d.pulse_levels,
      fmt::join(d.band_levels, ", "));
}

constexpr const char* kOptimizeReturnsDoc =
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
                          kFromRestArgsDoc + OptimizeOptionsDoc() + kOptimizeReturnsDoc + kUnits;
  const ForcingDesignOptions p2;
  const Margins robust = RobustMargins();
  m.def("optimize", &Optimize, doc.c_str(), py::kw_only(), py::arg("problem") = py::none(),
        py::arg("A") = py::none(), py::arg("c") = py::none(), py::arg("T0") = Params{}.T0,
        py::arg("e") = Params{}.e, py::arg("margin") = robust.clearance,
        py::arg("margin_stroke") = robust.clearance_stroke, py::arg("stick_margin") = robust.stick,
        py::arg("bound") = py::none(), py::arg("rho_max") = py::none(),
        py::arg("stable").noconvert() = false, py::arg("max_time") = p2.max_time,
        py::arg("harmonics") = py::none(), py::arg("global_algorithm") = py::none(),
        py::arg("local_algorithm") = py::none(), py::arg("global_evaluations") = py::none(),
        py::arg("hops") = py::none(), py::arg("starts") = py::none(), py::arg("alpha") = py::none(),
        py::arg("from_rest_starts") = OptimizeSettings{}.from_rest_starts,
        py::arg("reach_starts") = py::none(), py::arg("reach_evaluations") = py::none(),
        py::arg("reach_local_evaluations") = py::none(), py::arg("reach_seconds") = py::none(),
        py::arg("drive_evaluations") = py::none(), py::arg("drive_polishes") = py::none(),
        py::arg("drive_local_evaluations") = py::none(),
        py::arg("drive_refine_evaluations") = py::none(), py::arg("drive_screens") = py::none(),
        py::arg("T0_range") = py::none(), py::arg("waveform") = py::none(),
        py::arg("pulse_levels") = py::none(), py::arg("band_levels") = py::none(),
        py::arg("threads") = AttractorOptions{}.threads);
}

}  // namespace capsubot::python
