#include "design_config.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>
#include <toml++/toml.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <set>
#include <sstream>
#include <stdexcept>

#include "capsubot/io/io.hpp"
#include "cli.hpp"

namespace capsubot::app {
namespace {

// kBound: a number, or "inf" for no bound.
enum class Kind { kNumber, kBound, kInteger, kList, kRange };

// A parsed value; the field used depends on the setting's kind.
struct Value {
  double number = 0.0;        // kNumber, kInteger
  std::vector<double> list;   // kList
  double lo = 0.0, hi = 0.0;  // kRange
};

struct Setting {
  const char* name;  // the flag without "--" and the key in the config file
  Kind kind;
  const char* help;
  void (*set)(DesignInput&, const Value&);
  /// The value of the input (defaults, file and flags resolved); false when it has none
  /// (an alternative is used, or a default that depends on another setting).
  bool (*get)(const DesignInput&, Value&);
};

// Getters of Setting::get.
template <double DesignInput::*field>
bool GetNumber(const DesignInput& in, Value& v) {
  v.number = in.*field;
  return !std::isnan(v.number);
}

bool GetRange(double lo, double hi, Value& v) {
  v.lo = lo;
  v.hi = hi;
  return !std::isnan(lo) && !std::isnan(hi) && lo != hi;
}

// Each setting once: its name serves the flag and the file. Several settings write the same
// field where they are alternatives (frequency or frequency-range, amplitude or Fourier).
const Setting kSettings[] = {
    {"m1", Kind::kNumber, "shell mass m1 [kg], > 0",
     [](DesignInput& in, const Value& v) { in.m1 = v.number; }, GetNumber<&DesignInput::m1>},
    {"L", Kind::kNumber, "free gap L of the inner body between the walls [m], > 0",
     [](DesignInput& in, const Value& v) { in.L = v.number; }, GetNumber<&DesignInput::L>},
    {"mu", Kind::kNumber, "friction coefficient mu of the shell on the floor, > 0",
     [](DesignInput& in, const Value& v) { in.mu = v.number; }, GetNumber<&DesignInput::mu>},
    {"g", Kind::kNumber, "gravity g [m/s^2], > 0 (default 9.81)",
     [](DesignInput& in, const Value& v) { in.g = v.number; }, GetNumber<&DesignInput::g>},
    {"e", Kind::kNumber, "coefficient of restitution e of the impacts, 0 <= e <= 1",
     [](DesignInput& in, const Value& v) { in.e = v.number; }, GetNumber<&DesignInput::e>},
    {"force-amplitude", Kind::kNumber,
     "amplitude A_N [N] of the motor force F_N = A_N sin(omega t + phase) + c_N, >= 0",
     [](DesignInput& in, const Value& v) {
       in.force.amplitude = v.number;
       in.force.cos.clear();
       in.force.sin.clear();
     },
     [](const DesignInput& in, Value& v) {
       v.number = in.force.amplitude;
       return !in.force.fourier() && !std::isnan(v.number);
     }},
    {"force-bias", Kind::kNumber, "mean c_N [N] of the motor force, >= 0",
     [](DesignInput& in, const Value& v) { in.force.bias = v.number; },
     [](const DesignInput& in, Value& v) {
       v.number = in.force.bias;
       return !std::isnan(v.number);
     }},
    {"force-cos", Kind::kList,
     "Fourier motor force instead of the amplitude: cosine coefficients [N] of "
     "F_N = c_N + sum_k (a_k cos k s + b_k sin k s), s = omega t + phase (as many as "
     "force-sin; default 0)",
     [](DesignInput& in, const Value& v) {
       in.force.cos = v.list;
       in.force.amplitude = DesignInput::kNaN;
     },
     [](const DesignInput& in, Value& v) {
       v.list = in.force.cos;
       return !v.list.empty();
     }},
    {"force-sin", Kind::kList, "Fourier motor force: sine coefficients b_1,...,b_K [N]",
     [](DesignInput& in, const Value& v) {
       in.force.sin = v.list;
       in.force.amplitude = DesignInput::kNaN;
     },
     [](const DesignInput& in, Value& v) {
       v.list = in.force.sin;
       return !v.list.empty();
     }},
    {"frequency", Kind::kNumber, "motor frequency f [Hz], > 0",
     [](DesignInput& in, const Value& v) { in.frequency_min = in.frequency_max = v.number; },
     [](const DesignInput& in, Value& v) {
       v.number = in.frequency_min;
       return !std::isnan(v.number) && in.frequency_min == in.frequency_max;
     }},
    {"frequency-range", Kind::kRange,
     "search the motor frequency too, over FMIN:FMAX [Hz] (instead of frequency)",
     [](DesignInput& in, const Value& v) {
       in.frequency_min = v.lo;
       in.frequency_max = v.hi;
     },
     [](const DesignInput& in, Value& v) {
       return GetRange(in.frequency_min, in.frequency_max, v);
     }},
    {"m2-range", Kind::kRange, "inner masses searched, M2MIN:M2MAX [kg] (default 0.01 m1:10 m1)",
     [](DesignInput& in, const Value& v) {
       in.m2_min = v.lo;
       in.m2_max = v.hi;
     },
     [](const DesignInput& in, Value& v) { return GetRange(in.m2_min, in.m2_max, v); }},
    {"margin", Kind::kNumber, "clearance d from both walls [units of L], 0 <= d < 0.5 (default 0)",
     [](DesignInput& in, const Value& v) { in.margin = v.number; },
     GetNumber<&DesignInput::margin>},
    {"margin-stroke", Kind::kNumber,
     "clearance d_s from both walls [units of the stroke 1 - x_min], >= 0 (default 0.02)",
     [](DesignInput& in, const Value& v) { in.margin_stroke = v.number; },
     GetNumber<&DesignInput::margin_stroke>},
    {"stick-margin", Kind::kNumber,
     "stick margin s: |F| <= (1-s) T0 while the shell rests, 0 <= s < 1 (default 0.02)",
     [](DesignInput& in, const Value& v) { in.stick_margin = v.number; },
     GetNumber<&DesignInput::stick_margin>},
    {"rho-max", Kind::kBound,
     "largest admissible multiplier modulus of the gait, > 0; inf: no stability requirement "
     "(default 0.9)",
     [](DesignInput& in, const Value& v) { in.rho_max = v.number; },
     GetNumber<&DesignInput::rho_max>},
    {"scan-points", Kind::kInteger,
     "log-spaced samples of each searched variable before the refinement, >= 3 (default 64)",
     [](DesignInput& in, const Value& v) { in.scan_points = static_cast<int>(v.number); },
     [](const DesignInput& in, Value& v) {
       v.number = in.scan_points;
       return true;
     }},
};
constexpr int kSettingCount = static_cast<int>(sizeof(kSettings) / sizeof(kSettings[0]));

// Settings that must be given (by a flag or the file), and pairs that exclude each other
// within one source (across sources the flag wins).
const std::vector<std::vector<const char*>> kRequired = {{"m1"},
                                                         {"L"},
                                                         {"mu"},
                                                         {"e"},
                                                         {"force-bias"},
                                                         {"force-amplitude", "force-sin"},
                                                         {"frequency", "frequency-range"}};
const std::vector<std::pair<const char*, const char*>> kExclusive = {
    {"frequency", "frequency-range"},
    {"force-amplitude", "force-sin"},
    {"force-amplitude", "force-cos"}};

// "who = text[ where] is invalid: expected rule"; where says which file, if any.
[[noreturn]] void Bad(const std::string& who, const std::string& text, const char* rule,
                      const std::string& where = "") {
  throw std::invalid_argument(
      fmt::format("{} = {}{} is invalid: expected {}", who, text, where, rule));
}

// An element of a list or range: a number of capsubot::ParseNumber; false if it is not one.
bool ToNumber(const std::string& text, double& out) {
  try {
    out = ParseNumber(text, "element");
    return true;
  } catch (const std::invalid_argument&) {
    return false;
  }
}

const char* Rule(Kind kind) {
  switch (kind) {
    case Kind::kNumber:
      return "a number";
    case Kind::kBound:
      return "a number or inf";
    case Kind::kInteger:
      return "an integer";
    case Kind::kList:
      return "comma-separated numbers";
    case Kind::kRange:
      return "MIN:MAX with MIN < MAX";
  }
  return "a value";
}

// The value of a range once both ends are read: MIN < MAX (an empty or inverted range is an
// error; NaN too).
Value Range(const std::string& who, const std::string& text, double lo, double hi,
            const std::string& where) {
  if (!(lo < hi)) Bad(who, text, "MIN:MAX with MIN < MAX", where);
  Value v;
  v.lo = lo;
  v.hi = hi;
  return v;
}

// A setting's value from its text (a flag, or a string in the file).
Value FromText(const Setting& s, const std::string& who, const std::string& text,
               const std::string& where = "") {
  Value v;
  switch (s.kind) {
    case Kind::kBound:
      v.number = text == "inf" ? HUGE_VAL : ParseNumber(text, who);
      return v;
    case Kind::kNumber:
      v.number = ParseNumber(text, who);
      return v;
    case Kind::kInteger:
      v.number = static_cast<double>(ParseInteger(text, who, std::numeric_limits<int>::min(),
                                                  std::numeric_limits<int>::max()));
      return v;
    case Kind::kList:
      for (const std::string& element : SplitText(text, ',')) {
        double x = 0.0;
        if (!ToNumber(element, x)) Bad(who, text, Rule(s.kind), where);
        v.list.push_back(x);
      }
      return v;
    case Kind::kRange: {
      const std::size_t colon = text.find(':');
      double lo = 0.0, hi = 0.0;
      if (colon == std::string::npos || !ToNumber(text.substr(0, colon), lo) ||
          !ToNumber(text.substr(colon + 1), hi)) {
        Bad(who, text, Rule(s.kind), where);
      }
      return Range(who, text, lo, hi, where);
    }
  }
  return v;
}

// Most characters of a key or value a message shows: the rest is cut to "...", so that a
// huge key or value of the file makes a message of one short line.
constexpr std::size_t kShownChars = 60;

// `text` cut to kShownChars characters and "...".
std::string Clip(std::string text) {
  if (text.size() > kShownChars) text = text.substr(0, kShownChars) + "...";
  return text;
}

// A value as written in the file, numbers in shortest round-trip form: 0.1, 'abc', [0.5, 1],
// {a = 0.3}; cut once longer than a message shows (the file's nesting is bounded by
// RequireTomlDepth, so is this recursion).
std::string Show(const toml::node& node) {
  std::string text;
  const auto add = [&text](const std::string& item) {
    if (text.size() <= kShownChars) text += item;
  };
  if (const auto* array = node.as_array()) {
    add("[");
    for (const toml::node& element : *array) {
      if (text.size() > 1) add(", ");
      add(Show(element));
    }
    add("]");
  } else if (const auto* table = node.as_table()) {
    add("{");
    for (const auto& [key, value] : *table) {
      if (text.size() > 1) add(", ");
      add(std::string(key.str()) + " = " + Show(value));
    }
    add("}");
  } else if (node.is_floating_point()) {
    add(FormatNumber(**node.as_floating_point()));
  } else {
    std::ostringstream out;
    node.visit([&out](const auto& n) { out << n; });
    add(out.str());
  }
  return Clip(text);
}

// Nesting of a config file at the most: parts of a dotted key or table header, plus arrays
// and inline tables around a value. The parser descends once per level: a file nested
// thousands deep would exhaust the stack. A robot's file needs 2.
constexpr int kMaxTomlDepth = 32;

// The scan of RequireTomlDepth: keys' dots, headers' dots and the brackets and braces of values,
// outside strings and comments. Tracks only what nests; the parser checks the rest of the
// syntax.
class TomlDepthScan {
 public:
  TomlDepthScan(const std::string& text, const std::string& path) : text_(text), path_(path) {}

