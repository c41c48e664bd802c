#pragma once
// -o FILE of the commands that print one result (solve, simulate, orbits, periodic, design):
// what the command prints, its text or with --json its JSON object, goes to FILE instead of
// standard output, written atomically (capsubot::AtomicFile: a symlink's target is written, a
// device or pipe in place, never replaced); "-" is standard output.

#include <CLI/CLI.hpp>
#include <string>

namespace capsubot::app {

/// Adds -o,--output FILE to `cmd` (the result of the command; `what` says what it is).
CLI::Option* AddResultOutputOption(CLI::App& cmd, std::string& path, const std::string& what);

/// Throws IoError naming -o when `path` cannot be written (before the work); nothing for ""
/// or "-" (standard output).
void CheckResultOutput(const std::string& path);

/// Prints `text` on standard output ("" or "-"), else writes it to `path` atomically.
void WriteResult(const std::string& path, const std::string& text);

}  // namespace capsubot::app
