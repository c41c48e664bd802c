#include "config_file.hpp"

#include <fmt/format.h>
#include <toml++/toml.h>

#include <cmath>
#include <cstdint>
#include <sstream>
#include <stdexcept>
#include <vector>

#include "capsubot/io/io.hpp"
#include "robot_settings.hpp"
#include "toml_depth.hpp"

namespace capsubot::detail {
namespace {

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

// A setting's value from the config file: numbers as TOML numbers, lists and ranges as arrays
// of numbers (a range may also be the flag's text "MIN:MAX").
SettingValue FromToml(const RobotSetting& s, const std::string& where, const toml::node& node) {
  const std::string who = s.name;
  const std::string shown = Show(node);
  const char* rule = s.kind == SettingKind::kList    ? "an array of numbers"
                     : s.kind == SettingKind::kRange ? "\"MIN:MAX\" or [MIN, MAX] with MIN < MAX"
                                                     : TextRule(s.kind);
  if (s.kind == SettingKind::kRange && node.is_string())
    return FromText(s, who, **node.as_string(), where);
  SettingValue v;
  if (s.kind == SettingKind::kNumber || s.kind == SettingKind::kBound ||
      s.kind == SettingKind::kInteger) {
    if (!(s.kind == SettingKind::kInteger ? node.is_integer() : node.is_number()))
      BadSetting(who, shown, rule, where);
    v.number = node.value<double>().value_or(std::nan(""));
    if (s.kind == SettingKind::kInteger && std::abs(v.number) > INT32_MAX)
      BadSetting(who, shown, rule, where);
    return v;
  }
  const toml::array* array = node.as_array();
  if (array == nullptr) BadSetting(who, shown, rule, where);
  for (const toml::node& element : *array) {
    if (!element.is_number()) BadSetting(who, shown, rule, where);
    v.list.push_back(element.value<double>().value_or(std::nan("")));
  }
  if (s.kind == SettingKind::kList) {
    if (v.list.empty()) BadSetting(who, shown, rule, where);
    return v;
  }
  if (v.list.size() != 2) BadSetting(who, shown, rule, where);
  return RangeValue(who, shown, v.list[0], v.list[1], where);
}

}  // namespace

std::set<std::string> ReadConfigFile(const std::string& path, const std::string& option,
                                     DesignInput& in) {
  std::set<std::string> from_file;
  if (path.empty()) return from_file;
  const std::string text = ReadTextFile(path, option);
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
    const int i = FindRobotSetting(name);
    if (i < 0) {
      throw std::invalid_argument(
          fmt::format("{} = {} in {} is invalid: unknown key, expected one of {}", Clip(name),
                      Show(node), path, RobotSettingNames()));
    }
    const RobotSetting& s = RobotSettings()[i];
    s.set(in, FromToml(s, " in " + path, node));
    from_file.insert(name);
  }
  return from_file;
}

}  // namespace capsubot::detail
