#pragma once
// The command line's options of a job's settings, declared from the library's table of them.

#include <CLI/CLI.hpp>
#include <algorithm>
#include <cstring>
#include <set>
#include <string>
#include <type_traits>
#include <variant>

#include "capsubot/job/setting_table.hpp"
#include "cli.hpp"

namespace capsubot::app {

/// The flag of `field`: "--" and the field with '_' written '-' ("max_period" ->
/// "--max-period"). It lives as long as the program (a FlagNames entry points to it); called
/// while the commands are declared, before any thread starts.
inline const char* DashedFlag(const char* field) {
  static std::set<std::string> flags;  // a set's elements never move
  std::string flag = std::string("--") + field;
  std::replace(flag.begin(), flag.end(), '_', '-');
  return flags.insert(flag).first->c_str();
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

/// Adds one option per row of `table` to `cmd` (a flag for a bool field), named by `flags`,
/// bound to the row's field of `options`, with the row's help in the flags' names, its range
/// (Bounded), its default (unless the row hides it) and its type name (when the row has one).
template <class Options>
void AddSettings(CLI::App& cmd, Options& options, const SettingTable<Options>& table,
                 const FlagNames& flags) {
  const SettingNames names{flags};
  for (const SettingRow<Options>& row : table) {
    const std::string flag = names.Name(row.field);
    const std::string help = HelpIn(row.help, flags);
    std::visit(
        [&](auto member) {
          auto& field = options.*member;
          if constexpr (std::is_same_v<std::decay_t<decltype(field)>, bool>) {
            cmd.add_flag(flag, field, help);
          } else {
            CLI::Option* option = cmd.add_option(flag, field, help);
            if (row.lo < row.hi) Bounded(option, row.lo, row.hi);
            if (row.show_default) option->capture_default_str();
            if (row.type_name != nullptr) option->type_name(row.type_name);
          }
        },
        row.member);
  }
}

}  // namespace capsubot::app
