// The coordinates of the drives a reach search varies (docs/reach.md, "Drives").

#include "capsubot/reach/drive_family.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace capsubot {
namespace {

// A direction G whose largest value is below this is the zero force (its scale is not defined).
constexpr double kZeroDirection = 1e-12;
// A force belongs to a family under a bound it exceeds by rounding only (relative).
constexpr double kBoundRounding = 1e-12;

// The base coefficients (motor phase) of the direction at y[1..2K] of a Fourier family: the
// mean, a_1 = 0 and b_1, then a_k, b_k.
struct Series {
  double c = 0.0;
  std::vector<double> a, b;
};

Series DirectionAt(int harmonics, const double* g) {
  Series s;
  s.c = g[0];
  s.a.assign(static_cast<std::size_t>(harmonics), 0.0);
  s.b.assign(static_cast<std::size_t>(harmonics), 0.0);
  s.b[0] = g[1];
  for (int k = 2; k <= harmonics; ++k) {
    s.a[static_cast<std::size_t>(k - 1)] = g[2 * k - 2];
    s.b[static_cast<std::size_t>(k - 1)] = g[2 * k - 1];
  }
  return s;
}

Series Scaled(Series s, double factor) {
  s.c *= factor;
  for (double& v : s.a) v *= factor;
  for (double& v : s.b) v *= factor;
  return s;
}

}  // namespace

const char* WaveformName(Waveform waveform) {
  switch (waveform) {
    case Waveform::kSine:
      return "sine";
    case Waveform::kFourier:
      return "fourier";
    case Waveform::kPulse:
      return "pulse";
  }
  return "";
}

DriveFamily DriveFamily::Fourier(int harmonics) {
  DriveFamily f;
  f.waveform = Waveform::kFourier;
  f.harmonics = harmonics;
  return f;
}

DriveFamily DriveFamily::Pulse(int levels) {
  DriveFamily f;
  f.waveform = Waveform::kPulse;
  f.levels = levels;
  return f;
}

void DriveFamily::Validate() const {
  if (waveform == Waveform::kPulse && (levels < 2 || levels > kMaxPulseLevels)) {
    throw std::invalid_argument(
        fmt::format("levels = {} is invalid: expected 2 <= levels <= {}", levels, kMaxPulseLevels));
  }
  if (waveform == Waveform::kFourier && (harmonics < 1 || harmonics > kMaxHarmonics)) {
    throw std::invalid_argument(fmt::format(
        "harmonics = {} is invalid: expected 1 <= harmonics <= {}", harmonics, kMaxHarmonics));
  }
}

int DriveFamily::Dimension() const {
  if (waveform == Waveform::kPulse) return 2 * levels;
  return sine() ? 2 : 2 * harmonics;
}

std::string DriveFamily::Describe() const {
  if (waveform == Waveform::kPulse) return fmt::format("pulse, N = {}", levels);
  return sine() ? "sine" : fmt::format("Fourier, K = {}", harmonics);
}

void DriveBox(const DriveFamily& family, std::vector<double>& lower, std::vector<double>& upper) {
  const auto n = static_cast<std::size_t>(family.Dimension());
  lower.assign(n, 0.0);
  upper.assign(n, 1.0);
  if (family.waveform == Waveform::kPulse) {  // levels in [-1, 1], widths in [min, 1]
    for (int j = 0; j < family.levels; ++j) {
      lower[static_cast<std::size_t>(j)] = -1.0;
      lower[static_cast<std::size_t>(family.levels + j)] = kMinPulseWidth;
    }
    return;
  }
  // Fourier: the mean in [-1, 1], b_1 in [0, 1], the other coefficients in [-1, 1].
  if (!family.sine()) {
    lower[0] = -1.0;
    for (std::size_t i = 2; i < n; ++i) lower[i] = -1.0;
  }
}

namespace {

// The pulse drive at y: levels y[j] bound, widths y[N + j] (clamped into the box).
Forcing PulseAt(int N, const double* y, double bound, double phi0) {
  std::vector<double> levels(static_cast<std::size_t>(N)), switches(levels.size());
  double total = 0.0;
  for (int j = 0; j < N; ++j) total += std::clamp(y[N + j], kMinPulseWidth, 1.0);
  double at = 0.0;
  for (int j = 0; j < N; ++j) {
    levels[static_cast<std::size_t>(j)] = std::clamp(y[j], -1.0, 1.0) * bound;
    switches[static_cast<std::size_t>(j)] = kTau * at / total;
    at += std::clamp(y[N + j], kMinPulseWidth, 1.0);
  }
  return Forcing::Pulse(levels, switches, phi0);
}

// The box point of a pulse force of at most N levels whose first switch is at 0 (padded with
// pieces of the last level at the narrowest width), empty otherwise.
std::vector<double> PulseCoordinates(int N, const Forcing& f, double bound) {
  const int n = f.pulse_levels();
  if (n > N || f.switch_phase(0) != 0.0) return {};
  std::vector<double> widths;
  for (int j = 0; j < n; ++j) {
    widths.push_back((j + 1 < n ? f.switch_phase(j + 1) : kTau) - f.switch_phase(j));
  }
  const double widest = *std::max_element(widths.begin(), widths.end());
  std::vector<double> y(static_cast<std::size_t>(2 * N));
  for (int j = 0; j < N; ++j) {
    const int from = std::min(j, n - 1);
    y[static_cast<std::size_t>(j)] = f.level(from) / bound;
    y[static_cast<std::size_t>(N + j)] =
        j < n ? std::max(widths[static_cast<std::size_t>(j)] / widest, kMinPulseWidth) : 0.0;
  }
  return y;
}

}  // namespace

