#include "capsubot/model/setting_names.hpp"

#include <fmt/format.h>

#include <cctype>
#include <cstring>

namespace capsubot {

std::string SettingNames::Name(const std::string& field) const {
  for (const auto& [name, flag] : flags) {
    if (field == name) return flag;
  }
  return field;
}

std::string SettingNames::InRule(const std::string& field) const {
  const std::string name = Name(field);
  return style == Style::kFlags ? name.substr(name.find_first_not_of('-')) : name;
}

std::string SettingNames::Value(const std::string& value) const {
  return style == Style::kFlags ? value : "'" + value + "'";
}

std::string SettingNames::Given(const std::string& field, const std::string& value) const {
  return style == Style::kFlags ? fmt::format("{} {}", Name(field), value)
                                : fmt::format("{}={}", Name(field), Value(value));
}

std::string SettingNames::Absent(const std::string& field) const {
  return style == Style::kFlags ? "no " + Name(field) : Name(field) + "=None";
}

FlagNames Without(const FlagNames& names, const std::set<std::string>& fields) {
  FlagNames kept;
  for (const auto& entry : names) {
    if (fields.count(entry.first) == 0) kept.push_back(entry);
  }
  return kept;
}

namespace {

bool NamePart(char c) { return std::isalnum(static_cast<unsigned char>(c)) != 0 || c == '_'; }

// Whether the name at `at` is an operand of an expression ("to - from = 0.1", "2 * max_period =
// 16"): the value after it is the expression's, not the field's.
bool Operand(const std::string& message, std::size_t at) {
  return at >= 2 && message[at - 1] == ' ' && std::strchr("+-*/", message[at - 2]) != nullptr;
}

// The message with every "name = " of a field in its rule (after its first word) as "flag = ".
std::string RuleWithFlagNames(std::string message, const FlagNames& names) {
  for (const auto& [name, flag] : names) {
    const std::string field = std::string(name) + " = ";
    for (std::size_t at = message.find(field, 1); at != std::string::npos;
         at = message.find(field, at + 1)) {
      // Not a part of a longer name, a flag or a member path ("seeds[0].alpha").
      if (NamePart(message[at - 1]) || message[at - 1] == '-' || message[at - 1] == '.' ||
          Operand(message, at)) {
        continue;
      }
      message.replace(at, std::strlen(name), flag);
      at += std::strlen(flag);
    }
  }
  return message;
}

}  // namespace

std::string WithFlagNames(const std::string& message, const FlagNames& names) {
  for (const auto& [name, flag] : names) {
    const std::size_t n = std::strlen(name);
    if (message.compare(0, n, name) == 0 && n < message.size() &&
        (message[n] == ' ' || message[n] == ':')) {
      return RuleWithFlagNames(flag + message.substr(n), names);
    }
  }
  return RuleWithFlagNames(message, names);
}

}  // namespace capsubot
