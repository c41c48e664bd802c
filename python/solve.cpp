// solve and trajectory: the one-impact orbit (docs/model.md section 4) with its validity
// (section 5) and stability (section 8), as `capsubot solve --json` and `--trajectory`.

#include <fmt/format.h>
#include <pybind11/numpy.h>
#include <pybind11/stl.h>

#include <stdexcept>
#include <string>

#include "bindings.hpp"
#include "capsubot/attract/start_grid.hpp"
#include "capsubot/job/solve_job.hpp"
#include "capsubot/model/limits.hpp"
#include "capsubot/report/solution_json.hpp"

namespace capsubot::python {
namespace {

constexpr const char* kSolveDoc =
    "The one-impact periodic orbit (capsubot documentation, model section 4) for the force "
    "F(phi) = A sin(phi + phi0) + c (or a Fourier force), with every validity condition of "
    "section 5: the object `capsubot solve --json` prints.\n\n"
    "Arguments (keyword only, named as the options of `capsubot solve`):\n";

constexpr const char* kPhaseDoc =
    "    phi0    motor phase at the impact [rad]: F(phi) = A sin(phi + phi0) + c with phi = 0\n"
    "            at the impact; required with A, default 0 with sin/cos\n";

constexpr const char* kStabilityArgDoc =
    "    stability  also the stability of the orbit and its check from rest (capsubot\n"
    "            documentation, model sections 8 and 12)\n";

constexpr const char* kSolveReturnsDoc =
    "Returns a dict: A, c, phi0 (and cos, sin for a Fourier force, A is then None), T0, e, "
    "status ('ok', 'non_positive_mean_force', 'no_mass_ratio'), phi1 (stop phase, rad), alpha "
    "(mass ratio m2/(m1+m2) that closes the orbit), u (impact velocity, omega L), v_plus "
    "(capsule velocity after the impact, omega L), I (step per period, L), v_mean (mean "
    "velocity I/tau, omega L), x_min, x_max (extrema of the inner body's position, L), stroke "
    "(x_max - x_min, L), clearance (the clearance required from both walls, L), valid (bool), "
    "violations (names of the violated conditions), energy (a dict motor_work, "
    "motor_work_positive, friction_loss, impact_loss: per period, in (m1+m2) omega^2 L^2, "
    "capsubot documentation, model section 11); None where a quantity does not exist. With "
    "stability: multipliers (list of {'re', 'im'}: eigenvalues of the impact map's Jacobian), "
    "spectral_radius and stable (spectral_radius < 1), and from_rest: the "
    "orbit checked from rest on from_rest_starts (the dict of attractors() plus reached, the "
    "starts that end on the orbit, and summary; None without an orbit).\n\n"
    "Raises ValueError for bad input (the message names the parameter, its value and the "
    "rule). The check from rest runs without the GIL; Ctrl-C interrupts it "
    "(KeyboardInterrupt).\n\n";

constexpr const char* kTrajectoryDoc =
    "The state along one period of the one-impact orbit, as `capsubot solve --trajectory`: "
    "samples equally spaced phases from phi = 0 (just after the impact) to phi = tau (just "
    "before the next one).\n\n"
    "Arguments (keyword only, named as the options of `capsubot solve`):\n";

constexpr const char* kTrajectoryReturnsDoc =
    "    samples number of phases, 2 <= samples <= 10000000 (as --samples)\n\n"
    "Returns a dict of NumPy arrays of length samples: phi (rad), x (relative position of "
    "the inner body, L), u (relative velocity dx/dphi, omega L), v (capsule velocity, omega "
    "L).\n\n"
    "Raises ValueError for bad input, or when no one-impact orbit exists for this force, T0 "
    "and e (then the message names the orbit's status). Runs without the GIL; Ctrl-C "
    "interrupts it.\n\n";

py::dict Solve(std::optional<double> A, double c, std::optional<double> phi0,
               std::optional<std::vector<double>> cos, std::optional<std::vector<double>> sin,
               double T0, double e, double margin, double margin_stroke, double stick_margin,
               bool stability, const std::string& from_rest_starts, int threads) {
  SolveJobOptions o;
  o.params = Params{T0, e};
  o.margins = Margins{margin, margin_stroke, stick_margin};
  const FromRestOptions check = FromRestCheck(from_rest_starts, threads);
  o.forcing = ForceSpec{A, c, phi0, cos, sin}.Build();
  if (stability) o.stability = check;
  const SolveJobResult r = RunWithoutGil([&](SignalCheck& signals) {
    if (o.stability) o.stability->attractor.interrupt = signals.AsInterrupt();
    return RunSolveJob(o);
  });
  return py::dict(ToPython(json::SolveJobJson(r)));
}

py::dict Trajectory(std::optional<double> A, double c, std::optional<double> phi0,
                    std::optional<std::vector<double>> cos, std::optional<std::vector<double>> sin,
                    double T0, double e, long samples) {
  const Params params{T0, e};
  params.Validate();
  const Forcing forcing = ForceSpec{A, c, phi0, cos, sin}.Build();
  if (samples < 2 || samples > kMaxTrajectoryRows) {
    throw std::invalid_argument(fmt::format("samples = {} is invalid: expected 2 <= samples <= {}",
                                            samples, kMaxTrajectoryRows));
  }
  const Orbit o = ComputeOrbit(forcing, params);
  if (!o.ok()) {
    throw std::invalid_argument(
        fmt::format("no one-impact orbit exists for this force, T0 and e ({}): no trajectory",
                    StatusName(o.status)));
  }
  py::array_t<double> phi(samples), x(samples), u(samples), v(samples);
  double* phi_out = phi.mutable_data();
  double* x_out = x.mutable_data();
  double* u_out = u.mutable_data();
  double* v_out = v.mutable_data();
  RunWithoutGil([&](SignalCheck& check) {
    for (long i = 0; i < samples; ++i) {
      // phi = 0 is just after the impact, phi = tau just before the next one.
      phi_out[i] = kTau * static_cast<double>(i) / static_cast<double>(samples - 1);
      x_out[i] = o.x(phi_out[i]);
      u_out[i] = o.dx(phi_out[i]);
      v_out[i] = o.v(phi_out[i]);
      check();
    }
  });
  py::dict d;
  d["phi"] = phi;
  d["x"] = x;
  d["u"] = u;
  d["v"] = v;
  return d;
}

}  // namespace

void BindSolve(py::module_& m) {
  const std::string solve_doc = std::string(kSolveDoc) + ForceArgsDoc(false) + kPhaseDoc +
                                ModelArgsDoc() + MarginArgsDoc() + kStabilityArgDoc +
                                FromRestArgsDoc() + "\n" + kSolveReturnsDoc + kUnits;
  m.def("solve", &Solve, solve_doc.c_str(), py::kw_only(), py::arg("A") = py::none(), py::arg("c"),
        py::arg("phi0") = py::none(), py::arg("cos") = py::none(), py::arg("sin") = py::none(),
        py::arg("T0") = Params{}.T0, py::arg("e") = Params{}.e,
        py::arg("margin") = Margins{}.clearance,
        py::arg("margin_stroke") = Margins{}.clearance_stroke,
        py::arg("stick_margin") = Margins{}.stick, py::arg("stability").noconvert() = false,
        py::arg("from_rest_starts") = StartGrid{}.Text(),
        py::arg("threads") = AttractorOptions{}.threads);
  const std::string trajectory_doc = std::string(kTrajectoryDoc) + ForceArgsDoc(false) + kPhaseDoc +
                                     ModelArgsDoc() + kTrajectoryReturnsDoc + kUnits;
  m.def("trajectory", &Trajectory, trajectory_doc.c_str(), py::kw_only(), py::arg("A") = py::none(),
        py::arg("c"), py::arg("phi0") = py::none(), py::arg("cos") = py::none(),
        py::arg("sin") = py::none(), py::arg("T0") = Params{}.T0, py::arg("e") = Params{}.e,
        py::arg("samples") = 1001);
}

}  // namespace capsubot::python
