#include "capsubot/grid.hpp"

#include <fmt/format.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <stdexcept>

#include "capsubot/forcing.hpp"

namespace capsubot {
namespace {

constexpr SweepParameter kAllParameters[] = {
    SweepParameter::kA, SweepParameter::kc,      SweepParameter::kphi0, SweepParameter::kT0,
    SweepParameter::ke, SweepParameter::kmargin, SweepParameter::kalpha};
constexpr std::int64_t kMaxPoints = std::int64_t{1} << 53;  // indices stay exact in a double

[[noreturn]] void Fail(const std::string& spec, const std::string& why) {
  throw std::invalid_argument(fmt::format("--grid {} is invalid: {}", spec, why));
}

// A bound: a decimal number, or pi / -pi / +pi.
bool ParseBound(const std::string& text, double& value) {
  if (text == "pi" || text == "+pi") {
    value = kTau / 2.0;
    return true;
  }
  if (text == "-pi") {
    value = -kTau / 2.0;
    return true;
  }
  if (text.empty()) return false;
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && errno != ERANGE;
}

void CheckAxis(const GridAxis& axis, const std::string& spec);

}  // namespace

const char* SweepParameterName(SweepParameter parameter) {
  switch (parameter) {
    case SweepParameter::kA:
      return "A";
    case SweepParameter::kc:
      return "c";
    case SweepParameter::kphi0:
      return "phi0";
    case SweepParameter::kT0:
      return "T0";
    case SweepParameter::ke:
      return "e";
    case SweepParameter::kmargin:
      return "margin";
    case SweepParameter::kalpha:
      return "alpha";
  }
  return "unknown";
}

double GridAxis::Value(std::int64_t i) const {
  if (n <= 1 || i <= 0) return lo;
  if (i >= n - 1) return hi;
  // Weighted mean of the ends: symmetric in lo and hi, and round decimals stay round
  // (0.05:0.95:19 gives 0.1, not 0.09999999999999999).
  const double m = static_cast<double>(n - 1);
  return (lo * (m - static_cast<double>(i)) + hi * static_cast<double>(i)) / m;
}

std::string GridAxis::ToString() const {
  return fmt::format("{}={}:{}:{}", SweepParameterName(parameter), lo, hi, n);
}

void GridAxis::Validate() const { CheckAxis(*this, ToString()); }

namespace {

// The rules of GridAxis::Validate, with `spec` quoted in the message.
void CheckAxis(const GridAxis& axis, const std::string& spec) {
  const std::int64_t n = axis.n;
  const double lo = axis.lo, hi = axis.hi;
  if (n < 1) Fail(spec, fmt::format("n = {}: expected n >= 1 points", n));
  if (n > kMaxPoints) Fail(spec, fmt::format("n = {}: expected n <= 2^53", n));
  if (!std::isfinite(lo) || !std::isfinite(hi)) {
    Fail(spec, "expected finite bounds lo and hi (not NaN or infinite)");
  }
  const double a = n == 1 ? lo : std::min(lo, hi), b = n == 1 ? lo : std::max(lo, hi);
  switch (axis.parameter) {
    case SweepParameter::kA:
      if (a < 0.0) Fail(spec, "expected amplitudes A >= 0");
      break;
    case SweepParameter::kT0:
      if (a <= 0.0) Fail(spec, "expected friction bounds T0 > 0");
      break;
    case SweepParameter::ke:
      if (a < 0.0 || b > 1.0) Fail(spec, "expected restitutions 0 <= e <= 1");
      break;
    case SweepParameter::kmargin:
      if (a < 0.0 || b >= 0.5) Fail(spec, "expected margins 0 <= margin < 0.5");
      break;
    case SweepParameter::kalpha:
      if (a <= 0.0 || b >= 1.0) Fail(spec, "expected mass ratios 0 < alpha < 1");
      break;
    case SweepParameter::kc:
    case SweepParameter::kphi0:
      break;
  }
}

}  // namespace

GridAxis ParseGridAxis(const std::string& spec) {
  const auto eq = spec.find('=');
  if (eq == std::string::npos) Fail(spec, "expected name=lo:hi:n");
  const std::string name = spec.substr(0, eq);
  GridAxis axis;
  bool known = false;
  for (SweepParameter p : kAllParameters) {
    if (name == SweepParameterName(p)) {
      axis.parameter = p;
      known = true;
    }
  }
  if (!known) {
    Fail(spec, fmt::format("unknown parameter '{}': expected one of A, c, phi0, T0, e, margin, "
                           "alpha",
                           name));
  }
  const std::string rest = spec.substr(eq + 1);
  const auto c1 = rest.find(':');
  const auto c2 = c1 == std::string::npos ? c1 : rest.find(':', c1 + 1);
  if (c2 == std::string::npos || rest.find(':', c2 + 1) != std::string::npos) {
    Fail(spec, "expected name=lo:hi:n (three fields separated by ':')");
  }
  const std::string lo = rest.substr(0, c1), hi = rest.substr(c1 + 1, c2 - c1 - 1),
                    n = rest.substr(c2 + 1);
  if (!ParseBound(lo, axis.lo)) Fail(spec, fmt::format("lo = '{}' is not a number", lo));
  if (!ParseBound(hi, axis.hi)) Fail(spec, fmt::format("hi = '{}' is not a number", hi));
  char* end = nullptr;
  errno = 0;
  const long long count = n.empty() ? 0 : std::strtoll(n.c_str(), &end, 10);
  if (n.empty() || end != n.c_str() + n.size() || errno == ERANGE) {
    Fail(spec, fmt::format("n = '{}' is not an integer number of points", n));
  }
  axis.n = count;
  if (!std::isfinite(axis.lo) || !std::isfinite(axis.hi)) {
    Fail(spec, "expected finite bounds lo and hi (not NaN or infinite)");
  }
  if (axis.n < 1) Fail(spec, fmt::format("n = {}: expected n >= 1 points", axis.n));
  CheckAxis(axis, spec);
  return axis;
}

void Grid::Validate() const {
  if (axes.empty() || axes.size() > 2) {
    throw std::invalid_argument(fmt::format(
        "--grid given {} times is invalid: expected 1 or 2 grids (name=lo:hi:n)", axes.size()));
  }
  for (const GridAxis& axis : axes) axis.Validate();
  if (axes.size() == 2) {
    if (axes[0].parameter == axes[1].parameter) {
      throw std::invalid_argument(fmt::format(
          "--grid {} is invalid: parameter {} already has a grid (--grid {}): "
          "expected two different parameters",
          axes[1].ToString(), SweepParameterName(axes[1].parameter), axes[0].ToString()));
    }
    if (Has(SweepParameter::kalpha) && Has(SweepParameter::kphi0)) {
      throw std::invalid_argument(
          "--grid alpha together with --grid phi0 is invalid: a robot's mass ratio alpha "
          "determines its impact phases phi0: expected a grid over only one of them");
    }
    if (axes[0].n > kMaxPoints / axes[1].n) {
      throw std::invalid_argument(fmt::format(
          "--grid {} --grid {} is invalid: {} x {} points: expected at most 2^53 points",
          axes[0].ToString(), axes[1].ToString(), axes[0].n, axes[1].n));
    }
  }
}

std::int64_t Grid::size() const {
  std::int64_t n = 1;
  for (const GridAxis& axis : axes) n *= axis.n;
  return axes.empty() ? 0 : n;
}

bool Grid::Has(SweepParameter parameter) const {
  for (const GridAxis& axis : axes) {
    if (axis.parameter == parameter) return true;
  }
  return false;
}

double Grid::Value(std::int64_t point, std::size_t axis) const {
  if (axes.size() == 1) return axes[0].Value(point);
  return axis == 0 ? axes[0].Value(point / axes[1].n) : axes[1].Value(point % axes[1].n);
}

}  // namespace capsubot
