#pragma once
// Checks of a job's table of settings (capsubot/job/setting_table.hpp) that every table must
// pass: each row sets a field of its own (two rows on one member would bind two flags to one
// value), has a help whose "{field}" names a known setting (else a front end would print the
// braces), and a range (an integer's) that holds its default and is the job's own rule.

#include <gtest/gtest.h>

#include <cstdint>
#include <set>
#include <string>
#include <type_traits>
#include <variant>

#include "capsubot/job/setting_table.hpp"
#include "test_utils.hpp"

namespace capsubot::testing {

/// The names in braces of `help` ("{periods}" -> periods); braces holding anything but a
/// field's characters (letters, digits, '_') are text, as HelpIn keeps them.
inline std::set<std::string> BracedFields(const std::string& help) {
  std::set<std::string> names;
  for (std::size_t open = help.find('{'); open != std::string::npos;
       open = help.find('{', open + 1)) {
    const std::size_t close = help.find('}', open);
    if (close == std::string::npos) break;
    const std::string name = help.substr(open + 1, close - open - 1);
    const bool field =
        !name.empty() &&
        name.find_first_not_of("abcdefghijklmnopqrstuvwxyz0123456789_") == std::string::npos;
    if (field) names.insert(name);
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
    for (const std::string& name : BracedFields(row.help)) {
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

}  // namespace capsubot::testing