  // Throws at the first place nested deeper than kMaxTomlDepth. Every step moves i_ forward.
  void Run() {
    while (i_ < text_.size()) {
      const char c = text_[i_];
      if (c == '#') {
        while (i_ < text_.size() && text_[i_] != '\n') ++i_;
      } else if (c == '"' || c == '\'') {
        SkipString();
      } else if (c == '\n') {
        NewLine();
      } else if (at_key_ && open_.empty() && c == '[') {  // a [table] or [[array]] header
        Header();
      } else if (at_key_ && c == '}' && !open_.empty() && open_.back() == '{') {  // {} or {a=1,}
        Close();
        at_key_ = false;
        ++i_;
      } else if (at_key_) {
        KeyChar(c);
      } else {
        ValueChar(c);
      }
    }
  }

 private:
  void Check(int d) const {
    if (d > kMaxTomlDepth) {
      throw std::invalid_argument(fmt::format(
          "config file {} line {} is invalid: keys and values nested more than {} deep: "
          "expected at most {} levels (parts of dotted keys and table headers, nested arrays "
          "and inline tables)",
          path_, line_, kMaxTomlDepth, kMaxTomlDepth));
    }
  }

  int Context() const { return depth_.empty() ? header_ : depth_.back(); }

  // Moves past the string that starts at i_ (basic or literal, one line or several).
  void SkipString() {
    const std::size_t n = text_.size();
    const char quote = text_[i_];
    const bool multi = text_.compare(i_, 3, std::string(3, quote)) == 0;
    i_ += multi ? 3 : 1;
    while (i_ < n) {
      if (text_[i_] == '\n') ++line_;
      if (quote == '"' && text_[i_] == '\\') {
        i_ += 2;
        continue;
      }
      if (text_[i_] == quote && (!multi || text_.compare(i_, 3, std::string(3, quote)) == 0)) {
        i_ += multi ? 3 : 1;
        return;
      }
      if (text_[i_] == '\n' && !multi) return;
      ++i_;
    }
  }

