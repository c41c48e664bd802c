#pragma once
// The command line's options of a job's settings, declared from the library's table of them.

#include <CLI/CLI.hpp>
#include <type_traits>
#include <variant>

#include "capsubot/job/setting_table.hpp"
#include "cli.hpp"

namespace capsubot::app {

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
