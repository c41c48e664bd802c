// continue_branch: pseudo-arclength continuation of a periodic motion in one model parameter,
// with its special points (docs/continuation.md), as `capsubot continue --json`.

#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <algorithm>
#include <complex>
#include <cstdint>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <vector>

#include "bindings.hpp"
#include "capsubot/continue/parameter_branch.hpp"
#include "capsubot/report/continuation_json.hpp"

namespace capsubot::python {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

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

// The dict of `capsubot continue --json` with "points" as columns: {key: array}.
py::dict BranchDict(const nlohmann::json& j) {
  py::dict d = ToPython(j);
  const nlohmann::json& points = j.at("points");
  py::dict columns;
  if (!points.empty()) {
    for (const auto& [key, value] : points.front().items()) {
      columns[py::str(key)] =
          key == "multipliers" ? MultiplierColumns(points) : Column(points, key);
    }
  }
  d["points"] = columns;
  return d;
}

// The start: a state (x0, u0, v0 at phase psi) or the robot's one-impact orbit.
PhaseState Start(std::optional<double> x0, std::optional<double> u0, std::optional<double> v0,
                 std::optional<double> psi, bool from_orbit, const Forcing& forcing,
                 const Params& params, double alpha) {
  const int given = (x0 ? 1 : 0) + (u0 ? 1 : 0) + (v0 ? 1 : 0) + (psi ? 1 : 0);
  if (from_orbit && given > 0) {
    throw std::invalid_argument(
        "from_orbit gives the start: do not give x0, u0, v0 or psi with it");
  }
  if (!from_orbit && given < 4) {
    throw std::invalid_argument(
        "the start is missing: give all of x0, u0, v0, psi (or from_orbit=True)");
  }
  if (from_orbit) return OneImpactOrbitStart(forcing, params, alpha);
  PhaseState s;
  s.x = *x0;
  s.u = *u0;
  s.v = *v0;
  s.psi = *psi;
  return s;
}

py::dict ContinueBranchDict(std::optional<double> A, double c, std::optional<double> phi0,
                            std::optional<std::vector<double>> cos,
                            std::optional<std::vector<double>> sin, double T0, double e,
                            double alpha, const std::string& param, double from, double to,
                            std::optional<double> x0, std::optional<double> u0,
                            std::optional<double> v0, std::optional<double> psi, bool from_orbit,
                            int max_points, double initial_step, double min_step, double max_step,
                            int max_period, double step, double chatter_velocity) {
  const Params params{T0, e, 0.0};
  const Forcing forcing = ForcingArgs{A, c, phi0, cos, sin}.Build();
  params.Validate();
  const PhaseState start = Start(x0, u0, v0, psi, from_orbit, forcing, params, alpha);
  RequirePhase("psi", start.psi);
  ContinuationOptions o;
  o.from = from;
  o.to = to;
  o.max_points = max_points;
  o.initial_step = initial_step;
  o.min_step = min_step;
  o.max_step = max_step;
  o.shooting.max_period = max_period;
  o.shooting.step = step;
  o.shooting.chatter_velocity = chatter_velocity;
  const Branch branch = RunWithoutGil([&](SignalCheck& check) {
    o.interrupt = check.AsInterrupt();
    return ContinueParameter(forcing, params, alpha, param, start, o);
  });
  return BranchDict(json::BranchJson(branch, param));
}

constexpr const char* kContinueDoc =
    "Pseudo-arclength continuation of a periodic motion in one model parameter "
    "(capsubot documentation, continuation): the motion near the start is found by Newton shooting "
    "at the "
    "robot's value of the parameter and followed both ways through [from_, to], with its "
    "folds, period doublings, Neimark-Sacker points, grazings, segment changes and speed "
    "extrema: the dict `capsubot continue --json` prints, with the points as columns.\n\n"
    "Arguments (keyword only, named as the options of `capsubot continue`; `from_` is "
    "--from):\n"
    "    phi0    phase of the force F = A sin(psi + phi0) + c at the start's phase psi [rad]\n";

constexpr const char* kContinueArgsDoc =
    "    alpha   mass ratio m2/(m1+m2) of the robot, 0 < alpha < 1\n"
    "    param   the parameter followed: A, c, alpha, T0, e, phi0, a1..a16, b1..b16\n"
    "    from_, to  the range; the robot's own value of param must lie in it\n"
    "    x0, u0, v0, psi  the start state (all four), or\n"
    "    from_orbit  start on the robot's valid one-impact orbit with the smallest spectral\n"
    "            radius, right after its impact\n"
    "    max_points  points of the branch, both directions together, >= 2\n"
    "    initial_step, min_step, max_step  arclength steps\n"
    "    max_period  largest period searched at the start, 1 to 64\n"
    "    step    step of the central finite differences of the Jacobians\n"
    "    chatter_velocity  the simulator's chatter cut-off [omega L]\n\n"
    "Returns a dict: parameter, status ('ok', 'no_motion', 'event_limit', 'not_run'), message, "
    "start_index, ends {lower, upper: {end, <param>}}, points {<param>, arclength, x, u, v, "
    "psi, mode, period, impacts_right, impacts_left, mean_velocity, spectral_radius, stable, "
    "label: 1-D NumPy arrays; multipliers: a complex array, points x largest dimension, NaN "
    "padded}, special_points [{type, <param>, located, accuracy, mean_velocity, period, "
    "impacts_right, impacts_left, state, multipliers, stable}].\n\n"
    "Raises ValueError for bad input (the message names the parameter, its value and the "
    "rule). Runs without the GIL; Ctrl-C stops it (KeyboardInterrupt).\n\n";

}  // namespace

void BindContinuation(py::module_& m) {
  const std::string doc =
      std::string(kContinueDoc) + kForcingArgsDoc + kModelArgsDoc + kContinueArgsDoc + kUnits;
  const ContinuationOptions o;
  m.def("continue_branch", &ContinueBranchDict, doc.c_str(), py::kw_only(),
        py::arg("A") = py::none(), py::arg("c"), py::arg("phi0") = py::none(),
        py::arg("cos") = py::none(), py::arg("sin") = py::none(), py::arg("T0") = Params{}.T0,
        py::arg("e") = Params{}.e, py::arg("alpha"), py::arg("param"), py::arg("from_"),
        py::arg("to"), py::arg("x0") = py::none(), py::arg("u0") = py::none(),
        py::arg("v0") = py::none(), py::arg("psi") = py::none(), py::arg("from_orbit") = false,
        py::arg("max_points") = o.max_points, py::arg("initial_step") = o.initial_step,
        py::arg("min_step") = o.min_step, py::arg("max_step") = o.max_step,
        py::arg("max_period") = o.shooting.max_period, py::arg("step") = o.shooting.step,
        py::arg("chatter_velocity") = o.shooting.chatter_velocity);
}

}  // namespace capsubot::python
