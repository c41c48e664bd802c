#include "capsubot/model/force_spec.hpp"

#include <fmt/format.h>

#include <stdexcept>

namespace capsubot {

void RequireSeriesTerms(const std::string& name, const char* symbol,
                        const std::optional<std::vector<double>>& terms) {
  if (terms && terms->empty()) {
    throw std::invalid_argument(fmt::format(
        "{} = [] is invalid: expected the coefficients {}_1..{}_K, 1 <= K <= {} (an empty "
        "series is no force)",
        name, symbol, symbol, kMaxHarmonics));
  }
}

void RefusePulse(const Forcing& forcing, const std::string& what) {
  if (!forcing.pulse()) return;
  throw std::invalid_argument(fmt::format(
      "a pulse force is invalid for {}: expected a sine or Fourier force (the analytic "
      "one-impact orbit needs one; simulate, attractors, periodic, continue, basins and "
      "bifurcation take a pulse force)",
      what));
}

namespace {

// A pulse force from its levels and switches; "levels: ..." and "switches: ..." messages of
// Forcing::Pulse name the parameters with the prefix p.
Forcing BuildPulse(const ForceSpec& s, const std::string& p) {
  if (s.A || s.sin || s.cos) {
    throw std::invalid_argument(fmt::format(
        "{0}waveform pulse takes {0}levels and {0}switches: {0}{1} is invalid with it", p,
        s.A     ? "A"
        : s.sin ? "sin"
                : "cos"));
  }
  if (s.c) {
    throw std::invalid_argument(fmt::format(
        "{0}c = {1} is invalid with {0}waveform pulse: expected no {0}c (the levels give the mean "
        "force)",
        p, *s.c));
  }
  if (!s.levels || !s.switches) {
    throw std::invalid_argument(
        fmt::format("{0}{1} is missing: a pulse force needs {0}levels L_1,...,L_N and {0}switches "
                    "s_1,...,s_N [rad]",
                    p, s.levels ? "switches" : "levels"));
  }
  try {
    return Forcing::Pulse(*s.levels, *s.switches, s.phi0.value_or(0.0));
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    if (what.rfind("levels", 0) == 0 || what.rfind("switches", 0) == 0) {
      throw std::invalid_argument(p + what);
    }
    throw;
  }
}

}  // namespace

Forcing ForceSpec::Build(bool need_phase, const std::string& p) const {
  const bool pulse_parts = levels || switches;
  if (waveform && *waveform != "sine" && *waveform != "fourier" && *waveform != "pulse") {
    throw std::invalid_argument(
        fmt::format("{}waveform = '{}' is invalid: expected sine, fourier or pulse", p, *waveform));
  }
  if (waveform ? *waveform == "pulse" : pulse_parts) return BuildPulse(*this, p);
  if (pulse_parts) {
    throw std::invalid_argument(fmt::format(
        "{0}{1} is invalid with {0}waveform {2}: expected it only with {0}waveform pulse", p,
        levels ? "levels" : "switches", *waveform));
  }
  if (waveform && *waveform == "fourier" && !sin) {
    throw std::invalid_argument(fmt::format(
        "{0}sin is missing: {0}waveform fourier needs the sine coefficients b_1..b_K (and "
        "{0}cos)",
        p));
  }
  if (waveform && *waveform == "sine" && (sin || cos)) {
    throw std::invalid_argument(
        fmt::format("{0}{1} is invalid with {0}waveform sine: expected {0}A, {0}c and {0}phi0", p,
                    sin ? "sin" : "cos"));
  }
  if (!c) {
    throw std::invalid_argument(fmt::format("{}c is missing: give the mean force c", p));
  }
  RequireSeriesTerms(p + "sin", "b", sin);
  RequireSeriesTerms(p + "cos", "a", cos);
  if (sin) {
    if (A) {
      throw std::invalid_argument(fmt::format(
          "{0}A and {0}sin are exclusive: give the amplitude A of A sin(phi + phi0) + c, or the "
          "Fourier coefficients {0}sin (and {0}cos)",
          p));
    }
    const std::vector<double> a = cos ? *cos : std::vector<double>(sin->size(), 0.0);
    return Forcing::Fourier(*c, a, *sin, phi0.value_or(0.0));
  }
  if (cos) {
    throw std::invalid_argument(fmt::format(
        "{0}cos needs {0}sin: give the sine coefficients b_1..b_K of the Fourier force too "
        "(zeros are allowed)",
        p));
  }
  if (!A) {
    throw std::invalid_argument(
        fmt::format("{0}A is missing: give the amplitude A (or {0}sin/{0}cos)", p));
  }
  if (need_phase && !phi0) {
    throw std::invalid_argument(
        fmt::format("{}phi0 is missing: give the impact phase phi0 [rad]", p));
  }
  return Forcing::Harmonic(*A, *c, phi0.value_or(0.0));
}

}  // namespace capsubot