  void NewLine() {
    ++line_;
    ++i_;
    if (open_.empty()) {
      at_key_ = true;
      parts_ = 1;
    }
  }

  // A [table] or [[array]] header: its dotted parts give the depth of the keys below it.
  void Header() {
    int header_parts = 1;
    for (++i_; i_ < text_.size() && text_[i_] != ']' && text_[i_] != '\n';) {
      if (text_[i_] == '"' || text_[i_] == '\'') {
        SkipString();
        continue;
      }
      if (text_[i_] == '.') Check(++header_parts);
      ++i_;
    }
    header_ = header_parts;
    while (i_ < text_.size() && text_[i_] == ']') ++i_;
  }

  void Close() {
    depth_.pop_back();
    open_.pop_back();
  }

  void KeyChar(char c) {
    if (c == '.') Check(Context() + ++parts_);
    if (c == '=') {
      at_key_ = false;
      value_depth_ = Context() + parts_;
      Check(value_depth_);
    }
    ++i_;
  }

  void ValueChar(char c) {
    if (c == '[' || c == '{') {
      const int d = (!open_.empty() && open_.back() == '[' ? depth_.back() : value_depth_) + 1;
      Check(d);
      depth_.push_back(d);
      open_.push_back(c);
      if (c == '{') {
        at_key_ = true;
        parts_ = 1;
      }
    } else if ((c == ']' || c == '}') && !open_.empty()) {
      Close();
    } else if (c == ',' && !open_.empty() && open_.back() == '{') {
      at_key_ = true;
      parts_ = 1;
    }
    ++i_;
  }

