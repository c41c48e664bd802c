// periodic: a periodic motion of any kind by Newton shooting on the p-th iterate of the
// stroboscopic map, with its multipliers (docs/model.md section 13), as
// `capsubot periodic --json`.

#include <pybind11/stl.h>

#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "bindings.hpp"
#include "capsubot/job/periodic_job.hpp"
#include "capsubot/job/periodic_start_spec.hpp"
#include "capsubot/report/periodic_json.hpp"

namespace capsubot::python {
namespace {

py::dict Periodic(std::optional<double> A, std::optional<double> c, std::optional<double> phi0,
                  std::optional<std::vector<double>> cos, std::optional<std::vector<double>> sin,
                  std::optional<std::string> waveform, std::optional<std::vector<double>> levels,
                  std::optional<std::vector<double>> switches, double T0, double e, double alpha,
                  std::optional<double> x0, std::optional<double> u0, std::optional<double> v0,
                  std::optional<double> psi, std::optional<std::pair<double, double>> from_rest,
                  std::optional<int> transient, std::optional<int> period, int max_period,
                  double step, double chatter_velocity) {
  PeriodicJobOptions o;
  o.robot = {ForceSpec{A, c, phi0, cos, sin, waveform, levels, switches}.Build(), Params{T0, e},
             alpha};
  std::optional<PhaseState> rest;
  if (from_rest) rest = RestStart(from_rest->first, from_rest->second);
  o.start =
      PeriodicStartSpec{{x0, u0, v0, psi}, rest, transient, period}.Build("from_rest=(x0, psi)");
  o.shooting.max_period = max_period;
  o.shooting.step = step;
  o.shooting.chatter_velocity = chatter_velocity;
  const PeriodicJobResult r = RunWithoutGil([&](SignalCheck& signals) {
    o.shooting.interrupt = signals.AsInterrupt();
    return RunPeriodicJob(o);
  });
  return py::dict(ToPython(json::PeriodicJobJson(r)));
}

constexpr const char* kPeriodicDoc =
    "A periodic motion of any kind (several impacts, both walls, period p) found exactly by "
    "Newton's method on the p-th iterate of the stroboscopic map (capsubot documentation, model "
    "section 13), with its multipliers: the dict `capsubot periodic --json` prints.\n\n"
    "Arguments (keyword only, named as the options of `capsubot periodic`):\n"
    "    phi0    phase of the force F = A sin(psi + phi0) + c at the start's phase psi [rad]\n"
    "            (required for the harmonic force; default 0 for a Fourier force)\n";

constexpr const char* kPeriodicStartDoc =
    "    x0, u0, v0, psi  the start: position of the inner body, relative velocity, capsule\n"
    "            velocity at forcing phase psi (no transient unless transient is given)\n"
    "    from_rest  (x0, psi): start from rest there instead, after transient periods\n"
    "    transient  periods simulated before shooting (default 200 with from_rest, else 0)\n"
    "    period  the period p, 1 to 64, when known: Newton from the start itself (no search of\n"
    "            the period, no transient)\n";

constexpr const char* kPeriodicReturnsDoc =
    "\nReturns a dict: status ('converged', 'no_convergence', 'event_limit'), period, "
    "impacts_right, impacts_left, mean_velocity, state {x, u, v, psi}, mode, dimension, "
    "multipliers [[re, im], ...], spectral_radius, stable, distance_to_plus_one, "
    "distance_to_minus_one, distance_to_unit_circle, residual, iterations.\n\n"
    "Raises ValueError for bad input (the message names the parameter, its value and the "
    "rule). Runs without the GIL; Ctrl-C interrupts it (KeyboardInterrupt).\n\n";

}  // namespace

void BindPeriodic(py::module_& m) {
  const std::string doc = std::string(kPeriodicDoc) + ForceArgsDoc() + ModelArgsDoc() +
                          MassRatioArgDoc() + kPeriodicStartDoc + ShootingArgsDoc() +
                          kPeriodicReturnsDoc + kUnits;
  const ShootingOptions so;
  DefRobotFunction(m, "periodic", &Periodic, doc.c_str(), py::arg("alpha"),
                   py::arg("x0") = py::none(), py::arg("u0") = py::none(),
                   py::arg("v0") = py::none(), py::arg("psi") = py::none(),
                   py::arg("from_rest") = py::none(), py::arg("transient") = py::none(),
                   py::arg("period") = py::none(), py::arg("max_period") = so.max_period,
                   py::arg("step") = so.step, py::arg("chatter_velocity") = so.chatter_velocity);
}

}  // namespace capsubot::python
