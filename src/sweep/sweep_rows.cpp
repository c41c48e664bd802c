#include "sweep/sweep_rows.hpp"

#include <charconv>
#include <cmath>
#include <iterator>
#include <stdexcept>

#include "capsubot/optimize_phase.hpp"
#include "capsubot/robot_orbits.hpp"
#include "capsubot/stability.hpp"

namespace capsubot::detail {
namespace {

// Bumped whenever the bytes of a sweep change for the same options (invalidates checkpoints).
constexpr int kFormatVersion = 1;

bool RobotMode(const SweepOptions& o) { return o.grid.Has(SweepParameter::kalpha); }

void Append(RowBuffer& out, const char* text) { out.append(fmt::string_view(text)); }

// Exact text of a double for the description (hexadecimal: no rounding at all).
std::string Hex(double value) { return fmt::format("{:a}", value); }

}  // namespace

void AppendNumber(RowBuffer& out, double value) {
  if (std::isnan(value)) return;
  // std::to_chars with a precision formats exactly as printf("%.17g") (and so as fmt's
  // "{:.17g}" in FormatNumber), about twice as fast as fmt 9 here (measured).
  char text[32];
  const std::to_chars_result r =
      std::to_chars(text, text + sizeof text, value, std::chars_format::general, 17);
  out.append(text, r.ptr);
}

std::string SweepHeaderLine(const SweepOptions& options) {
  std::string line;
  for (const std::string& name : SweepColumns(options)) {
    line += (line.empty() ? "" : ",") + name;
  }
  return line + '\n';
}

std::string SweepDescription(const SweepOptions& o) {
  std::string d = fmt::format("format={} columns={}", kFormatVersion, SweepHeaderLine(o));
  d.pop_back();  // the header's '\n'
  for (const GridAxis& axis : o.grid.axes) {
    d += fmt::format(" grid={}:{}:{}:{}", SweepParameterName(axis.parameter), Hex(axis.lo),
                     Hex(axis.hi), axis.n);
  }
  const Forcing& f = o.forcing;
  d += fmt::format(" c={} phi0={} K={}", Hex(f.mean()), Hex(f.phi0()), f.harmonics());
  for (int k = 1; k <= f.harmonics(); ++k)
    d += fmt::format(" a{}={} b{}={}", k, Hex(f.a(k)), k, Hex(f.b(k)));
  d += fmt::format(
      " T0={} e={} margin={} margin_stroke={} stick_margin={} stability={} "
      "optimize_phi0={}",
      Hex(o.params.T0), Hex(o.params.e), Hex(o.params.margin), Hex(o.params.margin_stroke),
      Hex(o.params.stick_margin), o.stability, o.optimize_phi0);
  if (o.optimize_phi0) {
    const PhaseOptions& p = o.phase;
    d += fmt::format(" scan_points={} phase_tol={} rho_max={}", p.scan_points, Hex(p.phase_tol),
                     Hex(p.rho_max));
  }
  return d;
}

SweepRowWriter::SweepRowWriter(const SweepOptions& options)
    : options_(options), forcing_(options.forcing), params_(options.params) {
  const Grid& g = options.grid;
  rebuild_force_ = g.Has(SweepParameter::kA) || g.Has(SweepParameter::kc);
  const Forcing& f = options.forcing;
  for (int k = 1; k <= f.harmonics(); ++k) {
    a_.push_back(f.a(k));
    b_.push_back(f.b(k));
  }
  if (a_.empty()) {  // the zero-amplitude harmonic force still has a slot for A
    a_.push_back(0.0);
    b_.push_back(0.0);
  }
  c_ = f.mean();
  phi0_ = f.phi0();
}

void SweepRowWriter::SetPoint(std::int64_t point) {
  const Grid& g = options_.grid;
  double phi0 = phi0_;
  bool phase_changed = false;
  for (std::size_t i = 0; i < g.axes.size(); ++i) {
    const double value = g.Value(point, i);
    switch (g.axes[i].parameter) {
      case SweepParameter::kA:
        b_[0] = value;
        break;
      case SweepParameter::kc:
        c_ = value;
        break;
      case SweepParameter::kphi0:
        phi0 = value;
        phase_changed = true;
        break;
      case SweepParameter::kT0:
        params_.T0 = value;
        break;
      case SweepParameter::ke:
        params_.e = value;
        break;
      case SweepParameter::kmargin:
        params_.margin = value;
        break;
      case SweepParameter::kalpha:
        alpha_ = value;
        break;
    }
  }
  if (rebuild_force_) {
    forcing_ = Forcing::Fourier(c_, a_, b_, phi0);  // no allocation: the vectors are ours
  } else if (phase_changed) {
    forcing_ = options_.forcing.WithPhase(phi0);
  }
}

void SweepRowWriter::AppendSolution(const Solution& s, RowBuffer& out) const {
  const Orbit& o = s.orbit;
  const Validity& v = s.validity;
  for (double value : {o.phi1, o.alpha, o.u, o.v_plus, o.I, o.v_mean, v.x_min, v.x_max}) {
    AppendNumber(out, value);
    out.push_back(',');
  }
  out.push_back(v.valid() ? '1' : '0');
  out.push_back(',');
  bool first = true;
  for (int i = 0; i < static_cast<int>(Condition::kCount); ++i) {
    if (!v.violated(static_cast<Condition>(i))) continue;
    if (!first) out.push_back(';');
    Append(out, ConditionName(static_cast<Condition>(i)));
    first = false;
  }
  if (options_.stability) {
    out.push_back(',');
    if (o.ok()) {
      const Stability st = ComputeStability(o);
      AppendNumber(out, st.computed ? st.spectral_radius : Stability::kNaN);
      out.push_back(',');
      if (st.computed) out.push_back(st.stable ? '1' : '0');
    } else {
      out.push_back(',');
    }
  }
}

int SweepRowWriter::AppendPoint(std::int64_t point, RowBuffer& out) {
  SetPoint(point);
  const Grid& g = options_.grid;
  const auto append_axes = [&] {
    for (std::size_t i = 0; i < g.axes.size(); ++i) {
      AppendNumber(out, g.Value(point, i));
      out.push_back(',');
    }
  };
  if (RobotMode(options_)) {
    bool complete = true;
    const std::vector<Solution> orbits = FindRobotOrbits(forcing_, params_, alpha_, &complete);
    if (!complete) {  // never write a row set that may miss orbits
      throw std::runtime_error(fmt::format(
          "robot orbits at grid point {} (alpha = {}): the search stopped at its work bound, "
          "orbits may be missing",
          point, alpha_));
    }
    if (orbits.empty()) {
      append_axes();
      // orbits = 0, then empty cells: orbit, phi0, 8 numbers, valid, violations [, 2]
      Append(out, options_.stability ? "0,,,,,,,,,,,,,,\n" : "0,,,,,,,,,,,,\n");
      return 1;
    }
    int index = 0;
    for (const Solution& s : orbits) {
      append_axes();
      fmt::format_to(fmt::appender(out), "{},{},", orbits.size(), ++index);
      AppendNumber(out, s.orbit.forcing.phi0());
      out.push_back(',');
      AppendSolution(s, out);
      out.push_back('\n');
    }
    return index;
  }
  append_axes();
  if (options_.optimize_phi0) {
    const OptimizeResult r = OptimizePhase(forcing_, params_, options_.phase);
    const Solution& s = r.solution;
    AppendNumber(out, s.orbit.ok() || s.orbit.status != OrbitStatus::kNotRun
                          ? s.orbit.forcing.phi0()
                          : Orbit::kNaN);
    out.push_back(',');
    AppendSolution(s, out);
    out.push_back(',');
    Append(out, OptimizeStatusName(r.status));
    out.push_back('\n');
    return 1;
  }
  AppendSolution(Solve(forcing_, params_), out);
  out.push_back('\n');
  return 1;
}

}  // namespace capsubot::detail
