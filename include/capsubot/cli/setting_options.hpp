#pragma once
// The command line's options of a job's settings, declared from the library's table of them.

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cmath>
#include <cstring>
#include <set>
#include <string>
#include <type_traits>
#include <variant>
#include <vector>

#include "capsubot/cli/strict_values.hpp"
#include "capsubot/io/io.hpp"
#include "capsubot/job/setting_table.hpp"

namespace capsubot::cli {

/// The flag of `field`: "--" and the field with '_' written '-' ("max_period" ->
/// "--max-period"), kept as long as the program (KeptText).
inline const char* DashedFlag(const std::string& field) {
  std::string flag = "--" + field;
  std::replace(flag.begin(), flag.end(), '_', '-');
  return KeptText(flag);
}

/// The DashedFlag of each field of `fields` (names separated by spaces), in that order, then the
/// entries of `others`: the fields whose flag is another name ({"levels", "--pulse-levels"}).
inline FlagNames DashedFlags(const std::string& fields, const FlagNames& others = {}) {
  FlagNames names;
  for (const std::string& field : SplitText(fields, ' ')) {
    if (!field.empty()) names.emplace_back(KeptText(field), DashedFlag(field));
  }
  names.insert(names.end(), others.begin(), others.end());
  return names;
}

/// The fields of `names` whose flag was given on the parsed command `cmd`.
inline std::set<std::string> GivenFields(const CLI::App& cmd, const FlagNames& names) {
  std::set<std::string> given;
  for (const auto& [field, flag] : names) {
    const CLI::Option* option = cmd.get_option_no_throw(flag);
    if (option != nullptr && option->count() > 0) given.insert(field);
  }
  return given;
}

/// `names` with the DashedFlag of every field of `tables` that has no entry in it.
template <class... Options>
FlagNames WithDashedFlags(FlagNames names, const SettingTable<Options>&... tables) {
  const auto add = [&names](const auto& table) {
    for (const auto& row : table) {
      const bool named = std::any_of(names.begin(), names.end(), [&row](const auto& entry) {
        return std::strcmp(entry.first, row.field) == 0;
      });
      if (!named) names.emplace_back(row.field, DashedFlag(row.field));
    }
  };
  (add(tables), ...);
  return names;
}

/// Whether a setting's default is a value to show: not a number not given (NaN) nor an empty
/// text, which mean "none" (required, or computed by the job).
template <class Field>
bool HasDefault(const Field& field) {
  if constexpr (std::is_floating_point_v<Field>) {
    return !std::isnan(field);
  } else if constexpr (std::is_same_v<Field, std::string>) {
    return !field.empty();
  } else {
    return true;
  }
}

/// Adds the option of `row` to `cmd` (a flag for a bool field), named by `flags`, bound to the
/// row's field of `options`, with the row's help in the flags' names, its range (Bounded), its
/// default (when it has one: HasDefault, and the row shows it) and its type name (when the
/// row has one).
template <class Options>
CLI::Option* AddSetting(CLI::App& cmd, Options& options, const SettingRow<Options>& row,
                        const FlagNames& flags) {
  const std::string flag = SettingNames{flags}.Name(row.field);
  const std::string help = HelpIn(row.help, flags);
  return std::visit(
      [&](auto member) -> CLI::Option* {
        auto& field = options.*member;
        if constexpr (std::is_same_v<std::decay_t<decltype(field)>, bool>) {
          return cmd.add_flag(flag, field, help);
        } else {
          CLI::Option* option = cmd.add_option(flag, field, help);
          if (row.lo < row.hi) Bounded(option, row.lo, row.hi);
          if (row.default_shown && HasDefault(field)) option->capture_default_str();
          if (row.type_name != nullptr) option->type_name(row.type_name);
          return option;
        }
      },
      row.member);
}

/// Adds one option per row of `table` to `cmd`, in the table's order (AddSetting).
template <class Options>
void AddSettings(CLI::App& cmd, Options& options, const SettingTable<Options>& table,
                 const FlagNames& flags) {
  for (const SettingRow<Options>& row : table) AddSetting(cmd, options, row, flags);
}

/// Adds the options of the rows of `fields` only, in that order: for a command that lists
/// other options between them. Throws std::logic_error for a field the table has no row of.
template <class Options>
void AddSettings(CLI::App& cmd, Options& options, const SettingTable<Options>& table,
                 const FlagNames& flags, const std::vector<std::string>& fields) {
  for (const std::string& field : fields) AddSetting(cmd, options, RowOf(table, field), flags);
}

}  // namespace capsubot::cli
