#include "capsubot/job/optimize_settings.hpp"

#include <fmt/format.h>

#include <cmath>
#include <iterator>
#include <stdexcept>

#include "capsubot/attract/start_grid.hpp"
#include "capsubot/model/limits.hpp"

namespace capsubot {

const SettingTable<OptimizeSettings>& OptimizeProblemSettings() {
  using O = OptimizeSettings;
  // Each help opens with the problems that use its setting (WithModes).
  static const SettingTable<OptimizeSettings> table = WithModes<OptimizeSettings>(
      {{"problem", &O::problem,
        "phase (P1: best phi0 for given {A}, {c}), forcing (P2: best A, c, phi0 with A + c <= "
        "{bound}), fourier (P3: best K-harmonic force with max |F| <= {bound}) or reach (the "
        "fastest motion from rest: A, c, alpha with A + c <= {bound}, simulated, seeded with the "
        "robust P2 gait); default: the main job"},
       {"A", &O::A, "amplitude A >= 0 of F = A sin(phi + phi0) + c, in units of (m1+m2) omega^2 L"},
       {"c", &O::c, "mean force c > 0 of F (same unit)"},
       {"alpha", &O::alpha, "a fixed mass ratio 0 < alpha < 1 (default: alpha is optimised too)"},
       {"waveform", &O::waveform,
        "the drives searched: sine (A sin(phi + phi0) + c, the default), fourier ({harmonics} K, "
        "the default when {harmonics} is given) or pulse ({pulse_levels} N constant levels "
        "between switching phases), all with max |F| <= {bound}"},
       {"pulse_levels", &O::pulse_levels,
        "the number N of levels of the {waveform} pulse, 2 <= N <= 16"}},
      OptimizeSettingUses(), OptimizeModes());
  return table;
}

const std::vector<SettingUse>& OptimizeSettingUses() {
  // The P2 settings apply to reach through its seed, the robust gait.
  static const std::vector<SettingUse> uses = {
      {"A", {"phase"}},
      {"c", {"phase"}},
      {"harmonics", {"fourier", "reach"}},
      {"hops", {"", "forcing", "reach"}},
      {"starts", {"", "forcing", "fourier", "reach"}},
      {"bound", {"", "forcing", "fourier", "reach"}},
      {"global_algorithm", {"", "forcing", "fourier", "reach"}},
      {"local_algorithm", {"", "forcing", "fourier", "reach"}},
      {"global_evaluations", {"", "forcing", "fourier", "reach"}},
      {"alpha", {"reach"}},
      {"T0_range", {"reach"}},
      {"waveform", {"reach"}},
      {"pulse_levels", {"reach"}},
      {"reach_starts", {"", "reach"}},
      {"reach_evaluations", {"", "reach"}},
      {"reach_local_evaluations", {"", "reach"}},
      {"reach_seconds", {"", "reach"}},
      {"drive_evaluations", {"reach"}},
      {"drive_refine_evaluations", {"reach"}},
      {"drive_screens", {"reach"}},
      {"drive_polishes", {"reach"}},
      {"drive_local_evaluations", {"reach"}},
      {"band_levels", {""}},
  };
  return uses;
}

const ModeSet& OptimizeModes() {
  static const ModeSet modes = {
      "problem", {"phase", "forcing", "fourier", "reach"}, "the main job"};
  return modes;
}

namespace {

// The budgets of the search of a drive (a Fourier drive of K >= 2, or a pulse drive).
constexpr const char* kDriveBudgets[] = {"drive_evaluations", "drive_polishes",
                                         "drive_local_evaluations", "drive_refine_evaluations",
                                         "drive_screens"};

// Whether the reach problem of `s` searches a drive beyond the sine: a pulse drive, or a Fourier
// drive of K >= 2 harmonics (K = 1 is the sine: no drive search runs).
bool SearchesDrive(const OptimizeSettings& s) {
  return s.waveform == "pulse" ||
         (s.search.harmonics >= 2 && (s.Given("harmonics") || s.waveform == "fourier"));
}

}  // namespace

std::vector<std::string> UnusedOptimizeSettings(const OptimizeSettings& settings) {
  std::vector<std::string> unused = UnusedSettings(OptimizeSettingUses(), settings.problem);
  if (settings.search.global_algorithm == kMultistart) unused.emplace_back("global_evaluations");
  if (settings.problem == "reach") {
    if (!SearchesDrive(settings))
      unused.insert(unused.end(), std::begin(kDriveBudgets), std::end(kDriveBudgets));
    if (settings.waveform != "pulse") unused.emplace_back("pulse_levels");
  }
  return unused;
}

std::string OptimizeProblemName(const std::string& problem, const SettingNames& names) {
  if (problem.empty()) return fmt::format("the main job ({})", names.Absent("problem"));
  return names.Given("problem", problem);
}

namespace {

// The budgets of a drive search want a drive: a Fourier drive of K >= 2 or a pulse drive.
void RejectDriveBudgetsWithoutDrive(const OptimizeSettings& s, const SettingNames& names) {
  if (SearchesDrive(s)) return;
  for (const char* field : kDriveBudgets) {
    if (!s.Given(field)) continue;
    const std::string name = names.Name(field);
    throw std::invalid_argument(fmt::format(
        "{} conflicts with {} without {} K >= 2 or {}: expected {} only with a Fourier drive of "
        "K >= 2 harmonics or a pulse drive",
        name, OptimizeProblemName(s.problem, names), names.Name("harmonics"),
        names.Given("waveform", "pulse"), name));
  }
}

// The problem must be one of the job's (given as "": not a problem; not given: the main job).
void RequireKnownProblem(const OptimizeSettings& s, const SettingNames& names) {
  const std::string& p = s.problem;
  if ((p.empty() && !s.Given("problem")) || p == "phase" || p == "forcing" || p == "fourier" ||
      p == "reach") {
    return;
  }
  const auto value = [&names](const std::string& text) { return names.Value(text); };
  throw std::invalid_argument(fmt::format(
      "{} = {} is invalid: expected {}, {}, {}, {} or {} (the main job)", names.Name("problem"),
      value(p), value("phase"), value("forcing"), value("fourier"), value("reach"),
      names.style == SettingNames::Style::kFlags ? "none" : "None"));
}

// The settings given together that contradict each other or that the problem ignores.
void RejectConflicts(const OptimizeSettings& s, const SettingNames& names) {
  RejectUnusedSettings(
      OptimizeSettingUses(), s.given, s.problem,
      [&names](const std::string& problem) { return OptimizeProblemName(problem, names); }, names);
  RejectDriveBudgetsWithoutDrive(s, names);
  if (s.Given("global_evaluations") && s.search.global_algorithm == kMultistart) {
    throw std::invalid_argument(fmt::format(
        "{} conflicts with {}: expected an NLopt global algorithm with it (multistart has no "
        "evaluation budget)",
        names.Name("global_evaluations"), names.Given("global_algorithm", kMultistart)));
  }
}

// A value given must be admissible itself: NaN (the library's "use T0" for the bound, "not
// given" for A and c) is not a default.
void RequireAdmissible(const OptimizeSettings& s, const std::string& field, bool ok, double value,
                       const char* rule, const SettingNames& names) {
  if (s.Given(field) && !ok) {
    throw std::invalid_argument(
        fmt::format("{} = {} is invalid: expected {}", names.Name(field), value, rule));
  }
}

// A size given must lie in [lo, hi], checked before any work.
void RequireInRange(const std::string& field, long long value, long long lo, long long hi,
                    const SettingNames& names) {
  if (value < lo || value > hi) {
    throw std::invalid_argument(fmt::format("{} = {} is invalid: expected {} <= {} <= {}",
                                            names.Name(field), value, lo, names.InRule(field), hi));
  }
}

void RequireAdmissibleValues(const OptimizeSettings& s, const SettingNames& names) {
  const SearchRequest& search = s.search;
  RequireAdmissible(s, "A", std::isfinite(s.A) && s.A >= 0.0, s.A, "a finite amplitude A >= 0",
                    names);
  RequireAdmissible(s, "c", std::isfinite(s.c), s.c, "a finite mean force c", names);
  RequireAdmissible(s, "alpha", !std::isnan(s.alpha), s.alpha, "a mass ratio 0 < alpha < 1", names);
  if (s.Given("T0_range") && !(s.T0_min > 0.0 && s.T0_min < s.T0_max && std::isfinite(s.T0_max))) {
    const bool flags = names.style == SettingNames::Style::kFlags;
    throw std::invalid_argument(
        fmt::format(flags ? "{} = {}:{} is invalid: expected LO:HI, two numbers 0 < LO < HI"
                          : "{} = ({}, {}) is invalid: expected (lo, hi), two numbers 0 < lo < hi",
                    names.Name("T0_range"), s.T0_min, s.T0_max));
  }
  RequireAdmissible(s, "bound",
                    std::isfinite(search.gait.force_bound) && search.gait.force_bound > 0.0,
                    search.gait.force_bound, "a finite bound > 0 (at most T0)", names);
  if (search.starts) RequireInRange("starts", *search.starts, 1, kMaxStarts, names);
  RequireInRange("hops", search.hops, 0, kMaxStarts, names);
  RequireInRange("global_evaluations", search.global_evaluations, kMinStageEvaluations,
                 kMaxStageEvaluations, names);
  if (!(search.gait.rho_max > 0.0)) {
    throw std::invalid_argument(
        fmt::format("{} = {} is invalid: expected rho_max > 0 (inf: no stability requirement)",
                    names.Name("rho_max"), search.gait.rho_max));
  }
  if (!(search.max_time > 0.0)) {
    throw std::invalid_argument(
        fmt::format("{} = {} is invalid: expected a time limit > 0 seconds (inf: none)",
                    names.Name("max_time"), search.max_time));
  }
  if (s.problem == "phase" && (std::isnan(s.A) || std::isnan(s.c))) {
    throw std::invalid_argument(
        fmt::format("{} needs the force shape: give {} and {} (F = A sin(phi + phi0) + c)",
                    OptimizeProblemName("phase", names), names.Name("A"), names.Name("c")));
  }
}

// The drives of the reach problem: the waveform pulse (pulse_levels N), fourier (harmonics K,
// whose default waveform it is), or the sine.
DriveFamily ReachDrive(const OptimizeSettings& s, const SettingNames& names) {
  if (!((s.waveform.empty() && !s.Given("waveform")) || s.waveform == "sine" ||
        s.waveform == "fourier" || s.waveform == "pulse")) {
    throw std::invalid_argument(fmt::format("{} = {} is invalid: expected {}, {} or {}",
                                            names.Name("waveform"), names.Value(s.waveform),
                                            names.Value("sine"), names.Value("fourier"),
                                            names.Value("pulse")));
  }
  const std::string harmonics = names.Name("harmonics");
  const std::string levels = names.Name("pulse_levels");
  if (s.waveform == "pulse") {
    if (s.Given("harmonics")) {
      throw std::invalid_argument(fmt::format(
          "{} conflicts with {}: expected {} only with a Fourier drive ({} N sizes a pulse "
          "drive)",
          harmonics, names.Given("waveform", "pulse"), harmonics, levels));
    }
    return DriveFamily::Pulse(s.pulse_levels);
  }
  if (s.Given("pulse_levels")) {
    const std::string waveform =
        s.waveform.empty() ? (s.Given("harmonics") ? "fourier" : "sine") : s.waveform;
    throw std::invalid_argument(fmt::format("{} conflicts with {}: expected {} only with {}",
                                            levels, names.Given("waveform", waveform), levels,
                                            names.Given("waveform", "pulse")));
  }
  if (s.waveform == "sine") {
    if (s.Given("harmonics") && s.search.harmonics != 1) {
      throw std::invalid_argument(fmt::format("{} = {} conflicts with {}: expected {} 1 or none",
                                              harmonics, s.search.harmonics,
                                              names.Given("waveform", "sine"), harmonics));
    }
    return DriveFamily{};
  }
  if (s.Given("harmonics") || s.waveform == "fourier") {
    return DriveFamily::Fourier(s.search.harmonics);
  }
  return DriveFamily{};
}

// The reach search's effort: its grid of starts and its budgets.
ReachEffort ReachEffortOf(const OptimizeSettings& s) {
  ReachEffort effort = s.reach;
  const StartGrid grid = ParseStartGrid("reach_starts", s.reach_starts);
  effort.n_x = grid.n_x;
  effort.n_psi = grid.n_psi;
  return effort;
}

// The problem as a type of its own, holding only the settings it uses.
OptimizeMode ModeOf(const OptimizeSettings& s, const SettingNames& names) {
  const std::string& problem = s.problem;
  if (problem.empty()) return MainJob{ReachEffortOf(s), s.band_levels};
  if (problem == "phase") return PhaseProblem{s.A, s.c};
  if (problem == "forcing") return ForcingProblem{};
  if (problem == "fourier") return FourierProblem{};
  if (problem == "reach") {
    return ReachProblem{ReachEffortOf(s), s.alpha, ReachDrive(s, names), s.T0_min, s.T0_max};
  }
  throw std::logic_error("problem " + problem + " has no mode");
}

}  // namespace

OptimizeJobOptions OptimizeJobFrom(const OptimizeSettings& settings, const SettingNames& names) {
  RequireKnownProblem(settings, names);
  RejectConflicts(settings, names);
  RequireAdmissibleValues(settings, names);
  OptimizeJobOptions job;
  job.mode = ModeOf(settings, names);
  job.params = settings.params;
  job.search = settings.search;
  const StartGrid grid = ParseStartGrid("from_rest_starts", settings.from_rest_starts);
  job.check.n_x = grid.n_x;
  job.check.n_psi = grid.n_psi;
  job.check.attractor.threads = settings.threads;
  job.Validate();
  return job;
}

}  // namespace capsubot
