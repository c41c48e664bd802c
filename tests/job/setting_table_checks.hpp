#pragma once
// What the tests of the settings tables share: the tables of one command gathered with the
// values their rows bind, checked for a field or a value set twice and for a help that names
// a setting the command does not have.

#include <gtest/gtest.h>

#include <set>
#include <string>
#include <utility>
#include <variant>
#include <vector>

#include "capsubot/job/setting_table.hpp"

namespace capsubot::testing {

/// The "{field}" placeholders of `help`: the braces holding a name (lower-case letters, digits,
/// '_'), which HelpIn writes as a front end's names; braces around other text are kept.
inline std::vector<std::string> Placeholders(const std::string& help) {
  std::vector<std::string> names;
  for (std::size_t open = help.find('{'); open != std::string::npos;
       open = help.find('{', open + 1)) {
    const std::size_t close = help.find('}', open);
    if (close == std::string::npos) break;
    const std::string inside = help.substr(open + 1, close - open - 1);
    const bool name =
        !inside.empty() &&
        inside.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_") == std::string::npos;
    if (name) names.push_back(inside);
  }
  return names;
}

/// The tables of one command, each with the options value its rows bind.
class SettingTablesCheck {
 public:
  /// Adds the rows of `table`, bound to `options` (a field of the command's options struct or
  /// that struct itself, so that two tables binding one value are seen).
  template <class Options>
  void Add(const SettingTable<Options>& table, const Options& options) {
    for (const SettingRow<Options>& row : table) {
      if (!fields_.insert(row.field).second) twice_.push_back(row.field);
      std::visit(
          [&](auto member) {
            if (!members_.insert(&(options.*member)).second) twice_.push_back(row.field);
          },
          row.member);
      helps_.emplace_back(row.field, row.help);
    }
  }

  /// Every row has a field and a value of its own.
  ::testing::AssertionResult EachFieldAndValueOnce() const {
    if (fields_.empty()) return ::testing::AssertionFailure() << "no rows";
    if (twice_.empty()) return ::testing::AssertionSuccess();
    auto failure = ::testing::AssertionFailure() << "set twice (field or value):";
    for (const std::string& field : twice_) failure << ' ' << field;
    return failure;
  }

  /// Every placeholder of every help is a field of the tables or one of `others` (settings the
  /// command reads outside the tables).
  ::testing::AssertionResult HelpsNameKnownSettings(const std::set<std::string>& others) const {
    auto failure = ::testing::AssertionFailure();
    bool ok = true;
    for (const auto& [field, help] : helps_) {
      for (const std::string& name : Placeholders(help)) {
        if (fields_.count(name) == 0 && others.count(name) == 0) {
          ok = false;
          failure << field << "'s help names {" << name << "}; ";
        }
      }
    }
    return ok ? ::testing::AssertionSuccess() : failure;
  }

  /// The placeholders of all helps, in order.
  std::vector<std::string> AllPlaceholders() const {
    std::vector<std::string> all;
    for (const auto& entry : helps_) {
      for (const std::string& name : Placeholders(entry.second)) all.push_back(name);
    }
    return all;
  }

 private:
  std::set<std::string> fields_;
  std::set<const void*> members_;
  std::vector<std::string> twice_;
  std::vector<std::pair<std::string, std::string>> helps_;
};

}  // namespace capsubot::testing
