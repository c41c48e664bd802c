#pragma once
// The table of the robot's settings of the design job (design_config.hpp): each setting's kind,
// how its text is read and written, and how it sets and reads the DesignInput.

#include <string>
#include <utility>
#include <vector>

#include "capsubot/design/design.hpp"

namespace capsubot::detail {

// kBound: a number, or "inf" for no bound.
enum class SettingKind { kNumber, kBound, kInteger, kList, kRange };

// A parsed value; the field used depends on the setting's kind.
struct SettingValue {
  double number = 0.0;        // kNumber, kBound, kInteger
  std::vector<double> list;   // kList
  double lo = 0.0, hi = 0.0;  // kRange
};

struct RobotSetting {
  const char* name;  // the key in the config file; each front end writes it its own way
  SettingKind kind;
  const char* help;
  void (*set)(DesignInput&, const SettingValue&);
  // The value of the input (defaults, file and front end resolved); false when it has none
  // (an alternative is used, or a default that depends on another setting).
  bool (*get)(const DesignInput&, SettingValue&);
};

// Every setting once, in the order of a provenance. Several settings write the same field
// where they are alternatives (frequency or frequency-range, amplitude or Fourier).
const std::vector<RobotSetting>& RobotSettings();

// The index of setting `name` in RobotSettings(); -1 when there is none.
int FindRobotSetting(const std::string& name);

// The names of every setting, comma-separated.
std::string RobotSettingNames();

// Settings that must be given (by the front end or the file): one of each group.
const std::vector<std::vector<const char*>>& RequiredRobotSettings();

// Pairs that exclude each other within one source (across sources the later one wins).
const std::vector<std::pair<const char*, const char*>>& ExclusiveRobotSettings();

// The rule of a value of `kind` as text ("a number", "MIN:MAX with MIN < MAX").
const char* TextRule(SettingKind kind);

// "who = text[where] is invalid: expected rule"; `where` says which file, if any.
[[noreturn]] void BadSetting(const std::string& who, const std::string& text, const char* rule,
                             const std::string& where = "");

// The value of a range once both ends are read: MIN < MAX (an empty or inverted range is an
// error; NaN too).
SettingValue RangeValue(const std::string& who, const std::string& text, double lo, double hi,
                        const std::string& where);

// A setting's value from its text (given to a front end, or a string in the file), its
// messages naming it `who`.
SettingValue FromText(const RobotSetting& s, const std::string& who, const std::string& text,
                      const std::string& where = "");

// A value as text, read back by FromText to the same value.
std::string ToText(const RobotSetting& s, const SettingValue& v);

}  // namespace capsubot::detail
