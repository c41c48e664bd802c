// continue_branch: pseudo-arclength continuation of a periodic motion in one model parameter,
// with its special points (docs/continuation.md), as `capsubot continue --json`.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <complex>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <variant>
#include <vector>

#include "bindings.hpp"
#include "capsubot/attract/start_state_spec.hpp"
#include "capsubot/job/continue_job.hpp"
#include "capsubot/numerics/not_computed.hpp"
#include "capsubot/report/continuation_json.hpp"

namespace capsubot::python {
namespace {

// The multipliers of every point as one complex array (points x largest dimension), padded
// with NaN where a point has fewer (as the CSV of `capsubot continue` pads its columns).
py::object MultiplierColumns(const nlohmann::json& points) {
  std::size_t columns = 0;
  for (const auto& p : points) columns = std::max(columns, p.at("multipliers").size());
  py::array_t<std::complex<double>> out(
      {static_cast<py::ssize_t>(points.size()), static_cast<py::ssize_t>(columns)});
  auto z = out.mutable_unchecked<2>();
  for (std::size_t i = 0; i < points.size(); ++i) {
    const nlohmann::json& mu = points[i].at("multipliers");
    for (std::size_t k = 0; k < columns; ++k) {
      const bool has = k < mu.size() && mu[k].at(0).is_number() && mu[k].at(1).is_number();
      z(i, k) = has ? std::complex<double>(mu[k][0].get<double>(), mu[k][1].get<double>())
                    : std::complex<double>(kNaN, kNaN);
    }
  }
  return std::move(out);
}

// One column of the points: numbers -> float (null -> NaN), counts -> int64, flags -> bool,
// names -> str.
py::object Column(const nlohmann::json& points, const std::string& key) {
  const py::module_ np = py::module_::import("numpy");
  py::list values;
  for (const auto& p : points) values.append(ToPython(p.at(key)));
  const nlohmann::json& first = points.front().at(key);
  const char* dtype = first.is_boolean()          ? "bool"
                      : first.is_string()         ? "str"
                      : first.is_number_integer() ? "int64"
                                                  : "float64";
  if (std::string(dtype) == "float64") {
    for (std::size_t i = 0; i < values.size(); ++i) {
      if (values[i].is_none()) values[i] = py::float_(kNaN);
    }
  }
  return np.attr("asarray")(values, py::arg("dtype") = dtype);
}

// Rows of a branch or curve (a JSON array of objects with the same keys) as columns: {key:
// array}.
py::dict Columns(const nlohmann::json& rows) {
  py::dict columns;
  if (!rows.empty()) {
    for (const auto& [key, value] : rows.front().items()) {
      columns[py::str(key)] = key == "multipliers" ? MultiplierColumns(rows) : Column(rows, key);
    }
  }
  return columns;
}

// The dict of `capsubot continue --json` with the points of the branch, of the switched branch
// and of the curve as columns.
py::dict JobDict(const nlohmann::json& j) {
  py::dict d = ToPython(j);
  d["points"] = Columns(j.at("points"));
  if (j.contains("switched") && !j.at("switched").is_null()) {
    py::dict switched = d["switched"];
    switched["points"] = Columns(j.at("switched").at("points"));
  }
  if (j.contains("curve")) d["curve"] = Columns(j.at("curve"));
  return d;
}

// The switch: False (none), True (the first period doubling, as --switch) or the name of the
// kind of point (as --switch-at).
std::optional<SwitchPoint> SwitchAt(const std::variant<bool, std::string>& at) {
  if (const bool* on = std::get_if<bool>(&at)) {
    return *on ? std::optional<SwitchPoint>(SwitchPoint::kPeriodDoubling) : std::nullopt;
  }
  return ParseSwitchPoint(std::get<std::string>(at));
}

// The curve's options: all of param2, from2, to2 and follow, or none.
std::optional<FollowOptions> Follow(const std::optional<std::string>& param2,
                                    std::optional<double> from2, std::optional<double> to2,
                                    const std::optional<std::string>& follow) {
  const int given = (param2 ? 1 : 0) + (from2 ? 1 : 0) + (to2 ? 1 : 0) + (follow ? 1 : 0);
  if (given == 0) return std::nullopt;
  if (given < 4) {
    throw std::invalid_argument(
        "the curve is incomplete: give all of param2, from2, to2, follow (or none)");
  }
  FollowOptions f;
  f.param2 = *param2;
  f.from2 = *from2;
  f.to2 = *to2;
  f.type = ParseFollowType(*follow);
  return f;
}

py::dict ContinueBranchDict(
    std::optional<double> A, std::optional<double> c, std::optional<double> phi0,
    std::optional<std::vector<double>> cos, std::optional<std::vector<double>> sin,
    std::optional<std::string> waveform, std::optional<std::vector<double>> levels,
    std::optional<std::vector<double>> switches, double T0, double e, double alpha,
    const std::string& param, double from, double to, std::optional<double> x0,
    std::optional<double> u0, std::optional<double> v0, std::optional<double> psi, bool from_orbit,
    const std::variant<bool, std::string>& switch_at, std::optional<std::string> param2,
    std::optional<double> from2, std::optional<double> to2, std::optional<std::string> follow,
    int max_points, double initial_step, double min_step, double max_step, int max_period,
    double step, double chatter_velocity) {
  ContinueJobOptions job;
  job.robot = {ForceSpec{A, c, phi0, cos, sin, waveform, levels, switches}.Build(), Params{T0, e},
               alpha};
  job.param = param;
  const std::optional<PhaseState> state =
      StartStateSpec{x0, u0, v0, psi}.Build(from_orbit, "from_orbit", "from_orbit=True");
  job.start = state ? ContinueStart(*state) : FromOneImpactOrbit{};
  job.switch_at = SwitchAt(switch_at);
  job.follow = Follow(param2, from2, to2, follow);
  ContinuationOptions& o = job.continuation;
  o.from = from;
  o.to = to;
  o.max_points = max_points;
  o.initial_step = initial_step;
  o.min_step = min_step;
  o.max_step = max_step;
  o.shooting.max_period = max_period;
  o.shooting.step = step;
  o.shooting.chatter_velocity = chatter_velocity;
  const ContinueJobResult result = RunWithoutGil([&](SignalCheck& check) {
    job.continuation.interrupt = check.AsInterrupt();
    return RunContinueJob(job);
  });
  return JobDict(json::ContinueJobJson(result));
}

constexpr const char* kContinueDoc =
    "Pseudo-arclength continuation of a periodic motion in one model parameter (capsubot "
    "documentation, continuation): the motion near the start is found by Newton shooting at the "
    "robot's value of the parameter and followed both ways through [from_, to], with its folds, "
    "period doublings, Neimark-Sacker points, grazings, segment changes and speed extrema; on "
    "request the branch switched to at its first period doubling or grazing (switch) and the curve "
    "of its first special point of a type in two parameters (param2, from2, to2, follow): the dict "
    "`capsubot continue --json` prints, with the points as columns.\n\n"
    "Arguments (keyword only, named as the options of `capsubot continue`; `from_` is --from):\n"
    "    phi0    phase of the force F = A sin(psi + phi0) + c at the start's phase psi [rad]\n";

constexpr const char* kContinueArgsDoc =
    "    param   the parameter followed: A, c, alpha, T0, e, phi0, a1..a16, b1..b16\n"
    "    from_, to  the range; the robot's own value of param must lie in it\n"
    "    x0, u0, v0, psi  the start state (all four), or\n"
    "    from_orbit  start on the robot's valid one-impact orbit with the smallest spectral\n"
    "            radius, right after its impact\n"
    "    switch  also follow a switched branch: True or 'period_doubling' (the period-2p\n"
    "            branch born at the first located period doubling), 'grazing' (the motion\n"
    "            with other impacts per period just beyond the first grazing); False: none\n"
    "    param2, from2, to2, follow  also follow the first located special point of type\n"
    "            follow ('fold', 'period_doubling', 'grazing', 'speed_extremum') in (param,\n"
    "            param2), param2 over [from2, to2] (all four, or none)\n"
    "    max_points  points of the branch (and of the curve), both directions together, >= 2\n"
    "    initial_step, min_step, max_step  arclength steps\n";

constexpr const char* kContinueReturnsDoc =
    "\nReturns a dict: parameter, status ('ok', 'no_motion', 'event_limit', 'not_run'), message, "
    "start_index, ends {lower, upper: {end, <param>}}, points {<param>, arclength, x, u, v, "
    "psi, mode, period, impacts_right, impacts_left, mean_velocity, spectral_radius, stable, "
    "label: 1-D NumPy arrays; multipliers: a complex array, points x largest dimension, NaN "
    "padded}, special_points [{type, <param>, located, accuracy, wall ('right', 'left' at a "
    "grazing, else 'none'), mean_velocity, period, "
    "impacts_right, impacts_left, state, multipliers, stable}]; with switch: switched (the "
    "same dict for the switched branch, None without a located period doubling or a grazing; "
    "status 'no_motion' with a message when the motion ends at the grazing); with "
    "param2: follow {type, parameter2, status, message, start, start_index, ends {backward, "
    "forward}} and curve {<param>, <param2>, arclength, condition, x, u, v, psi, mode, period, "
    "impacts_right, impacts_left, mean_velocity, spectral_radius, stable: 1-D NumPy arrays; "
    "multipliers: complex}.\n\n"
    "Raises ValueError for bad input (the message names the parameter, its value and the "
    "rule). Runs without the GIL; Ctrl-C stops it (KeyboardInterrupt).\n\n";

}  // namespace

void BindContinuation(py::module_& m) {
  const std::string doc = std::string(kContinueDoc) + ForceArgsDoc() + ModelArgsDoc() +
                          MassRatioArgDoc() + kContinueArgsDoc + ShootingArgsDoc() +
                          kContinueReturnsDoc + kUnits;
  const ContinuationOptions o;
  DefRobotFunction(
      m, "continue_branch", &ContinueBranchDict, doc.c_str(), py::arg("alpha"), py::arg("param"),
      py::arg("from_"), py::arg("to"), py::arg("x0") = py::none(), py::arg("u0") = py::none(),
      py::arg("v0") = py::none(), py::arg("psi") = py::none(), py::arg("from_orbit") = false,
      py::arg("switch").noconvert() = false, py::arg("param2") = py::none(),
      py::arg("from2") = py::none(), py::arg("to2") = py::none(), py::arg("follow") = py::none(),
      py::arg("max_points") = o.max_points, py::arg("initial_step") = o.initial_step,
      py::arg("min_step") = o.min_step, py::arg("max_step") = o.max_step,
      py::arg("max_period") = o.shooting.max_period, py::arg("step") = o.shooting.step,
      py::arg("chatter_velocity") = o.shooting.chatter_velocity);
}

}  // namespace capsubot::python
