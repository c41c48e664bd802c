#include "capsubot/sweep/grid.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <charconv>
#include <cmath>
#include <limits>
#include <stdexcept>

#include "capsubot/io/io.hpp"
#include "capsubot/model/forcing.hpp"
#include "capsubot/numerics/grid_value.hpp"

namespace capsubot {
namespace {

[[noreturn]] void Fail(const std::string& spec, const std::string& why) {
  throw std::invalid_argument(fmt::format("grid {} is invalid: {}", spec, why));
}

// A decimal number (optional sign, no spaces, no hexadecimal), or a multiple of pi in the
// syntax of the phase options (pi, -pi/2, 2*pi: ParsePhase).
bool ParseNumber(const std::string& text, double& value) {
  if (text.find("pi") != std::string::npos) {
    try {
      value = ParsePhase(text, "grid value");
      return true;
    } catch (const std::invalid_argument&) {
      return false;
    }
  }
  const char* first = text.data();
  const char* last = first + text.size();
  if (first != last && *first == '+' && last - first > 1 && first[1] != '-') ++first;
  const std::from_chars_result r = std::from_chars(first, last, value);
  // Infinity only as "inf", the way the CSV writes it (not "Infinity", "-inf", "INF").
  if (std::isinf(value) && text != "inf") return false;
  return first != last && r.ec == std::errc() && r.ptr == last;
}

std::vector<std::string> Split(const std::string& text, char separator) {
  std::vector<std::string> parts;
  std::size_t start = 0;
  for (;;) {
    const std::size_t end = std::min(text.find(separator, start), text.size());
    parts.push_back(text.substr(start, end - start));
    if (end == text.size()) return parts;
    start = end + 1;
  }
}

}  // namespace

std::int64_t GridValues::size() const {
  return spacing == GridSpacing::kList ? static_cast<std::int64_t>(values.size()) : n;
}

double GridValues::Value(std::int64_t i) const {
  if (spacing == GridSpacing::kList) return values[static_cast<std::size_t>(i)];
  if (spacing == GridSpacing::kLinear) return GridValue(lo, hi, n, i);
  if (n <= 1 || i <= 0) return lo;
  if (i >= n - 1) return hi;
  // Equal ratios, through decimal logarithms: decades stay exact (1e-3:1:4:log).
  const double m = static_cast<double>(n - 1), t = static_cast<double>(i);
  const double value = std::pow(10.0, (std::log10(lo) * (m - t) + std::log10(hi) * t) / m);
  // Rounding must not leave [lo, hi] (e = 1 at a bound of the domain).
  return std::clamp(value, std::min(lo, hi), std::max(lo, hi));
}

double GridValues::Min() const {
  if (spacing == GridSpacing::kList) return *std::min_element(values.begin(), values.end());
  return n == 1 ? lo : std::min(lo, hi);
}

double GridValues::Max() const {
  if (spacing == GridSpacing::kList) return *std::max_element(values.begin(), values.end());
  return n == 1 ? lo : std::max(lo, hi);
}

std::string GridValues::ValuesText() const {
  if (spacing == GridSpacing::kList) return fmt::format("{}", fmt::join(values, ","));
  return fmt::format("{}:{}:{}{}", lo, hi, n, spacing == GridSpacing::kLog ? ":log" : "");
}

void GridAxis::Validate() const {
  const std::string spec = ToString();
  if (IsFourierCoefficient(parameter) && (harmonic < 1 || harmonic > kMaxHarmonics)) {
    Fail(spec, fmt::format("harmonic k = {}: expected 1 <= k <= {}", harmonic, kMaxHarmonics));
  }
  Check(spec, ModelParameterDomain(parameter));
}

void GridValues::Check(const std::string& spec, const ParameterDomain& domain) const {
  if (spacing == GridSpacing::kList) {
    if (values.empty()) Fail(spec, "expected at least one value");
    if (size() > kMaxGridPoints) {
      Fail(spec, fmt::format("{} values: expected at most {}", size(), kMaxGridPoints));
    }
    for (double v : values) {
      if (std::isnan(v) || (std::isinf(v) && !(domain.infinite && v > 0.0))) {
        Fail(spec, domain.infinite ? "expected finite values or inf (not NaN or -inf)"
                                   : "expected finite values (not NaN or infinite)");
      }
    }
  } else {
    if (n < 1) Fail(spec, fmt::format("n = {}: expected n >= 1 points", n));
    if (n > kMaxGridPoints) {
      Fail(spec, fmt::format("n = {}: expected n <= {} points", n, kMaxGridPoints));
    }
    if (!std::isfinite(lo) || !std::isfinite(hi)) {
      Fail(spec, "expected finite bounds lo and hi (not NaN or infinite)");
    }
    const double m = static_cast<double>(n - 1);
    if (spacing == GridSpacing::kLinear && (!std::isfinite(lo * m) || !std::isfinite(hi * m))) {
      Fail(spec, fmt::format("the bounds are too large for {} points: expected |lo| and |hi| "
                             "<= {} (the values lo (n-1-i)/(n-1) + hi i/(n-1) overflow)",
                             n, std::numeric_limits<double>::max() / m));
    }
    if (spacing == GridSpacing::kLog && !(lo > 0.0 && hi > 0.0)) {
      Fail(spec, "expected lo > 0 and hi > 0 for a log grid (geometric spacing)");
    }
  }
  const double a = Min(), b = Max();
  const ParameterDomain& d = domain;
  if ((d.min_open ? a <= d.min : a < d.min) || (d.max_open ? b >= d.max : b > d.max)) {
    Fail(spec, fmt::format("expected {}", d.rule));
  }
}

std::string GridSpecName(const std::string& spec) {
  const auto eq = spec.find('=');
  if (eq == std::string::npos)
    Fail(spec, "expected name=lo:hi:n, name=lo:hi:n:log or name=v1,v2,...");
  return spec.substr(0, eq);
}

GridValues ParseGridValues(const std::string& spec, const ParameterDomain& domain) {
  GridValues axis;
  const std::string rest = spec.substr(GridSpecName(spec).size() + 1);
  if (rest.find(':') == std::string::npos) {  // a list (one value is a list of one)
    axis.spacing = GridSpacing::kList;
    const std::vector<std::string> items = Split(rest, ',');
    if (static_cast<std::int64_t>(items.size()) > kMaxGridPoints) {
      Fail(spec, fmt::format("{} values: expected at most {}", items.size(), kMaxGridPoints));
    }
    axis.values.resize(items.size());
    for (std::size_t i = 0; i < items.size(); ++i) {
      if (!ParseNumber(items[i], axis.values[i])) {
        Fail(spec, fmt::format("value {} = '{}' is not a number (decimal, within the range of a "
                               "double)",
                               i + 1, items[i]));
      }
    }
  } else {
    const std::vector<std::string> fields = Split(rest, ':');
    const bool log = fields.size() == 4 && fields[3] == "log";
    if (fields.size() != 3 && !log) {
      Fail(spec, "expected name=lo:hi:n or name=lo:hi:n:log (fields separated by ':')");
    }
    axis.spacing = log ? GridSpacing::kLog : GridSpacing::kLinear;
    if (!ParseNumber(fields[0], axis.lo)) {
      Fail(spec, fmt::format("lo = '{}' is not a number", fields[0]));
    }
    if (!ParseNumber(fields[1], axis.hi)) {
      Fail(spec, fmt::format("hi = '{}' is not a number", fields[1]));
    }
    const std::string& n = fields[2];
    const std::from_chars_result r = std::from_chars(n.data(), n.data() + n.size(), axis.n);
    if (n.empty() || r.ec != std::errc() || r.ptr != n.data() + n.size()) {
      Fail(spec,
           fmt::format("n = '{}' is not an integer number of points (1 to {})", n, kMaxGridPoints));
    }
  }
  axis.Check(spec, domain);  // quotes the spec as written
  return axis;
}

GridAxis ParseGridAxis(const std::string& spec) {
  GridAxis axis;
  const std::string name = GridSpecName(spec);
  if (!ParseModelParameter(name, axis.parameter, axis.harmonic)) {
    Fail(spec,
         fmt::format("unknown parameter '{}': expected one of {}", name, ModelParameterNames()));
  }
  static_cast<GridValues&>(axis) = ParseGridValues(spec, ModelParameterDomain(axis.parameter));
  return axis;
}

void Grid::Validate() const {
  if (axes.empty()) {
    throw std::invalid_argument(
        "grid is missing: expected at least one axis (name=lo:hi:n, name=lo:hi:n:log or "
        "name=v1,v2,...)");
  }
  for (std::size_t i = 0; i < axes.size(); ++i) {
    axes[i].Validate();
    for (std::size_t j = 0; j < i; ++j) {
      if (axes[j].parameter == axes[i].parameter && axes[j].harmonic == axes[i].harmonic) {
        throw std::invalid_argument(
            fmt::format("grid {} is invalid: parameter {} already has a grid ({}): expected each "
                        "parameter at most once",
                        axes[i].ToString(), axes[i].name(), axes[j].ToString()));
      }
    }
  }
  if (Has(ModelParameter::kAlpha) && Has(ModelParameter::kPhi0)) {
    throw std::invalid_argument(
        "grid alpha together with grid phi0 is invalid: a robot's mass ratio alpha "
        "determines its impact phases phi0: expected a grid over only one of them");
  }
  if (Has(ModelParameter::kA) && Has(ModelParameter::kSin, 1)) {
    throw std::invalid_argument(
        "grid A together with grid b1 is invalid: A is the sine coefficient b1 of the "
        "harmonic force: expected a grid over only one of them");
  }
  std::vector<std::int64_t> sizes;
  std::string specs;
  for (const GridAxis& a : axes) {
    sizes.push_back(a.size());
    specs += (specs.empty() ? "" : " ") + a.ToString();
  }
  CheckGridPoints(sizes, specs);
}

void CheckGridPoints(const std::vector<std::int64_t>& sizes, const std::string& specs) {
  std::int64_t points = 1;
  for (const std::int64_t size : sizes) {
    if (points > kMaxGridPoints / size) {
      throw std::invalid_argument(
          fmt::format("grid {} is invalid: more than {} points: expected at most {} points", specs,
                      kMaxGridPoints, kMaxGridPoints));
    }
    points *= size;
  }
}

std::int64_t Grid::size() const {
  std::int64_t n = 1;
  for (const GridAxis& axis : axes) n *= axis.size();
  return axes.empty() ? 0 : n;
}

bool Grid::Has(ModelParameter parameter, int harmonic) const {
  for (const GridAxis& axis : axes) {
    if (axis.parameter == parameter && (harmonic == 0 || axis.harmonic == harmonic)) return true;
  }
  return false;
}

double Grid::Value(std::int64_t point, std::size_t axis) const {
  return RowMajorValue(axes, point, axis);
}

}  // namespace capsubot