  const std::string& text_;
  const std::string& path_;
  std::size_t i_ = 0;
  int line_ = 1;
  int header_ = 0;          // parts of the last [table] header: the depth of the keys below it
  std::vector<int> depth_;  // depth of the elements of each open array or inline table
  std::vector<char> open_;  // '[' or '{' of each
  int value_depth_ = 0;     // depth of the value after the last '='
  bool at_key_ = true;      // reading a key: its dots separate its parts
  int parts_ = 1;
};

// Refuses a TOML text nested deeper than kMaxTomlDepth, scanning it before it is parsed.
void RequireTomlDepth(const std::string& text, const std::string& path) {
  TomlDepthScan(text, path).Run();
}

// A setting's value from the config file: numbers as TOML numbers, lists and ranges as arrays
// of numbers (a range may also be the flag's text "MIN:MAX").
Value FromToml(const Setting& s, const std::string& where, const toml::node& node) {
  const std::string who = s.name;
  const std::string shown = Show(node);
  const char* rule = s.kind == Kind::kList    ? "an array of numbers"
                     : s.kind == Kind::kRange ? "\"MIN:MAX\" or [MIN, MAX] with MIN < MAX"
                                              : Rule(s.kind);
  if (s.kind == Kind::kRange && node.is_string())
    return FromText(s, who, **node.as_string(), where);
  Value v;
  if (s.kind == Kind::kNumber || s.kind == Kind::kBound || s.kind == Kind::kInteger) {
    if (!(s.kind == Kind::kInteger ? node.is_integer() : node.is_number()))
      Bad(who, shown, rule, where);
    v.number = node.value<double>().value_or(std::nan(""));
    if (s.kind == Kind::kInteger && std::abs(v.number) > INT32_MAX) Bad(who, shown, rule, where);
    return v;
  }
  const toml::array* array = node.as_array();
  if (array == nullptr) Bad(who, shown, rule, where);
  for (const toml::node& element : *array) {
    if (!element.is_number()) Bad(who, shown, rule, where);
    v.list.push_back(element.value<double>().value_or(std::nan("")));
  }
  if (s.kind == Kind::kList) {
    if (v.list.empty()) Bad(who, shown, rule, where);
    return v;
  }
  if (v.list.size() != 2) Bad(who, shown, rule, where);
  return Range(who, shown, v.list[0], v.list[1], where);
}

// A value as the text of its flag, read back by FromText to the same value.
std::string FlagText(const Setting& s, const Value& v) {
  switch (s.kind) {
    case Kind::kBound:
      return std::isinf(v.number) ? "inf" : FormatNumber(v.number);
    case Kind::kInteger:
      return fmt::format("{}", static_cast<long long>(v.number));
    case Kind::kList: {
      std::vector<std::string> items;
      for (double x : v.list) items.push_back(FormatNumber(x));
      return fmt::format("{}", fmt::join(items, ","));
    }
    case Kind::kRange:
      return FormatNumber(v.lo) + ":" + FormatNumber(v.hi);
    case Kind::kNumber:
      break;
  }
  return FormatNumber(v.number);
}

// Whether setting `name` or an alternative of it (kExclusive) is among `names`.
bool NamedOrAlternative(const std::set<std::string>& names, const std::string& name) {
  if (names.count(name) > 0) return true;
  for (const auto& [a, b] : kExclusive) {
    if ((name == a && names.count(b) > 0) || (name == b && names.count(a) > 0)) return true;
  }
  return false;
}

// No two alternatives (kExclusive) from one source: `given` holds the names it set.
void CheckExclusive(const std::set<std::string>& given, const std::string& source) {
  for (const auto& [a, b] : kExclusive) {
    if (given.count(a) > 0 && given.count(b) > 0) {
      throw std::invalid_argument(
          fmt::format("settings {} and {} are both given {}: expected one of them", a, b, source));
    }
  }
}

int Find(const std::string& name) {
  for (int i = 0; i < kSettingCount; ++i) {
    if (name == kSettings[i].name) return i;
  }
  return -1;
}

std::string Names() {
  std::vector<std::string> names;
  for (const Setting& s : kSettings) names.emplace_back(s.name);
  return fmt::format("{}", fmt::join(names, ", "));
}

// The settings of the config file `path` (none when empty) into `in`; returns their names.
std::set<std::string> ReadConfigFile(const std::string& path, DesignInput& in) {
  std::set<std::string> from_file;
  if (path.empty()) return from_file;
  const std::string text = ReadTextFile(path, "--config");
  RequireTomlDepth(text, path);
  toml::table table;
  try {
    table = toml::parse(text, path);
  } catch (const toml::parse_error& e) {
    throw std::invalid_argument(fmt::format("config file {} line {} is invalid: {}", path,
                                            e.source().begin.line, e.description()));
  }
  for (const auto& [key, node] : table) {
    const std::string name(key.str());
    const int i = Find(name);
    if (i < 0) {
      throw std::invalid_argument(
          fmt::format("{} = {} in {} is invalid: unknown key, expected one of {}", Clip(name),
                      Show(node), path, Names()));
    }
    const Setting& s = kSettings[i];
    s.set(in, FromToml(s, " in " + path, node));
    from_file.insert(name);
  }
  CheckExclusive(from_file, "in " + path);
  return from_file;
}

// A grid's axis gives its setting (added to `given`) the axis's first value, a valid one (the
// run sets each point's, DesignGridOptions); a flag for it or an alternative of it (in
// `from_flags`) is refused.
void SetFromGrid(const DesignGridAxis& axis, const DesignConfigOptions& o,
                 const std::set<std::string>& from_flags, DesignInput& in,
                 std::set<std::string>& given) {
  const int i = Find(axis.name());
  // m2 is not a setting: its grid fixes what m2-range searches, so the two exclude each other.
  std::vector<std::string> flags = {i < 0 ? std::string("m2-range") : axis.name()};
  for (const auto& [a, b] : kExclusive) {
    if (axis.name() == a) flags.emplace_back(b);
    if (axis.name() == b) flags.emplace_back(a);
  }
  for (const std::string& flag : flags) {
    if (from_flags.count(flag) == 0) continue;
    throw std::invalid_argument(
        fmt::format("--{} = {} is invalid with --grid {}: expected the value from only one of them",
                    flag, o.values[Find(flag)], axis.ToString()));
  }
  if (i < 0) return;
  Value v;
  v.number = axis.Value(0);
  kSettings[i].set(in, v);
  given.insert(axis.name());
}

}  // namespace

void AddDesignConfigOptions(CLI::App& cmd, DesignConfigOptions& o) {
  cmd.add_option("--config", o.config,
                 "TOML file with the robot: keys named like these flags without the dashes "
                 "(m1 = 0.2, force-sin = [0.5], frequency-range = [10, 40]); flags override it")
      ->type_name("FILE");
  o.values.assign(kSettingCount, std::string());
  o.options.assign(kSettingCount, nullptr);
  for (int i = 0; i < kSettingCount; ++i) {
    const Setting& s = kSettings[i];
    o.options[i] = cmd.add_option(std::string("--") + s.name, o.values[i], s.help);
    o.options[i]->type_name(s.kind == Kind::kRange     ? "MIN:MAX"
                            : s.kind == Kind::kBound   ? "NUMBER|inf"
                            : s.kind == Kind::kList    ? "X1,X2,..."
                            : s.kind == Kind::kInteger ? "INT"
                                                       : "NUMBER");
  }
}

DesignInput BuildDesignInput(const DesignConfigOptions& o, const std::vector<DesignGridAxis>& grid,
                             std::vector<std::pair<std::string, std::string>>* settings,
                             bool motor_force) {
  DesignInput in;
  std::set<std::string> given = ReadConfigFile(o.config, in);
  std::set<std::string> from_flags;
  for (int i = 0; i < kSettingCount; ++i) {
    if (o.options[i]->count() == 0) continue;
    const Setting& s = kSettings[i];
    s.set(in, FromText(s, std::string("--") + s.name, o.values[i]));
    from_flags.insert(s.name);
  }
  CheckExclusive(from_flags, "as flags");
  given.insert(from_flags.begin(), from_flags.end());
  for (const DesignGridAxis& axis : grid) SetFromGrid(axis, o, from_flags, in, given);
  if (!motor_force) {
    for (const char* name : {"force-amplitude", "force-bias", "force-cos", "force-sin"}) {
      if (given.count(name) > 0) {
        throw std::invalid_argument(fmt::format(
            "setting {} is invalid with --drive: expected no motor force (the drive search "
            "chooses it; give the motor's peak with --force-max)",
            name));
      }
    }
    in.force = MotorForce{0.0, 0.0, {}, {}};
  }
  // Every missing setting named at once: "setting L is missing: ..." or "settings L, mu and
  // e are missing: give --L, --mu and --e (or L, mu and e in the --config file)".
  std::vector<std::string> missing, flags, keys;
  for (const auto& group : kRequired) {
    if (!motor_force && std::string(group.front()).rfind("force", 0) == 0) continue;
    bool any = false;
    for (const char* name : group) any = any || given.count(name) > 0;
    if (!any) {
      missing.push_back(fmt::format("{}", fmt::join(group, " or ")));
      flags.push_back(std::string("--") + group.front());
      keys.emplace_back(group.front());
    }
  }
  if (!missing.empty()) {
    const auto list = [](const std::vector<std::string>& items) {
      if (items.size() == 1) return items.front();
      return fmt::format("{} and {}", fmt::join(items.begin(), items.end() - 1, ", "),
                         items.back());
    };
    throw std::invalid_argument(
        fmt::format("setting{} {} {} missing: give {} (or {} in the --config file)",
                    missing.size() == 1 ? "" : "s", list(missing),
                    missing.size() == 1 ? "is" : "are", list(flags), list(keys)));
  }
  in.Validate();
  if (settings != nullptr) {
    // A grid gives its settings (m2: the range searched) at every point.
    std::set<std::string> gridded;
    for (const DesignGridAxis& axis : grid) {
      gridded.insert(Find(axis.name()) < 0 ? std::string("m2-range") : axis.name());
    }
    settings->clear();
    for (const Setting& s : kSettings) {
      Value v;
      if (NamedOrAlternative(gridded, s.name) || !s.get(in, v)) continue;
      settings->emplace_back(std::string("--") + s.name, FlagText(s, v));
    }
  }
  return in;
}

}  // namespace capsubot::app
