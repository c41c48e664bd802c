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

Forcing ForceSpec::Build(bool need_phase, const std::string& p) const {
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
    return Forcing::Fourier(c, a, *sin, phi0.value_or(0.0));
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
  return Forcing::Harmonic(*A, c, phi0.value_or(0.0));
}

}  // namespace capsubot
