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

// A pulse force from its levels and switches; the messages name the parameters in `n`.
Forcing BuildPulse(const ForceSpec& s, const SettingNames& n) {
  if (s.A || s.sin || s.cos) {
    throw std::invalid_argument(fmt::format("{} pulse takes {} and {}: {} is invalid with it",
                                            n.Name("waveform"), n.Name("levels"),
                                            n.Name("switches"),
                                            n.Name(s.A     ? "A"
                                                   : s.sin ? "sin"
                                                           : "cos")));
  }
  if (s.c) {
    throw std::invalid_argument(fmt::format(
        "{0} = {1} is invalid with {2} pulse: expected no {0} (the levels give the mean force)",
        n.Name("c"), *s.c, n.Name("waveform")));
  }
  if (!s.levels || !s.switches) {
    throw std::invalid_argument(fmt::format(
        "{} is missing: a pulse force needs {} L_1,...,L_N and {} s_1,...,s_N [rad]",
        n.Name(s.levels ? "switches" : "levels"), n.Name("levels"), n.Name("switches")));
  }
  try {
    return Forcing::Pulse(*s.levels, *s.switches, s.phi0.value_or(0.0));
  } catch (const std::invalid_argument& e) {
    const std::string what = e.what();
    if (what.rfind("levels", 0) == 0 || what.rfind("switches", 0) == 0) {
      throw std::invalid_argument(WithFlagNames(what, n.flags));
    }
    throw;
  }
}

// The rules of the parts of a sine or Fourier force; the messages name them in `n`.
void RequireSmoothParts(const ForceSpec& s, const SettingNames& n) {
  if (s.levels || s.switches) {
    throw std::invalid_argument(
        fmt::format("{} is invalid with {} {}: expected it only with {} pulse",
                    n.Name(s.levels ? "levels" : "switches"), n.Name("waveform"), *s.waveform,
                    n.Name("waveform")));
  }
  if (s.waveform && *s.waveform == "fourier" && !s.sin) {
    throw std::invalid_argument(
        fmt::format("{0} is missing: {1} fourier needs the sine coefficients b_1..b_K (and {2})",
                    n.Name("sin"), n.Name("waveform"), n.Name("cos")));
  }
  if (s.waveform && *s.waveform == "sine" && (s.sin || s.cos)) {
    throw std::invalid_argument(fmt::format("{} is invalid with {} sine: expected {}, {} and {}",
                                            n.Name(s.sin ? "sin" : "cos"), n.Name("waveform"),
                                            n.Name("A"), n.Name("c"), n.Name("phi0")));
  }
  if (!s.c) {
    throw std::invalid_argument(fmt::format("{} is missing: give the mean force c", n.Name("c")));
  }
  RequireSeriesTerms(n.Name("sin"), "b", s.sin);
  RequireSeriesTerms(n.Name("cos"), "a", s.cos);
}

}  // namespace

Forcing ForceSpec::Build(bool need_phase, const FlagNames& names) const {
  const SettingNames n{names};
  if (waveform && *waveform != "sine" && *waveform != "fourier" && *waveform != "pulse") {
    throw std::invalid_argument(fmt::format("{} = '{}' is invalid: expected sine, fourier or pulse",
                                            n.Name("waveform"), *waveform));
  }
  if (waveform ? *waveform == "pulse" : levels || switches) return BuildPulse(*this, n);
  RequireSmoothParts(*this, n);
  if (sin) {
    if (A) {
      throw std::invalid_argument(fmt::format(
          "{0} and {1} are exclusive: give the amplitude A of A sin(phi + phi0) + c, or the "
          "Fourier coefficients {1} (and {2})",
          n.Name("A"), n.Name("sin"), n.Name("cos")));
    }
    const std::vector<double> a = cos ? *cos : std::vector<double>(sin->size(), 0.0);
    return Forcing::Fourier(*c, a, *sin, phi0.value_or(0.0));
  }
  if (cos) {
    throw std::invalid_argument(fmt::format(
        "{0} needs {1}: give the sine coefficients b_1..b_K of the Fourier force too (zeros are "
        "allowed)",
        n.Name("cos"), n.Name("sin")));
  }
  if (!A) {
    throw std::invalid_argument(fmt::format("{} is missing: give the amplitude A (or {}/{})",
                                            n.Name("A"), n.Name("sin"), n.Name("cos")));
  }
  if (need_phase && !phi0) {
    throw std::invalid_argument(
        fmt::format("{} is missing: give the impact phase phi0 [rad]", n.Name("phi0")));
  }
  return Forcing::Harmonic(*A, *c, phi0.value_or(0.0));
}

}  // namespace capsubot
