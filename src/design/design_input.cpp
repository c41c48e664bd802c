// The physical robot: validation of the SI inputs and their map to the dimensionless model
// (docs/model.md sections 2 and 9).

#include <fmt/format.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "capsubot/design/design.hpp"
#include "capsubot/model/limits.hpp"

namespace capsubot {
namespace {

constexpr double kDefaultM2MinRatio = 0.01;  // default m2 range: 0.01 m1 ...
constexpr double kDefaultM2MaxRatio = 10.0;  // ... 10 m1
constexpr int kMaxScanPoints = 100000;

void Require(bool ok, const std::string& message) {
  if (!ok) throw std::invalid_argument(message);
}

// "shell mass m1 = -1 is invalid: expected a finite m1 > 0 [kg]"
void RequirePositive(double value, const char* what, const char* symbol, const char* unit) {
  Require(std::isfinite(value) && value > 0.0,
          fmt::format("{} {} = {} is invalid: expected a finite {} > 0{}", what, symbol, value,
                      symbol, unit));
}

void RequireCoefficients(const std::vector<double>& values, const char* name) {
  for (std::size_t k = 0; k < values.size(); ++k) {
    Require(std::isfinite(values[k]),
            fmt::format("motor force {}[{}] = {} is invalid: expected a finite coefficient [N]",
                        name, k + 1, values[k]));
  }
}

}  // namespace

void MotorForce::Validate() const {
  Require(std::isfinite(bias) && bias >= 0.0,
          fmt::format("motor force bias = {} is invalid: expected a finite bias >= 0 [N]", bias));
  if (!fourier()) {
    Require(std::isfinite(amplitude) && amplitude >= 0.0,
            fmt::format("motor force amplitude = {} is invalid: expected a finite amplitude >= 0 "
                        "[N] (or Fourier coefficients)",
                        amplitude));
    return;
  }
  Require(cos.empty() || cos.size() == sin.size(),
          fmt::format("motor force cos = {} coefficients is invalid: expected as many as sin ({})",
                      cos.size(), sin.size()));
  Require(!sin.empty() && sin.size() <= static_cast<std::size_t>(kMaxHarmonics),
          fmt::format("motor force sin = {} coefficients is invalid: expected 1 to {}", sin.size(),
                      kMaxHarmonics));
  RequireCoefficients(cos, "cos");
  RequireCoefficients(sin, "sin");
}

double DesignInput::M2Min() const { return std::isnan(m2_min) ? kDefaultM2MinRatio * m1 : m2_min; }
double DesignInput::M2Max() const { return std::isnan(m2_max) ? kDefaultM2MaxRatio * m1 : m2_max; }

void DesignInput::Validate() const {
  RequirePositive(m1, "shell mass", "m1", " [kg]");
  // The default inner-mass range is 0.01 m1 .. 10 m1: where it leaves double precision, the
  // mass given is the bad input, not a range never given.
  Require(!std::isnan(m2_min) || !std::isnan(m2_max) || std::isfinite(M2Max()),
          fmt::format("shell mass m1 = {} kg is invalid: expected m1 <= {} kg, so that the default "
                      "inner mass range 0.01 m1:10 m1 is finite (or give the inner mass range)",
                      m1, std::numeric_limits<double>::max() / kDefaultM2MaxRatio));
  RequirePositive(L, "gap", "L", " [m]");
  RequirePositive(mu, "friction coefficient", "mu", "");
  RequirePositive(g, "gravity", "g", " [m/s^2]");
  Require(e >= 0.0 && e <= 1.0,
          fmt::format("restitution e = {} is invalid: expected 0 <= e <= 1", e));
  force.Validate();
  RequirePositive(frequency_min, "frequency", "f", " [Hz]");
  Require(std::isfinite(frequency_max) && frequency_max >= frequency_min,
          fmt::format("frequency range = {}:{} is invalid: expected finite FMIN <= FMAX [Hz]",
                      frequency_min, frequency_max));
  const double lo = M2Min(), hi = M2Max();
  Require(std::isfinite(lo) && std::isfinite(hi) && lo > 0.0 && lo < hi,
          fmt::format("inner mass range m2 = {}:{} is invalid: expected 0 < M2MIN < M2MAX [kg]", lo,
                      hi));
  Params{1.0, e}.Validate();  // the rule of e
  Margins{margin, margin_stroke, stick_margin}.Validate();
  Require(rho_max > 0.0, fmt::format("rho_max = {} is invalid: expected rho_max > 0 (infinity: "
                                     "no stability requirement)",
                                     rho_max));
  Require(scan_points >= 3 && scan_points <= kMaxScanPoints,
          fmt::format("scan_points = {} is invalid: expected 3 <= scan_points <= {}", scan_points,
                      kMaxScanPoints));
  Require(orbit_evaluations >= 1 && orbit_evaluations <= kMaxOrbitEvaluations,
          fmt::format("orbit_evaluations = {} is invalid: expected 1 <= orbit_evaluations <= {}",
                      orbit_evaluations, kMaxOrbitEvaluations));
  // The dimensionless model (MapToModel) at the corners of the searched ranges must exist in
  // double precision: extreme SI inputs (f = 1e300 Hz, m2 = 1e300 kg) would round T0, the
  // force or alpha to 0, 1 or infinity.
  double force_bound = force.bias + (force.fourier() ? 0.0 : force.amplitude);  // [N]
  for (const double c : force.cos) force_bound += std::abs(c);
  for (const double c : force.sin) force_bound += std::abs(c);
  for (const double m2 : {lo, hi}) {
    for (const double f : {frequency_min, frequency_max}) {
      const double w2L = (kTau * f) * (kTau * f) * L, T0 = mu * g / w2L;
      const double largest = force_bound / ((m1 + m2) * w2L), alpha = m2 / (m1 + m2);
      Require(std::isfinite(T0) && T0 > 0.0 && std::isfinite(largest) && alpha > 0.0 && alpha < 1.0,
              fmt::format("inputs m2 = {} kg, f = {} Hz are invalid: with m1 = {} kg, L = {} m, "
                          "mu = {}, g = {} m/s^2 they give T0 = {}, a force up to {} and alpha = "
                          "{} (dimensionless): expected T0 > 0, a finite force and 0 < alpha < 1 "
                          "in double precision (inputs of realistic size)",
                          m2, f, m1, L, mu, g, T0, largest, alpha));
    }
  }
}

DesignModel MapToModel(const DesignInput& in, double m2, double frequency) {
  DesignModel m;
  m.omega = kTau * frequency;
  const double w2L = m.omega * m.omega * in.L;
  const double force_unit = (in.m1 + m2) * w2L;  // (m1+m2) omega^2 L [N]
  const MotorForce& f = in.force;
  if (f.fourier()) {
    std::vector<double> a(f.sin.size(), 0.0), b(f.sin.size());
    for (std::size_t k = 0; k < b.size(); ++k) {
      if (!f.cos.empty()) a[k] = f.cos[k] / force_unit;
      b[k] = f.sin[k] / force_unit;
    }
    m.robot.forcing = Forcing::Fourier(f.bias / force_unit, a, b, 0.0);
  } else {
    m.robot.forcing = Forcing::Harmonic(f.amplitude / force_unit, f.bias / force_unit, 0.0);
  }
  m.robot.params.T0 = in.mu * in.g / w2L;
  m.robot.params.e = in.e;
  m.margins = {in.margin, in.margin_stroke, in.stick_margin};
  m.robot.alpha = m2 / (in.m1 + m2);
  return m;
}

}  // namespace capsubot
