#include "robot_settings.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "capsubot/io/io.hpp"

namespace capsubot::detail {
namespace {

// Getters of RobotSetting::get.
template <double DesignInput::*field>
bool GetNumber(const DesignInput& in, SettingValue& v) {
  v.number = in.*field;
  return !std::isnan(v.number);
}

bool GetRange(double lo, double hi, SettingValue& v) {
  v.lo = lo;
  v.hi = hi;
  return !std::isnan(lo) && !std::isnan(hi) && lo != hi;
}

const RobotSetting kSettings[] = {
    {"m1", SettingKind::kNumber, "shell mass m1 [kg], > 0",
     [](DesignInput& in, const SettingValue& v) { in.m1 = v.number; }, GetNumber<&DesignInput::m1>},
    {"L", SettingKind::kNumber, "free gap L of the inner body between the walls [m], > 0",
     [](DesignInput& in, const SettingValue& v) { in.L = v.number; }, GetNumber<&DesignInput::L>},
    {"mu", SettingKind::kNumber, "friction coefficient mu of the shell on the floor, > 0",
     [](DesignInput& in, const SettingValue& v) { in.mu = v.number; }, GetNumber<&DesignInput::mu>},
    {"g", SettingKind::kNumber, "gravity g [m/s^2], > 0 (default 9.81)",
     [](DesignInput& in, const SettingValue& v) { in.g = v.number; }, GetNumber<&DesignInput::g>},
    {"e", SettingKind::kNumber, "coefficient of restitution e of the impacts, 0 <= e <= 1",
     [](DesignInput& in, const SettingValue& v) { in.e = v.number; }, GetNumber<&DesignInput::e>},
    {"force-amplitude", SettingKind::kNumber,
     "amplitude A_N [N] of the motor force F_N = A_N sin(omega t + phase) + c_N, >= 0",
     [](DesignInput& in, const SettingValue& v) {
       in.force.amplitude = v.number;
       in.force.cos.clear();
       in.force.sin.clear();
     },
     [](const DesignInput& in, SettingValue& v) {
       v.number = in.force.amplitude;
       return !in.force.fourier() && !std::isnan(v.number);
     }},
    {"force-bias", SettingKind::kNumber, "mean c_N [N] of the motor force, >= 0",
     [](DesignInput& in, const SettingValue& v) { in.force.bias = v.number; },
     [](const DesignInput& in, SettingValue& v) {
       v.number = in.force.bias;
       return !std::isnan(v.number);
     }},
    {"force-cos", SettingKind::kList,
     "Fourier motor force instead of the amplitude: cosine coefficients [N] of "
     "F_N = c_N + sum_k (a_k cos k s + b_k sin k s), s = omega t + phase (as many as "
     "force-sin; default 0)",
     [](DesignInput& in, const SettingValue& v) {
       in.force.cos = v.list;
       in.force.amplitude = kNaN;
     },
     [](const DesignInput& in, SettingValue& v) {
       v.list = in.force.cos;
       return !v.list.empty();
     }},
    {"force-sin", SettingKind::kList, "Fourier motor force: sine coefficients b_1,...,b_K [N]",
     [](DesignInput& in, const SettingValue& v) {
       in.force.sin = v.list;
       in.force.amplitude = kNaN;
     },
     [](const DesignInput& in, SettingValue& v) {
       v.list = in.force.sin;
       return !v.list.empty();
     }},
    {"frequency", SettingKind::kNumber, "motor frequency f [Hz], > 0",
     [](DesignInput& in, const SettingValue& v) { in.frequency_min = in.frequency_max = v.number; },
     [](const DesignInput& in, SettingValue& v) {
       v.number = in.frequency_min;
       return !std::isnan(v.number) && in.frequency_min == in.frequency_max;
     }},
    {"frequency-range", SettingKind::kRange,
     "search the motor frequency too, over FMIN:FMAX [Hz] (instead of frequency)",
     [](DesignInput& in, const SettingValue& v) {
       in.frequency_min = v.lo;
       in.frequency_max = v.hi;
     },
     [](const DesignInput& in, SettingValue& v) {
       return GetRange(in.frequency_min, in.frequency_max, v);
     }},
    {"m2-range", SettingKind::kRange,
     "inner masses searched, M2MIN:M2MAX [kg] (default 0.01 m1:10 m1)",
     [](DesignInput& in, const SettingValue& v) {
       in.m2_min = v.lo;
       in.m2_max = v.hi;
     },
     [](const DesignInput& in, SettingValue& v) { return GetRange(in.m2_min, in.m2_max, v); }},
    {"margin", SettingKind::kNumber,
     "clearance d from both walls [units of L], 0 <= d < 0.5 (default 0)",
     [](DesignInput& in, const SettingValue& v) { in.margin = v.number; },
     GetNumber<&DesignInput::margin>},
    {"margin-stroke", SettingKind::kNumber,
     "clearance d_s from both walls [units of the stroke 1 - x_min], >= 0 (default 0.02)",
     [](DesignInput& in, const SettingValue& v) { in.margin_stroke = v.number; },
     GetNumber<&DesignInput::margin_stroke>},
    {"stick-margin", SettingKind::kNumber,
     "stick margin s: |F| <= (1-s) T0 while the shell rests, 0 <= s < 1 (default 0.02)",
     [](DesignInput& in, const SettingValue& v) { in.stick_margin = v.number; },
     GetNumber<&DesignInput::stick_margin>},
    {"rho-max", SettingKind::kBound,
     "largest admissible multiplier modulus of the gait, > 0; inf: no stability requirement "
     "(default 0.9)",
     [](DesignInput& in, const SettingValue& v) { in.rho_max = v.number; },
     GetNumber<&DesignInput::rho_max>},
    {"scan-points", SettingKind::kInteger,
     "log-spaced samples of each searched variable before the refinement, >= 3 (default 64)",
     [](DesignInput& in, const SettingValue& v) { in.scan_points = static_cast<int>(v.number); },
     [](const DesignInput& in, SettingValue& v) {
       v.number = in.scan_points;
       return true;
     }},
};

// An element of a list or range: a number of capsubot::ParseNumber; false if it is not one.
bool ToNumber(const std::string& text, double& out) {
  try {
    out = ParseNumber(text, "element");
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

}  // namespace

const std::vector<RobotSetting>& RobotSettings() {
  static const std::vector<RobotSetting> settings(std::begin(kSettings), std::end(kSettings));
  return settings;
}

const std::vector<std::vector<const char*>>& RequiredRobotSettings() {
  static const std::vector<std::vector<const char*>> required = {{"m1"},
                                                                 {"L"},
                                                                 {"mu"},
                                                                 {"e"},
                                                                 {"force-bias"},
                                                                 {"force-amplitude", "force-sin"},
                                                                 {"frequency", "frequency-range"}};
  return required;
}

const std::vector<std::pair<const char*, const char*>>& ExclusiveRobotSettings() {
  static const std::vector<std::pair<const char*, const char*>> exclusive = {
      {"frequency", "frequency-range"},
      {"force-amplitude", "force-sin"},
      {"force-amplitude", "force-cos"}};
  return exclusive;
}

void BadSetting(const std::string& who, const std::string& text, const char* rule,
                const std::string& where) {
  throw std::invalid_argument(
      fmt::format("{} = {}{} is invalid: expected {}", who, text, where, rule));
}

const char* TextRule(SettingKind kind) {
  switch (kind) {
    case SettingKind::kNumber:
      return "a number";
    case SettingKind::kBound:
      return "a number or inf";
    case SettingKind::kInteger:
      return "an integer";
    case SettingKind::kList:
      return "comma-separated numbers";
    case SettingKind::kRange:
      return "MIN:MAX with MIN < MAX";
  }
  return "a value";
}

SettingValue RangeValue(const std::string& who, const std::string& text, double lo, double hi,
                        const std::string& where) {
  if (!(lo < hi)) BadSetting(who, text, "MIN:MAX with MIN < MAX", where);
  SettingValue v;
  v.lo = lo;
  v.hi = hi;
  return v;
}

SettingValue FromText(const RobotSetting& s, const std::string& who, const std::string& text,
                      const std::string& where) {
  SettingValue v;
  switch (s.kind) {
    case SettingKind::kBound:
      v.number = text == "inf" ? HUGE_VAL : ParseNumber(text, who);
      return v;
    case SettingKind::kNumber:
      v.number = ParseNumber(text, who);
      return v;
    case SettingKind::kInteger:
      v.number = static_cast<double>(ParseInteger(text, who, std::numeric_limits<int>::min(),
                                                  std::numeric_limits<int>::max()));
      return v;
    case SettingKind::kList:
      for (const std::string& element : SplitText(text, ',')) {
        double x = 0.0;
        if (!ToNumber(element, x)) BadSetting(who, text, TextRule(s.kind), where);
        v.list.push_back(x);
      }
      return v;
    case SettingKind::kRange: {
      const std::size_t colon = text.find(':');
      double lo = 0.0, hi = 0.0;
      if (colon == std::string::npos || !ToNumber(text.substr(0, colon), lo) ||
          !ToNumber(text.substr(colon + 1), hi)) {
        BadSetting(who, text, TextRule(s.kind), where);
      }
      return RangeValue(who, text, lo, hi, where);
    }
  }
  return v;
}

std::string ToText(const RobotSetting& s, const SettingValue& v) {
  switch (s.kind) {
    case SettingKind::kBound:
      return std::isinf(v.number) ? "inf" : FormatNumber(v.number);
    case SettingKind::kInteger:
      return fmt::format("{}", static_cast<long long>(v.number));
    case SettingKind::kList: {
      std::vector<std::string> items;
      for (double x : v.list) items.push_back(FormatNumber(x));
      return fmt::format("{}", fmt::join(items, ","));
    }
    case SettingKind::kRange:
      return FormatNumber(v.lo) + ":" + FormatNumber(v.hi);
    case SettingKind::kNumber:
      break;
  }
  return FormatNumber(v.number);
}

int FindRobotSetting(const std::string& name) {
  const std::vector<RobotSetting>& settings = RobotSettings();
  for (std::size_t i = 0; i < settings.size(); ++i) {
    if (name == settings[i].name) return static_cast<int>(i);
  }
  return -1;
}

std::string RobotSettingNames() {
  std::vector<std::string> names;
  for (const RobotSetting& s : RobotSettings()) names.emplace_back(s.name);
  return fmt::format("{}", fmt::join(names, ", "));
}

}  // namespace capsubot::detail
