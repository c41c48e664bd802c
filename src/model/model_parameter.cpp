// The parameters a study varies: one table of names and domains, and the setter of a robot.

#include "capsubot/model/model_parameter.hpp"

#include <fmt/format.h>

#include <charconv>
#include <limits>
#include <stdexcept>

#include "capsubot/numerics/not_computed.hpp"

namespace capsubot {
namespace {

constexpr double kInf = std::numeric_limits<double>::infinity();

// Every parameter: its name (with a harmonic, the prefix of a1, a2, ...) and its domain. A new
// parameter is one row here, one enumerator, and for a robot parameter one entry of
// kRobotParameters and one case of SetParameter.
struct ParameterRow {
  ModelParameter parameter;
  const char* name;
  ParameterDomain domain;
};

static_assert(kMaxPhase == 1e6, "the phi0 rule below names kMaxPhase");
constexpr ParameterRow kParameters[] = {
    {ModelParameter::kA, "A", {0.0, false, kInf, false, "amplitudes A >= 0"}},
    {ModelParameter::kMean, "c", {-kInf, false, kInf, false, ""}},
    {ModelParameter::kPhi0,
     "phi0",
     {-kMaxPhase, false, kMaxPhase, false, "phases |phi0| <= 1e6 rad (phases are in radians)"}},
    {ModelParameter::kT0, "T0", {0.0, true, kInf, false, "friction bounds T0 > 0"}},
    {ModelParameter::kRestitution, "e", {0.0, false, 1.0, false, "restitutions 0 <= e <= 1"}},
    {ModelParameter::kMargin, "margin", {0.0, false, 0.5, true, "margins 0 <= margin < 0.5"}},
    {ModelParameter::kAlpha, "alpha", {0.0, true, 1.0, true, "mass ratios 0 < alpha < 1"}},
    {ModelParameter::kCos, "a", {-kInf, false, kInf, false, ""}},
    {ModelParameter::kSin, "b", {-kInf, false, kInf, false, ""}},
    {ModelParameter::kBound, "bound", {0.0, true, kInf, false, "force bounds bound > 0"}},
    // Infinity: no stability requirement (the optimisers' default).
    {ModelParameter::kRhoMax,
     "rho_max",
     {0.0, true, kInf, false, "spectral radius bounds rho_max > 0 (inf: no bound)", true}},
    {ModelParameter::kMarginStroke,
     "margin_stroke",
     {0.0, false, 0.5, true, "stroke margins 0 <= margin_stroke < 0.5"}},
    {ModelParameter::kStickMargin,
     "stick_margin",
     {0.0, false, 1.0, true, "stick margins 0 <= stick_margin < 1"}},
};

// The robot parameters, in the order messages list them.
constexpr ModelParameter kRobotParameters[] = {ModelParameter::kA,           ModelParameter::kMean,
                                               ModelParameter::kAlpha,       ModelParameter::kT0,
                                               ModelParameter::kRestitution, ModelParameter::kPhi0,
                                               ModelParameter::kCos,         ModelParameter::kSin};

const ParameterRow& RowOf(ModelParameter parameter) {
  for (const ParameterRow& r : kParameters) {
    if (r.parameter == parameter) return r;
  }
  return kParameters[0];  // unreachable: every enumerator has a row
}

[[noreturn]] void NotARobotParameter(const std::string& name) {
  std::string names;
  for (ModelParameter p : kRobotParameters) {
    if (!IsFourierCoefficient(p)) names += ModelParameterName(p) + ", ";
  }
  throw std::invalid_argument(fmt::format(
      "parameter = {} is invalid: expected one of {}or a Fourier coefficient a1..a{}, b1..b{}",
      name, names, kMaxHarmonics, kMaxHarmonics));
}

}  // namespace

std::string ModelParameterName(ModelParameter parameter, int harmonic) {
  const ParameterRow& r = RowOf(parameter);
  return IsFourierCoefficient(parameter) && harmonic > 0 ? fmt::format("{}{}", r.name, harmonic)
                                                         : std::string(r.name);
}

std::string ModelParameterNames() {
  std::string names;
  for (const ParameterRow& r : kParameters) {
    if (!names.empty()) names += ", ";
    names += IsFourierCoefficient(r.parameter) ? fmt::format("{0}1..{0}{1}", r.name, kMaxHarmonics)
                                               : r.name;
  }
  return names;
}

bool ParseModelParameter(const std::string& name, ModelParameter& parameter, int& harmonic) {
  for (const ParameterRow& r : kParameters) {
    if (!IsFourierCoefficient(r.parameter)) {
      if (name != r.name) continue;
      parameter = r.parameter;
      harmonic = 0;
      return true;
    }
    // a1 .. a16, b1 .. b16: the prefix, then k without a leading zero.
    const std::string prefix = r.name;
    if (name.size() <= prefix.size() || name.compare(0, prefix.size(), prefix) != 0) continue;
    const char* first = name.data() + prefix.size();
    const char* last = name.data() + name.size();
    int k = 0;
    const std::from_chars_result res = std::from_chars(first, last, k);
    if (res.ec != std::errc() || res.ptr != last || *first == '0' || k < 1 || k > kMaxHarmonics) {
      continue;
    }
    parameter = r.parameter;
    harmonic = k;
    return true;
  }
  return false;
}

const ParameterDomain& ModelParameterDomain(ModelParameter parameter) {
  return RowOf(parameter).domain;
}

bool IsFourierCoefficient(ModelParameter parameter) {
  return parameter == ModelParameter::kCos || parameter == ModelParameter::kSin;
}

bool IsRobotParameter(ModelParameter parameter) {
  for (ModelParameter p : kRobotParameters) {
    if (p == parameter) return true;
  }
  return false;
}

ModelParameter ParseRobotParameter(const std::string& name, int* harmonic) {
  ModelParameter parameter = ModelParameter::kA;
  int k = 0;
  if (!ParseModelParameter(name, parameter, k) || !IsRobotParameter(parameter)) {
    NotARobotParameter(name);
  }
  if (harmonic != nullptr) *harmonic = k;
  return parameter;
}

void CheckRobotParameter(const Forcing& forcing, ModelParameter parameter, int harmonic) {
  if (!IsRobotParameter(parameter)) NotARobotParameter(ModelParameterName(parameter, harmonic));
  if (forcing.pulse() && (parameter == ModelParameter::kA || IsFourierCoefficient(parameter))) {
    throw std::invalid_argument(fmt::format(
        "parameter = {} is invalid for a pulse force: expected c (every level moved), phi0, "
        "T0, e or alpha",
        ModelParameterName(parameter, harmonic)));
  }
  if (parameter == ModelParameter::kA && !forcing.harmonic()) {
    throw std::invalid_argument(
        "parameter = A is invalid for a Fourier force: expected the harmonic family");
  }
  if (IsFourierCoefficient(parameter) && (harmonic < 1 || harmonic > forcing.harmonics())) {
    throw std::invalid_argument(fmt::format(
        "parameter = {} is invalid for this force: expected a_k or b_k with 1 <= k <= K = {}, "
        "its harmonics",
        ModelParameterName(parameter, harmonic), forcing.harmonics()));
  }
}

void SetParameter(RobotModel& robot, ModelParameter parameter, int harmonic, double value) {
  CheckRobotParameter(robot.forcing, parameter, harmonic);
  Forcing& f = robot.forcing;
  switch (parameter) {
    case ModelParameter::kA:
      f = Forcing::Harmonic(value, f.mean(), f.phi0());
      break;
    case ModelParameter::kMean:
      f = f.WithMean(value);
      break;
    case ModelParameter::kCos:
      f = f.WithCosine(harmonic, value);
      break;
    case ModelParameter::kSin:
      f = f.WithSine(harmonic, value);
      break;
    case ModelParameter::kPhi0:
      f = f.WithPhase(value);
      break;
    case ModelParameter::kT0:
      robot.params.T0 = value;
      break;
    case ModelParameter::kRestitution:
      robot.params.e = value;
      break;
    case ModelParameter::kAlpha:
      robot.alpha = value;
      break;
    default:  // a requirement: refused by CheckRobotParameter
      break;
  }
}

double ParameterValue(const RobotModel& robot, ModelParameter parameter, int harmonic) {
  CheckRobotParameter(robot.forcing, parameter, harmonic);
  const Forcing& f = robot.forcing;
  switch (parameter) {
    case ModelParameter::kA:
      return f.amplitude();
    case ModelParameter::kMean:
      return f.mean();
    case ModelParameter::kCos:
      return f.a(harmonic);
    case ModelParameter::kSin:
      return f.b(harmonic);
    case ModelParameter::kPhi0:
      return f.phi0();
    case ModelParameter::kT0:
      return robot.params.T0;
    case ModelParameter::kRestitution:
      return robot.params.e;
    case ModelParameter::kAlpha:
      return robot.alpha;
    default:  // a requirement: refused by CheckRobotParameter
      break;
  }
  return kNaN;
}

}  // namespace capsubot