Forcing DriveAt(const DriveFamily& family, const double* y, double bound, double phi0) {
  if (family.waveform == Waveform::kPulse) return PulseAt(family.levels, y, bound, phi0);
  if (family.sine()) {
    const double s = std::clamp(y[0], 0.0, 1.0), r = std::clamp(y[1], 0.0, 1.0);
    return Forcing::Harmonic(s * (1.0 - r) * bound, s * r * bound, phi0);
  }
  const Series g = DirectionAt(family.harmonics, y);
  const double largest = Forcing::Fourier(g.c, g.a, g.b, 0.0).MaxAbs();
  const Series f = largest > kZeroDirection ? Scaled(g, bound / largest) : Scaled(g, 0.0);
  return Forcing::Fourier(f.c, f.a, f.b, phi0);
}

std::vector<double> DriveCoordinates(const DriveFamily& family, const Forcing& forcing,
                                     double bound) {
  const double largest = forcing.MaxAbs();
  if (!(largest <= bound * (1.0 + kBoundRounding))) return {};
  if (family.waveform == Waveform::kPulse || forcing.pulse()) {
    if (family.waveform != Waveform::kPulse || !forcing.pulse()) return {};
    return PulseCoordinates(family.levels, forcing, bound);
  }
  const int K = forcing.harmonics();
  if (!(largest <= bound * (1.0 + kBoundRounding)) || (K >= 1 && forcing.a(1) != 0.0) ||
      (K >= 1 && forcing.b(1) < 0.0)) {
    return {};
  }
  if (family.sine()) {
    if (!forcing.harmonic() || forcing.mean() < 0.0) return {};
    const double A = forcing.amplitude(), c = forcing.mean();
    if (A + c == 0.0) return {0.0, 0.0};
    return {std::min((A + c) / bound, 1.0), c / (A + c)};
  }
  if (K > family.harmonics) return {};
  // The direction: the coefficients over the largest of them (so each is in [-1, 1]).
  std::vector<double> g(static_cast<std::size_t>(2 * family.harmonics), 0.0);
  g[0] = forcing.mean();
  if (K >= 1) g[1] = forcing.b(1);
  for (int k = 2; k <= K; ++k) {
    g[static_cast<std::size_t>(2 * k - 2)] = forcing.a(k);
    g[static_cast<std::size_t>(2 * k - 1)] = forcing.b(k);
  }
  double top = 0.0;
  for (double v : g) top = std::max(top, std::abs(v));
  for (double& v : g) v = top > 0.0 ? v / top : 0.0;
  return g;
}

Forcing ScaledDrive(const Forcing& forcing, double factor) {
  if (forcing.pulse()) {
    std::vector<double> levels, switches;
    for (int j = 0; j < forcing.pulse_levels(); ++j) {
      levels.push_back(factor * forcing.level(j));
      switches.push_back(forcing.switch_phase(j));
    }
    return Forcing::Pulse(levels, switches, forcing.phi0());
  }
  std::vector<double> a(static_cast<std::size_t>(forcing.harmonics())), b = a;
  for (int k = 1; k <= forcing.harmonics(); ++k) {
    a[static_cast<std::size_t>(k - 1)] = factor * forcing.a(k);
    b[static_cast<std::size_t>(k - 1)] = factor * forcing.b(k);
  }
  return Forcing::Fourier(factor * forcing.mean(), a, b, forcing.phi0());
}

Forcing WithHarmonicsOf(const DriveFamily& family, const Forcing& forcing) {
  if (family.sine() || family.waveform == Waveform::kPulse ||
      forcing.harmonics() >= family.harmonics)
    return forcing;
  std::vector<double> a(static_cast<std::size_t>(family.harmonics), 0.0), b = a;
  for (int k = 1; k <= forcing.harmonics(); ++k) {
    a[static_cast<std::size_t>(k - 1)] = forcing.a(k);
    b[static_cast<std::size_t>(k - 1)] = forcing.b(k);
  }
  return Forcing::Fourier(forcing.mean(), a, b, forcing.phi0());
}

}  // namespace capsubot
