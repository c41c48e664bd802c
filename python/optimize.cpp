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
#include "capsubot/job/reach_effort_settings.hpp"
#include "capsubot/job/search_settings.hpp"
#include "capsubot/model/limits.hpp"
#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/optimize/optimize_search.hpp"
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
    "Arguments (keyword only, named as the options of `capsubot optimize`; None: not given, the "
    "default):\n";

// The arguments of the problem and of the search, from the library's tables of their settings
// (the meanings --help shows), but the few the command line declares by hand too; a problem that
// does not use an argument refuses it when given.
std::string OptimizeArgumentsDoc() {
  const OptimizeSettings d;
  const FlagNames& k = kOptimizeKeywords;
  constexpr DefaultInDoc kNone = DefaultInDoc::kNoneMeans;
  return TableArgumentLines(OptimizeProblemSettings(), d, k, {"problem", "A", "c"}, kNone) +
         ModelArgsDoc() + MarginArgsDoc() + FromRestArgsDoc() +
         TableArgumentLines(GaitBoundSettings(), d.search.gait, k, {"bound", "rho_max"}, kNone) +
         ArgumentLines("stable", "the same as rho_max = 1 (not with rho_max)") +
         TableArgumentLines(SearchSettings(), d.search, k, {"max_time"}, DefaultInDoc::kSignature) +
         TableArgumentLines(
             SearchSettings(), d.search, k,
             {"harmonics", "global_algorithm", "local_algorithm", "global_evaluations", "hops"},
             kNone) +
         ArgumentLines("starts", fmt::format("local polishes of the multistart, 1 to {}; None: 10 "
                                             "(forcing), 20 (fourier)",
                                             kMaxStarts)) +
         TableArgumentLines(OptimizeProblemSettings(), d, k, {"alpha"}, kNone) +
         ArgumentLines("reach_starts",
                       "with the main job or problem reach: grid 'NXxNPSI' of starts from rest "
                       "inside the reach search (the winner is re-checked on from_rest_starts); "
                       "None: '" +
                           d.reach_starts + "'") +
         TableArgumentLines(ReachEffortSettings(), d.reach, k,
                            {"reach_evaluations", "reach_local_evaluations", "reach_seconds",
                             "drive_evaluations", "drive_polishes", "drive_local_evaluations",
                             "drive_refine_evaluations", "drive_screens"},
                            kNone) +
         ArgumentLines("T0_range",
                       "with problem reach: (lo, hi), the motor's frequency free: T0 in [lo, hi] "
                       "(holding T0), the bound tied to T0, v_mean/sqrt(T0) maximised; frequency "
                       "in the result") +
         TableArgumentLines(OptimizeProblemSettings(), d, k, {"waveform", "pulse_levels"}, kNone) +
         ArgumentLines("band_levels",
                       fmt::format("with the main job: the levels of the speed bands, fractions "
                                   "of the speed from rest in (0, 1); None: {}",
                                   fmt::join(d.band_levels, ", ")));
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
  const std::string doc =
      std::string(kOptimizeDoc) + OptimizeArgumentsDoc() + kOptimizeReturnsDoc + kUnits;
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
