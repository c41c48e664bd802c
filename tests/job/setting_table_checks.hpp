#pragma once
// Checks of a job's tables of settings (capsubot/job/setting_table.hpp) that every table must
// pass: each row sets a field of its own (two rows on one member would bind two flags to one
// value), has a help whose "{field}" names a known setting (else a front end would print the
// braces), and a range (an integer's) that holds its default and is the job's own rule; and
// the tables of one command gathered with the values their rows bind, checked the same way.

#include <gtest/gtest.h>

#include <cstdint>
#include <set>
#include <string>
#include <type_traits>
#include <utility>
#include <variant>
#include <vector>

#include "capsubot/job/setting_table.hpp"
#include "test_utils.hpp"

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

/// `table` is not empty, its fields and members are distinct, each help is a sentence whose
/// "{field}"s are fields of the table or of `others` (the job's settings that have no row of
/// it), and each range is an integer's, lo <= hi, holding the field's default.
template <class Options>
::testing::AssertionResult WellFormed(const SettingTable<Options>& table,
                                      const std::set<std::string>& others = {}) {
  if (table.empty()) return ::testing::AssertionFailure() << "the table has no rows";
  std::set<std::string> fields = others;
  for (const auto& row : table) fields.insert(row.field);
  std::set<std::string> seen;
  std::set<const void*> members;
  const Options defaults;
  for (const auto& row : table) {
    if (!seen.insert(row.field).second) {
      return ::testing::AssertionFailure() << "two rows of " << row.field;
    }
    const void* member =
        std::visit([&](auto m) -> const void* { return &(defaults.*m); }, row.member);
    if (!members.insert(member).second) {
      return ::testing::AssertionFailure() << row.field << " sets the member of another row";
    }
    if (std::string(row.help).size() < 10) {
      return ::testing::AssertionFailure() << row.field << " has no help: \"" << row.help << "\"";
    }
    for (const std::string& name : Placeholders(row.help)) {
      if (fields.count(name) == 0) {
        return ::testing::AssertionFailure()
               << "the help of " << row.field << " names {" << name << "}, not a setting";
      }
    }
    if (row.lo > row.hi) {
      return ::testing::AssertionFailure() << row.field << ": range " << row.lo << " > " << row.hi;
    }
    const bool default_in_range = std::visit(
        [&](auto m) {
          using Field = std::decay_t<decltype(defaults.*m)>;
          if constexpr (std::is_integral_v<Field> && !std::is_same_v<Field, bool>) {
            const auto value = static_cast<std::int64_t>(defaults.*m);
            return row.lo == row.hi || (row.lo <= value && value <= row.hi);
          } else {
            return row.lo == row.hi;  // a range is an integer's
          }
        },
        row.member);
    if (!default_in_range) {
      return ::testing::AssertionFailure()
             << row.field << ": the default is outside its range, or the field is no integer";
    }
  }
  return ::testing::AssertionSuccess();
}

/// Each ranged (integer) row of `table` is the rule `check` (which validates an Options, e.g.
/// by its job's Validate) applies: `valid` with the field at lo or hi passes, at lo - 1 or
/// hi + 1 is refused by a message that begins with the field's name. At least one row is
/// ranged.
template <class Options, class Check>
::testing::AssertionResult RangesAreTheRules(const SettingTable<Options>& table,
                                             const Options& valid, Check check) {
  int ranged = 0;
  for (const auto& row : table) {
    if (row.lo == row.hi) continue;
    ++ranged;
    for (const std::int64_t value : {row.lo - 1, row.lo, row.hi, row.hi + 1}) {
      Options o = valid;
      std::visit(
          [&](auto m) {
            using Field = std::decay_t<decltype(o.*m)>;
            if constexpr (std::is_integral_v<Field> && !std::is_same_v<Field, bool>) {
              o.*m = static_cast<Field>(value);
            }
          },
          row.member);
      const std::string message = InvalidArgumentMessage([&] { check(o); });
      const bool inside = row.lo <= value && value <= row.hi;
      if (inside && !message.empty()) {
        return ::testing::AssertionFailure()
               << row.field << " = " << value << " is refused: " << message;
      }
      if (!inside && message.rfind(std::string(row.field) + " = ", 0) != 0) {
        return ::testing::AssertionFailure()
               << row.field << " = " << value << " is not refused by its rule: \"" << message
               << "\"";
      }
    }
  }
  if (ranged == 0) return ::testing::AssertionFailure() << "no row has a range";
  return ::testing::AssertionSuccess();
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
