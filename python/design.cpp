// design: a real robot in SI units; the inner mass (and motor frequency) of its fastest robust
// one-impact gait, with speed, power and cost of transport, or its fastest drive from rest, as
// `capsubot design --json`. The robot's settings are the library's table
// (capsubot/config/design_config.hpp), read as the command line reads them: a config file, then
// the keyword arguments.

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <pybind11/stl.h>

#include <cmath>
#include <cstdint>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "capsubot/attract/start_grid.hpp"
#include "capsubot/config/design_config.hpp"
#include "capsubot/io/io.hpp"
#include "capsubot/job/design_job.hpp"
#include "capsubot/job/design_settings.hpp"
#include "capsubot/job/reach_effort_settings.hpp"
#include "capsubot/model/limits.hpp"
#include "capsubot/report/design_json.hpp"
#include "design_keywords.hpp"

namespace capsubot::python {
namespace {

// The keyword of a setting of the robot (or of "config", "drive", "force-max"): its name with
// _ for -, force-amplitude -> force_amplitude.
std::string Keyword(std::string name) {
  for (char& c : name) {
    if (c == '-') c = '_';
  }
  return name;
}

// The module's names of the robot's settings in the library's messages.
DesignConfigNames KeywordNamesOfSettings() { return {Keyword, Keyword, "as keyword arguments"}; }

// The robot's settings, in the table's order: the keyword arguments design() declares.
constexpr std::size_t kRobotSettingCount = 17;

const std::vector<std::string>& RobotKeywords() {
  static const std::vector<std::string> keywords = [] {
    std::vector<std::string> out;
    for (const DesignRobotSetting& s : DesignRobotSettings()) out.push_back(Keyword(s.name));
    return out;
  }();
  return keywords;
}

// A number as the text the library reads: shortest round-trip form, "nan" for NaN (which the
// library refuses, as the command line refuses --m1 nan); anything else as its repr, which the
// library refuses with its rule.
std::string NumberText(const py::handle& x) {
  if (py::isinstance<py::bool_>(x)) return py::repr(x);
  if (PyIndex_Check(x.ptr())) return py::str(py::int_(py::reinterpret_borrow<py::object>(x)));
  if (PyFloat_Check(x.ptr())) {
    const double value = x.cast<double>();
    return std::isnan(value) ? "nan" : FormatNumber(value);
  }
  return py::repr(x);
}

// A keyword argument's value as the text of the setting: a str as it is ("10:40"), a sequence
// joined as a list "0.5,0.1" or a range "10:40", a number; anything else as its repr.
std::string SettingText(const DesignRobotSetting& setting, const py::handle& x) {
  if (py::isinstance<py::str>(x)) return x.cast<std::string>();
  // An empty sequence as Python shows it ([]), which the library refuses.
  if (!py::isinstance<py::sequence>(x) || py::len(x) == 0) return NumberText(x);
  const std::string separator = std::string(setting.syntax) == "MIN:MAX" ? ":" : ",";
  std::string text;
  for (const py::handle element : x) {
    text += (text.empty() ? "" : separator) + NumberText(element);
  }
  return text;
}

// The robot from the config file and the keyword arguments given (not None), as the command
// line builds it from --config and its flags.
DesignInput RobotInput(const std::optional<std::string>& config,
                       const std::vector<py::object>& robot, bool motor_force) {
  DesignConfigInput input;
  input.config = config.value_or("");
  input.motor_force = motor_force;
  const std::vector<DesignRobotSetting>& settings = DesignRobotSettings();
  for (std::size_t i = 0; i < settings.size(); ++i) {
    if (!robot[i].is_none())
      input.given.emplace_back(settings[i].name, SettingText(settings[i], robot[i]));
  }
  return BuildDesignInput(input, KeywordNamesOfSettings());
}

// The from-rest part's arguments; None: not given (the part's default).
struct FromRestArgs {
  std::optional<std::string> from_rest_starts, reach_starts;
  std::optional<int> reach_evaluations, reach_local_evaluations;
  std::optional<double> reach_seconds;
  std::optional<int> threads;
};

// The drive design's arguments; None: not given (the command line's default).
struct DriveArgs {
  std::optional<std::string> drive;
  std::optional<double> force_max;
  std::optional<int> harmonics, pulse_levels;
  std::optional<int> drive_evaluations, drive_polishes, drive_local_evaluations,
      drive_refine_evaluations, drive_screens;
};

// The settings of the runs given (not None), by field.
std::set<std::string> GivenSettings(const FromRestArgs& r, const DriveArgs& d, bool band_levels) {
  std::set<std::string> given;
  const auto take = [&given](const char* field, bool is_given) {
    if (is_given) given.insert(field);
  };
  take("from_rest_starts", r.from_rest_starts.has_value());
  take("reach_starts", r.reach_starts.has_value());
  take("reach_evaluations", r.reach_evaluations.has_value());
  take("reach_local_evaluations", r.reach_local_evaluations.has_value());
  take("reach_seconds", r.reach_seconds.has_value());
  take("threads", r.threads.has_value());
  take("force_max", d.force_max.has_value());
  take("harmonics", d.harmonics.has_value());
  take("pulse_levels", d.pulse_levels.has_value());
  take("drive_evaluations", d.drive_evaluations.has_value());
  take("drive_polishes", d.drive_polishes.has_value());
  take("drive_local_evaluations", d.drive_local_evaluations.has_value());
  take("drive_refine_evaluations", d.drive_refine_evaluations.has_value());
  take("drive_screens", d.drive_screens.has_value());
  take("band_levels", band_levels);
  return given;
}

// A setting given to a run that does not use it is refused, as the command line refuses it
// (DesignSettingUses, RejectUnusedDriveSettings), before the robot is read.
void RejectUnusedArguments(const std::set<std::string>& given, const DriveArgs& d, bool from_rest) {
  const DesignRunChoice choice{d.drive, false, from_rest};
  choice.RejectUnused(given, kDesignKeywords, DesignRunKeywords);
}

// Part (b) as the arguments give it.
DesignFromRestPart FromRestPart(const FromRestArgs& a) {
  DesignFromRestPart part;
  part.from_rest_starts =
      ParseStartGrid("from_rest_starts", a.from_rest_starts.value_or(part.from_rest_starts.Text()));
  part.reach_starts =
      ParseStartGrid("reach_starts", a.reach_starts.value_or(part.reach_starts.Text()));
  part.reach_evaluations = a.reach_evaluations.value_or(part.reach_evaluations);
  part.reach_local_evaluations = a.reach_local_evaluations.value_or(part.reach_local_evaluations);
  part.reach_seconds = a.reach_seconds.value_or(part.reach_seconds);
  part.threads = CapThreads(a.threads.value_or(part.threads));
  return part;
}

// The fastest drive as the arguments give it, with the command line's defaults: the reach
// search's grids, the design's from-rest budgets and time limit, the drive budgets.
DesignDriveMode DriveMode(const DriveArgs& d, const FromRestArgs& r) {
  RequireDriveForceMax(d.force_max.value_or(kNaN), KeywordNamesOfSettings());
  const DesignFromRestPart part;
  DesignDriveMode mode;
  DriveDesignOptions& o = mode.options;
  o.drive = DesignDriveFamily(*d.drive, d.harmonics.value_or(kDesignDriveHarmonics),
                              d.pulse_levels.value_or(kDesignDrivePulseLevels), kDesignKeywords);
  o.force_max = *d.force_max;
  ReachEffort& e = o.effort;
  const StartGrid reach_starts =
      ParseStartGrid("reach_starts", r.reach_starts.value_or(StartGrid{e.n_x, e.n_psi}.Text()));
  e.n_x = reach_starts.n_x;
  e.n_psi = reach_starts.n_psi;
  e.global_evaluations = r.reach_evaluations.value_or(part.reach_evaluations);
  e.local_evaluations = r.reach_local_evaluations.value_or(part.reach_local_evaluations);
  e.max_seconds = r.reach_seconds.value_or(part.reach_seconds);
  e.drive_evaluations = d.drive_evaluations.value_or(e.drive_evaluations);
  e.drive_polishes = d.drive_polishes.value_or(e.drive_polishes);
  e.drive_local_evaluations = d.drive_local_evaluations.value_or(e.drive_local_evaluations);
  e.drive_refine_evaluations = d.drive_refine_evaluations.value_or(e.drive_refine_evaluations);
  e.drive_screens = d.drive_screens.value_or(e.drive_screens);
  o.check = FromRestCheck(r.from_rest_starts.value_or(StartGrid{}.Text()), r.threads.value_or(0));
  return mode;
}

// The run: one design (with part (b) when from_rest) or the fastest drive.
DesignJobResult RunDesign(DesignJobOptions& options, const FromRestArgs& r, const DriveArgs& d,
                          bool from_rest, const std::optional<std::vector<double>>& band_levels) {
  if (d.drive) {
    DesignDriveMode drive = DriveMode(d, r);
    return RunWithoutGil([&](SignalCheck& check) {
      drive.interrupt = check.AsInterrupt();
      options.mode = drive;
      return RunDesignJob(options);
    });
  }
  DesignFromRestPart part = FromRestPart(r);
  return RunWithoutGil([&](SignalCheck& check) {
    // Design tells its robots on this thread, and the robustness's continuations and the
    // from-rest search ask their interrupt there: where Ctrl-C is seen.
    DesignOneMode one;
    one.progress = [&check](std::int64_t, std::int64_t) { check.Check(); };
    one.interrupt = check.AsInterrupt();
    if (from_rest) {
      part.interrupt = check.AsInterrupt();
      one.from_rest = part;
    }
    if (band_levels) one.band_levels = *band_levels;
    options.mode = one;
    return RunDesignJob(options);
  });
}

// The library's field names in messages, as design()'s keywords.
const FlagNames kRenamedFields = {{"levels", "pulse_levels"}};

py::dict DesignDict(const std::optional<std::string>& config, const std::vector<py::object>& robot,
                    bool from_rest, const FromRestArgs& r,
                    const std::optional<std::vector<double>>& band_levels, const DriveArgs& d) {
  try {
    RejectUnusedArguments(GivenSettings(r, d, band_levels.has_value()), d, from_rest);
    DesignJobOptions options;
    options.input = RobotInput(config, robot, !d.drive);
    return py::dict(
        ToPython(json::DesignJobJson(RunDesign(options, r, d, from_rest, band_levels))));
  } catch (const std::invalid_argument& error) {
    throw std::invalid_argument(WithFlagNames(error.what(), kRenamedFields));
  } catch (const IoError& error) {  // the config file cannot be read
    PyErr_SetString(PyExc_OSError, error.what());
    throw py::error_already_set();
  }
}

// The docstring lines of the robot's settings, from the library's table.
std::string RobotArgsDoc() {
  std::string doc;
  const std::vector<DesignRobotSetting>& settings = DesignRobotSettings();
  for (std::size_t i = 0; i < settings.size(); ++i) {
    doc += ArgumentLines(RobotKeywords()[i], settings[i].help);
  }
  return doc;
}

constexpr const char* kDesignDoc =
    "Design a real robot in SI units: for the shell (m1, gap L, friction mu) and the motor "
    "force, the inner mass m2 (and the frequency, with frequency_range) of the fastest robust "
    "one-impact gait, with its speed, motor power, losses and cost of transport; or, with "
    "drive, the fastest drive from rest (capsubot documentation, design): the dict `capsubot "
    "design --json` prints.\n\n"
    "Arguments (keyword only). The robot: a TOML config file and the settings of `capsubot "
    "design` (keys of the file as written there, keywords with _ for -); the keywords "
    "override the file; None: not given (the file's value, else the default):\n"
    "    config  TOML file with the robot (m1 = 0.2, force-sin = [0.5], frequency-range = "
    "[10, 40])\n";

// The run's arguments, with their defaults (None) from the library.
// The default of a grid of starts: `one`'s, and the drive design's when it differs.
std::string GridDefaults(const StartGrid& one, const StartGrid& drive) {
  return one.Text() == drive.Text()
             ? "'" + one.Text() + "'"
             : fmt::format("'{}' ('{}' with drive)", one.Text(), drive.Text());
}

std::string RunArgsDoc() {
  const DesignFromRestPart d;
  const ReachEffort effort;
  return ArgumentLines("from_rest",
                       "also find the fastest motion reached from rest in each direction (key "
                       "from_rest_best; simulated, a few seconds); the next six arguments apply "
                       "with from_rest or drive only") +
         ArgumentLines("from_rest_starts",
                       "grid 'NXxNPSI' of starts on which the best robots are re-checked; None: " +
                           GridDefaults(d.from_rest_starts, StartGrid{})) +
         ArgumentLines("reach_starts",
                       "grid 'NXxNPSI' of starts inside the search; None: " +
                           GridDefaults(d.reach_starts, StartGrid{effort.n_x, effort.n_psi})) +
         ArgumentLines("reach_evaluations, reach_local_evaluations",
                       fmt::format("from-rest evaluations of the global search and of the local "
                                   "polish, per direction; None: {}, {}",
                                   d.reach_evaluations, d.reach_local_evaluations)) +
         ArgumentLines("reach_seconds",
                       fmt::format("wall-clock limit of the search stages [s], > 0; when it stops "
                                   "the search, the result depends on the machine's speed; None: "
                                   "{}",
                                   d.reach_seconds)) +
         ArgumentLines("threads", fmt::format("worker threads of the simulated starts (0: all "
                                              "cores; {}); the result does not depend on it; "
                                              "None: {}",
                                              ThreadsCapDoc(), d.threads)) +
         ArgumentLines("band_levels",
                       "the levels of the gait's speed bands, fractions of the speed from rest in "
                       "(0, 1): how far mu, e and m2 move, each way, before the mean speed from "
                       "rest falls below each (capsubot documentation, design); None: " +
                           fmt::format("[{}]", fmt::join(DesignOneMode{}.band_levels, ", "))) +
         ArgumentLines("drive",
                       "'sine', 'fourier' or 'pulse': instead of the one-impact design, the "
                       "fastest drive from rest of that waveform, the frequency over "
                       "frequency_range and the inner mass over m2_range, under the motor's peak "
                       "force_max (no force_* settings)") +
         ArgumentLines("force_max", "with drive: the motor's peak force max |F_N| [N], > 0") +
         ArgumentLines("harmonics", fmt::format("with drive='fourier': harmonics K, 1 <= K <= 16 "
                                                "(None: {})",
                                                kDesignDriveHarmonics)) +
         ArgumentLines("pulse_levels", fmt::format("with drive='pulse': constant levels N, 2 <= N "
                                                   "<= 16 (None: {})",
                                                   kDesignDrivePulseLevels)) +
         TableArgumentLines(ReachEffortSettings(), effort, {},
                            {"drive_evaluations", "drive_polishes", "drive_local_evaluations",
                             "drive_refine_evaluations", "drive_screens"},
                            DefaultInDoc::kNoneMeans) +
         "\n";
}

constexpr const char* kDesignDocTail =
    "Returns a dict: status ('ok', 'motor_slides_shell', 'no_gait'), message, one_impact "
    "{status, m2_kg, frequency_hz, speed_mm_s, displacement_mm, impact_velocity_m_s, "
    "energy_mj, power_mw, power_positive_mw, friction_loss_mj, impact_loss_mj, cot, "
    "efficiency, dimensionless {T0, A, c, alpha, phi0, I, spectral_radius, x_min, x_max, "
    "cos, sin (Fourier), energy}, orbits, binding}, robots, complete, robustness (with a "
    "gait: {mu, e, m2_kg: {value, from, to, status, message, down, up}}, each limit {type, "
    "the parameter's value, located, ...}; else None); with from_rest, "
    "from_rest_best {forward, backward: the same keys, forward_fraction, backward_fraction, "
    "attractors}; with drive, the keys of `capsubot design --drive --json`.\n\n"
    "Raises ValueError for bad input (the message names the parameter, its value and the "
    "rule), OSError for an unreadable config file. Runs without the GIL; Ctrl-C interrupts it "
    "(KeyboardInterrupt).";

// One robot argument of design()'s signature (a Python object: None, a number, a sequence or
// a str, read by the library as the text of the setting).
template <std::size_t>
using RobotArg = py::object;

template <std::size_t... I>
void DefineDesign(py::module_& m, const std::string& doc, std::index_sequence<I...>) {
  const std::vector<std::string>& keywords = RobotKeywords();
  m.def(
      "design",
      [](std::optional<std::string> config, RobotArg<I>... robot, bool from_rest,
         std::optional<std::string> from_rest_starts, std::optional<std::string> reach_starts,
         std::optional<int> reach_evaluations, std::optional<int> reach_local_evaluations,
         std::optional<double> reach_seconds, std::optional<int> threads,
         std::optional<std::vector<double>> band_levels, std::optional<std::string> drive,
         std::optional<double> force_max, std::optional<int> harmonics,
         std::optional<int> pulse_levels, std::optional<int> drive_evaluations,
         std::optional<int> drive_polishes, std::optional<int> drive_local_evaluations,
         std::optional<int> drive_refine_evaluations, std::optional<int> drive_screens) {
        return DesignDict(
            config, {robot...}, from_rest,
            {from_rest_starts, reach_starts, reach_evaluations, reach_local_evaluations,
             reach_seconds, threads},
            band_levels,
            {drive, force_max, harmonics, pulse_levels, drive_evaluations, drive_polishes,
             drive_local_evaluations, drive_refine_evaluations, drive_screens});
      },
      doc.c_str(), py::kw_only(), py::arg("config") = py::none(),
      py::arg(keywords[I].c_str()) = py::none()..., py::arg("from_rest").noconvert() = false,
      py::arg("from_rest_starts") = py::none(), py::arg("reach_starts") = py::none(),
      py::arg("reach_evaluations") = py::none(), py::arg("reach_local_evaluations") = py::none(),
      py::arg("reach_seconds") = py::none(), py::arg("threads") = py::none(),
      py::arg("band_levels") = py::none(), py::arg("drive") = py::none(),
      py::arg("force_max") = py::none(), py::arg("harmonics") = py::none(),
      py::arg("pulse_levels") = py::none(), py::arg("drive_evaluations") = py::none(),
      py::arg("drive_polishes") = py::none(), py::arg("drive_local_evaluations") = py::none(),
      py::arg("drive_refine_evaluations") = py::none(), py::arg("drive_screens") = py::none());
}

}  // namespace

void BindDesign(py::module_& m) {
  if (RobotKeywords().size() != kRobotSettingCount) {
    throw std::logic_error(
        fmt::format("design() declares {} settings of the robot, the table has {}",
                    kRobotSettingCount, RobotKeywords().size()));
  }
  const std::string doc = kDesignDoc + RobotArgsDoc() + RunArgsDoc() + kDesignDocTail;
  DefineDesign(m, doc, std::make_index_sequence<kRobotSettingCount>());
}

}  // namespace capsubot::python
