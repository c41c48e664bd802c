#pragma once
// Helps a user who mistyped: the nearest command or flag name, and the command line read with
// `capsubot help [COMMAND]` and the problems' short names.

#include <CLI/CLI.hpp>
#include <optional>
#include <string>
#include <vector>

namespace capsubot::cli {

/// The candidate nearest to `word`: equal but for case first, else the one within an edit
/// distance of max(1, size/3) (the first of equal distance); none when nothing is that close.
std::optional<std::string> Nearest(const std::string& word,
                                   const std::vector<std::string>& candidates);

/// Arguments as CLI11 should read them: `help` alone is `--help`, `help COMMAND` is
/// `COMMAND --help`. The others are kept.
std::vector<std::string> ReadHelpCommand(std::vector<std::string> args);

/// The one-line complaint about a first argument that names no command ("unknown command
/// 'optimise'; did you mean 'optimize'?"), or none when the argument is fine for CLI11
/// (a command, --help, --help-all, --version, -h). Flags unknown at the top level get the same
/// treatment.
std::optional<std::string> UnknownCommand(const CLI::App& app, const std::string& first);

/// For CLI11's "arguments were not expected" of a command: the nearest flag of `command` to
/// each unexpected flag ("--t0: unknown flag; did you mean --T0?"), or none if no flag is near.
std::optional<std::string> UnknownFlag(const CLI::App& command,
                                       const std::vector<std::string>& extras);

}  // namespace capsubot::cli
