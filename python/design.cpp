// design: a real robot in SI units; the inner mass (and motor frequency) of its fastest robust
// one-impact gait, with speed, power and cost of transport, as `capsubot design --json`.

#include <fmt/format.h>
#include <pybind11/stl.h>

#include <cstdint>
#include <optional>
#include <set>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "capsubot/job/design_job.hpp"
#include "capsubot/job/design_settings.hpp"
#include "capsubot/model/limits.hpp"
#include "capsubot/report/design_json.hpp"
#include "design_keywords.hpp"

namespace capsubot::python {
namespace {

using Range = std::pair<double, double>;

// As the command line's ranges MIN:MAX: a range has MIN < MAX (one frequency is `frequency`).
void RequireRange(const char* name, const std::optional<Range>& range) {
  if (range && !(range->first < range->second)) {
    throw std::invalid_argument(
        fmt::format("{} = ({}, {}) is invalid: expected (MIN, MAX) with MIN < MAX", name,
                    range->first, range->second));
  }
}

// One of two alternatives must be given, not both (names as the arguments).
void RequireOne(bool a, bool b, const char* name_a, const char* name_b) {
  if (a && b) {
    throw std::invalid_argument(std::string(name_a) + " and " + name_b +
                                " are exclusive: give one of them");
  }
  if (!a && !b) {
    throw std::invalid_argument(std::string(name_a) + " is missing: give " + name_a + " (or " +
                                name_b + ")");
  }
}

// The from-rest part's arguments; None: not given (the part's default).
struct FromRestArgs {
  std::optional<std::string> from_rest_starts, reach_starts;
  std::optional<int> reach_evaluations, reach_local_evaluations;
  std::optional<double> reach_seconds;
  std::optional<int> threads;
};

// Part (b) as the arguments give it; a setting of it given without from_rest is refused, as
// the command line refuses it (DesignSettingUses).
DesignFromRestPart FromRestPart(const FromRestArgs& a, bool from_rest) {
  DesignFromRestPart part;
  std::set<std::string> given;
  std::string from_rest_starts = part.from_rest_starts.Text();
  std::string reach_starts = part.reach_starts.Text();
  TakeGiven(given, "from_rest_starts", a.from_rest_starts, from_rest_starts);
  TakeGiven(given, "reach_starts", a.reach_starts, reach_starts);
  TakeGiven(given, "reach_evaluations", a.reach_evaluations, part.reach_evaluations);
  TakeGiven(given, "reach_local_evaluations", a.reach_local_evaluations,
            part.reach_local_evaluations);
  TakeGiven(given, "reach_seconds", a.reach_seconds, part.reach_seconds);
  TakeGiven(given, "threads", a.threads, part.threads);
  RejectUnusedSettings(DesignSettingUses(), given, from_rest ? "from-rest" : "", DesignRunKeywords,
                       kDesignKeywords, "is invalid with");
  part.from_rest_starts = ParseStartGrid("from_rest_starts", from_rest_starts);
  part.reach_starts = ParseStartGrid("reach_starts", reach_starts);
  part.threads = CapThreads(part.threads);
  return part;
}

py::dict DesignDict(double m1, double L, double mu, double g, double e,
                    std::optional<double> force_amplitude, double force_bias,
                    std::optional<std::vector<double>> force_cos,
                    std::optional<std::vector<double>> force_sin, std::optional<double> frequency,
                    std::optional<Range> frequency_range, std::optional<Range> m2_range,
                    double margin, double margin_stroke, double stick_margin, double rho_max,
                    int scan_points, bool from_rest, std::optional<std::string> from_rest_starts,
                    std::optional<std::string> reach_starts, std::optional<int> reach_evaluations,
                    std::optional<int> reach_local_evaluations, std::optional<double> reach_seconds,
                    std::optional<int> threads, std::optional<std::vector<double>> band_levels) {
  RequireOne(force_amplitude.has_value(), force_sin.has_value(), "force_amplitude", "force_sin");
  if (force_cos && force_amplitude) {
    throw std::invalid_argument(
        "force_amplitude and force_cos are exclusive: give one of them (force_cos goes with "
        "force_sin)");
  }
  RequireOne(frequency.has_value(), frequency_range.has_value(), "frequency", "frequency_range");
  RequireSeriesTerms("force_sin", "b", force_sin);
  RequireSeriesTerms("force_cos", "a", force_cos);
  RequireRange("frequency_range", frequency_range);
  RequireRange("m2_range", m2_range);
  DesignJobOptions options;
  DesignInput& in = options.input;
  in.m1 = m1;
  in.L = L;
  in.mu = mu;
  in.g = g;
  in.e = e;
  in.force.amplitude = force_amplitude.value_or(DesignInput::kNaN);
  in.force.bias = force_bias;
  in.force.cos = force_cos.value_or(std::vector<double>());
  in.force.sin = force_sin.value_or(std::vector<double>());
  const Range f = frequency_range.value_or(Range(frequency.value_or(0.0), frequency.value_or(0.0)));
  in.frequency_min = f.first;
  in.frequency_max = f.second;
  if (m2_range) {
    in.m2_min = m2_range->first;
    in.m2_max = m2_range->second;
  }
  in.margin = margin;
  in.margin_stroke = margin_stroke;
  in.stick_margin = stick_margin;
  in.rho_max = rho_max;
  in.scan_points = scan_points;
  DesignFromRestPart part = FromRestPart({from_rest_starts, reach_starts, reach_evaluations,
                                          reach_local_evaluations, reach_seconds, threads},
                                         from_rest);
  const DesignJobResult r = RunWithoutGil([&](SignalCheck& check) {
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
  return py::dict(ToPython(json::DesignJobJson(r)));
}

constexpr const char* kDesignDoc =
    "Design a real robot in SI units: for the shell (m1, gap L, friction mu) and the motor "
    "force, the inner mass m2 (and the frequency, with frequency_range) of the fastest robust "
    "one-impact gait, with its speed, motor power, losses and cost of transport "
    "(capsubot documentation, design): the dict `capsubot design --json` prints.\n\n"
    "Arguments (keyword only, named as the settings of `capsubot design` with _ for -):\n"
    "    m1      shell mass [kg], > 0\n"
    "    L       free gap of the inner body between the walls [m], > 0\n"
    "    mu      friction coefficient of the shell on the floor, > 0\n"
    "    g       gravity [m/s^2], > 0\n"
    "    e       coefficient of restitution of the impacts, 0 <= e <= 1\n"
    "    force_amplitude  amplitude A_N [N] of F_N = A_N sin(omega t + phase) + c_N, >= 0\n"
    "    force_bias  mean c_N [N] of the motor force, >= 0\n"
    "    force_cos, force_sin  Fourier motor force instead of the amplitude: coefficients\n"
    "            a_1..a_K, b_1..b_K [N] of F_N = c_N + sum_k (a_k cos k s + b_k sin k s)\n"
    "    frequency  motor frequency f [Hz], > 0; or\n"
    "    frequency_range  (fmin, fmax) [Hz]: search the frequency too\n"
    "    m2_range  (m2min, m2max) [kg] searched, default (0.01 m1, 10 m1)\n"
    "    margin, margin_stroke, stick_margin  the robust gait's clearances and stick margin\n"
    "            (capsubot documentation, model section 12)\n"
    "    rho_max  largest admissible multiplier modulus, > 0 (inf: no stability requirement)\n"
    "    scan_points  log-spaced samples of each searched variable, >= 3\n"
    "    from_rest  also find the fastest motion reached from rest in each direction\n"
    "            (key from_rest_best; simulated, a few seconds)\n"
    "    from_rest_starts, reach_starts, reach_evaluations, reach_local_evaluations,\n";

// The from-rest arguments' defaults (None), from the library's DesignFromRestPart.
std::string FromRestArgsDoc() {
  const DesignFromRestPart d;
  return fmt::format(
      "    reach_seconds, threads  with from_rest only (None: '{}', '{}', {}, {}, {}, {});\n"
      "            given without from_rest they are refused, as the command line refuses them):\n",
      d.from_rest_starts.Text(), d.reach_starts.Text(), d.reach_evaluations,
      d.reach_local_evaluations, d.reach_seconds, d.threads);
}

constexpr const char* kDesignDocTail =

    "    from_rest_starts  grid 'NXxNPSI' of starts on which the best robots are re-checked\n"
    "    reach_starts  grid 'NXxNPSI' of starts inside the search\n"
    "    reach_evaluations, reach_local_evaluations  from-rest evaluations of the global\n"
    "            search and of the local polish, per direction\n"
    "    reach_seconds  wall-clock limit of the search stages [s], > 0\n"
    "    threads worker threads of the simulated starts (0: all cores; more than 4 per core\n"
    "            are lowered to that); the result does not depend on it\n"
    "    band_levels  the levels of the gait's speed bands, fractions of the speed from rest in\n"
    "            (0, 1): how far mu, e and m2 move, each way, before the mean speed from rest\n"
    "            falls below each (capsubot documentation, design); None: [0.95]\n\n"
    "Returns a dict: status ('ok', 'motor_slides_shell', 'no_gait'), message, one_impact "
    "{status, m2_kg, frequency_hz, speed_mm_s, displacement_mm, impact_velocity_m_s, "
    "energy_mj, power_mw, power_positive_mw, friction_loss_mj, impact_loss_mj, cot, "
    "efficiency, dimensionless {T0, A, c, alpha, phi0, I, spectral_radius, x_min, x_max, "
    "cos, sin (Fourier), energy}, orbits, binding}, robots, complete, robustness (with a "
    "gait: {mu, e, m2_kg: {value, from, to, status, message, down, up}}, each limit {type, "
    "the parameter's value, located, ...}; else None); with from_rest, "
    "from_rest_best {forward, backward: the same keys, forward_fraction, backward_fraction, "
    "attractors}.\n\n"
    "Raises ValueError for bad input (the message names the parameter, its value and the "
    "rule). Runs without the GIL; Ctrl-C interrupts it (KeyboardInterrupt).";

}  // namespace

void BindDesign(py::module_& m) {
  const DesignInput in;
  const DesignFromRestPart rest;
  const std::string doc = kDesignDoc + FromRestArgsDoc() + kDesignDocTail;
  m.def("design", &DesignDict, doc.c_str(), py::kw_only(), py::arg("m1"), py::arg("L"),
        py::arg("mu"), py::arg("g") = in.g, py::arg("e"), py::arg("force_amplitude") = py::none(),
        py::arg("force_bias"), py::arg("force_cos") = py::none(), py::arg("force_sin") = py::none(),
        py::arg("frequency") = py::none(), py::arg("frequency_range") = py::none(),
        py::arg("m2_range") = py::none(), py::arg("margin") = in.margin,
        py::arg("margin_stroke") = in.margin_stroke, py::arg("stick_margin") = in.stick_margin,
        py::arg("rho_max") = in.rho_max, py::arg("scan_points") = in.scan_points,
        py::arg("from_rest").noconvert() = false, py::arg("from_rest_starts") = py::none(),
        py::arg("reach_starts") = py::none(), py::arg("reach_evaluations") = py::none(),
        py::arg("reach_local_evaluations") = py::none(), py::arg("reach_seconds") = py::none(),
        py::arg("threads") = py::none(), py::arg("band_levels") = py::none());
}

}  // namespace capsubot::python
