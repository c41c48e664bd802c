#include "report.hpp"

#include <fmt/format.h>

#include <cmath>

namespace capsubot::app {
namespace {

std::vector<double> Coefficients(const Forcing& f, bool sine) {
  std::vector<double> out;
  for (int k = 1; k <= f.harmonics(); ++k) out.push_back(sine ? f.b(k) : f.a(k));
  return out;
}

std::string Num(double value) { return std::isnan(value) ? "-" : fmt::format("{:.10g}", value); }

}  // namespace

nlohmann::json SolutionJson(const Solution& s) {
  const Orbit& o = s.orbit;
  const Validity& v = s.validity;
  const Forcing& f = o.forcing;
  nlohmann::json j;
  j["A"] = f.harmonic() ? nlohmann::json(f.amplitude()) : nlohmann::json();
  j["c"] = f.mean();
  j["phi0"] = f.phi0();
  if (!f.harmonic()) {
    j["cos"] = Coefficients(f, false);
    j["sin"] = Coefficients(f, true);
  }
  j["T0"] = o.T0;
  j["e"] = o.e;
  j["status"] = StatusName(o.status);
  // nlohmann::json writes NaN as null: a quantity that does not exist is null.
  j["phi1"] = o.phi1;
  j["alpha"] = o.alpha;
  j["u"] = o.u;
  j["v_plus"] = o.v_plus;
  j["I"] = o.I;
  j["v_mean"] = o.v_mean;
  j["x_min"] = v.x_min;
  j["x_max"] = v.x_max;
  j["valid"] = v.valid();
  j["violations"] = v.ViolationNames();
  return j;
}

std::string ForceFormula(const Forcing& f) {
  if (f.harmonic()) {
    return fmt::format("F(phi) = {:.6g} sin(phi {} {:.6g}) + {:.6g}", f.amplitude(),
                       f.phi0() < 0 ? '-' : '+', std::abs(f.phi0()), f.mean());
  }
  std::string s = fmt::format("F(phi) = {:.6g}", f.mean());
  for (int k = 1; k <= f.harmonics(); ++k) {
    s += fmt::format(" + {:.6g} cos {}t + {:.6g} sin {}t", f.a(k), k, f.b(k), k);
  }
  return s + fmt::format(",  t = phi + {:.6g}", f.phi0());
}

std::string SolutionTable(const Solution& s, const Params& p) {
  const Orbit& o = s.orbit;
  const Validity& v = s.validity;
  std::string t;
  t += fmt::format("one-impact periodic orbit\n");
  t += fmt::format("  force            {}\n", ForceFormula(o.forcing));
  t += fmt::format("  model            T0 = {:g}, e = {:g}, margin = {:g}\n", p.T0, p.e, p.margin);
  t += fmt::format("  status           {}\n", StatusName(o.status));
  t += fmt::format("  stop phase       phi1   = {}\n", Num(o.phi1));
  t += fmt::format("  mass ratio       alpha  = {}   (m2/(m1+m2))\n", Num(o.alpha));
  t += fmt::format("  impact velocity  u      = {}   (omega L)\n", Num(o.u));
  t += fmt::format("  capsule kick     v_plus = {}   (omega L)\n", Num(o.v_plus));
  t += fmt::format("  step per period  I      = {}   (L)\n", Num(o.I));
  t += fmt::format("  mean velocity    v_mean = {}   (omega L)\n", Num(o.v_mean));
  t += fmt::format("  inner body       x_min  = {}, x_max = {}   (walls at 0 and 1)\n",
                   Num(v.x_min), Num(v.x_max));
  if (v.valid()) {
    t += "  valid            yes: every condition of docs/model.md section 5 holds\n";
  } else {
    std::string names;
    for (const auto& n : v.ViolationNames()) names += (names.empty() ? "" : ", ") + n;
    t += fmt::format("  valid            no: violated {}\n", names);
  }
  return t;
}

void AddStabilityJson(nlohmann::json& j, const Stability& st) {
  if (!st.computed) {
    j["multipliers"] = nullptr;
    j["spectral_radius"] = nullptr;
    j["stable"] = false;
    return;
  }
  nlohmann::json m = nlohmann::json::array();
  for (const auto& z : st.multipliers) m.push_back({{"re", z.real()}, {"im", z.imag()}});
  j["multipliers"] = m;
  j["spectral_radius"] = st.spectral_radius;
  j["stable"] = st.stable;
}

std::string StabilityTable(const Stability& st) {
  if (!st.computed) return "  stability        not computed (no orbit)\n";
  std::string t;
  for (int i = 0; i < 2; ++i) {
    const auto& z = st.multipliers[i];
    t += fmt::format("  multiplier {}     {} {} {}i\n", i + 1, Num(z.real()),
                     z.imag() < 0 ? '-' : '+', Num(std::abs(z.imag())));
  }
  t += fmt::format("  spectral radius  {}   ({}: docs/model.md section 8)\n",
                   Num(st.spectral_radius), st.stable ? "stable, < 1" : "unstable, >= 1");
  return t;
}

}  // namespace capsubot::app
