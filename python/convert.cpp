// Conversions shared by the module's functions: the force arguments, numbers, and the
// solved orbit as the dict of `capsubot solve --json`.

#include <pybind11/stl.h>

#include <cmath>
#include <stdexcept>
#include <string>

#include "bindings.hpp"

namespace capsubot::python {
Forcing ForcingArgs::Build(bool need_phase) const {
  if (sin) {
    if (A) {
      throw std::invalid_argument(
          "A and sin are exclusive: give the amplitude A of A sin(phi + phi0) + c, or the "
          "Fourier coefficients sin (and cos)");
    }
    const std::vector<double> a = cos ? *cos : std::vector<double>(sin->size(), 0.0);
    return Forcing::Fourier(c, a, *sin, phi0.value_or(0.0));
  }
  if (cos) {
    throw std::invalid_argument(
        "cos needs sin: give the sine coefficients b_1..b_K of the Fourier force too (zeros "
        "are allowed)");
  }
  if (!A) throw std::invalid_argument("A is missing: give the amplitude A (or sin/cos)");
  if (need_phase && !phi0) {
    throw std::invalid_argument("phi0 is missing: give the impact phase phi0 [rad]");
  }
  return Forcing::Harmonic(*A, c, phi0.value_or(0.0));
}

std::vector<double> Coefficients(const Forcing& f, bool sine) {
  std::vector<double> out;
  for (int k = 1; k <= f.harmonics(); ++k) out.push_back(sine ? f.b(k) : f.a(k));
  return out;
}

py::object Number(double value) {
  return std::isfinite(value) ? py::object(py::float_(value)) : py::object(py::none());
}

py::dict SolutionDict(const Solution& s) {
  const Orbit& o = s.orbit;
  const Validity& v = s.validity;
  const Forcing& f = o.forcing;
  py::dict d;
  d["A"] = f.harmonic() ? Number(f.amplitude()) : py::none();
  d["c"] = Number(f.mean());
  d["phi0"] = Number(f.phi0());
  if (!f.harmonic()) {
    d["cos"] = Coefficients(f, false);
    d["sin"] = Coefficients(f, true);
  }
  d["T0"] = Number(o.T0);
  d["e"] = Number(o.e);
  d["status"] = StatusName(o.status);
  d["phi1"] = Number(o.phi1);
  d["alpha"] = Number(o.alpha);
  d["u"] = Number(o.u);
  d["v_plus"] = Number(o.v_plus);
  d["I"] = Number(o.I);
  d["v_mean"] = Number(o.v_mean);
  d["x_min"] = Number(v.x_min);
  d["x_max"] = Number(v.x_max);
  d["stroke"] = Number(v.stroke);
  d["clearance"] = Number(v.clearance);
  d["valid"] = v.valid();
  d["violations"] = v.ViolationNames();
  return d;
}

void AddEnergy(py::dict& d, const Energy& en) {
  py::dict energy;
  energy["motor_work"] = Number(en.motor_work);
  energy["motor_work_positive"] = Number(en.motor_work_positive);
  energy["friction_loss"] = Number(en.friction_loss);
  energy["impact_loss"] = Number(en.impact_loss);
  d["energy"] = energy;
}

void AddStability(py::dict& d, const Stability& st) {
  if (!st.computed) {
    d["multipliers"] = py::none();
    d["spectral_radius"] = py::none();
    d["stable"] = false;
    return;
  }
  py::list multipliers;
  for (const auto& z : st.multipliers) {
    py::dict m;
    m["re"] = Number(z.real());
    m["im"] = Number(z.imag());
    multipliers.append(m);
  }
  d["multipliers"] = multipliers;
  d["spectral_radius"] = Number(st.spectral_radius);
  d["stable"] = st.stable;
}

}  // namespace capsubot::python
