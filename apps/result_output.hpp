#pragma once
// What a command prints at its end: the text of its result, or with --json its JSON object
// with the provenance (JsonOutput). With -o FILE (solve, simulate, orbits, periodic, design)
// it goes to FILE instead of standard output, written atomically (capsubot::AtomicFile: a
// symlink's target is written, a device or pipe in place, never replaced); "-" is standard
// output.

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>

#include "provenance.hpp"

namespace capsubot::app {

/// Adds -o,--output FILE to `cmd` (the result of the command; `what` says what it is).
CLI::Option* AddResultOutputOption(CLI::App& cmd, std::string& path, const std::string& what);

/// Throws IoError naming -o when `path` cannot be written (before the work); nothing for ""
/// or "-" (standard output).
void CheckResultOutput(const std::string& path);

/// Prints `text` on standard output ("" or "-"), else writes it to `path` atomically.
void WriteResult(const std::string& path, const std::string& text);

/// What a command prints with --json: the JSON object `j` of its result with "provenance"
/// (`provenance`, e.g. JsonProvenance(cmd)), on one line ended by a newline. A command ends with
/// WriteResult(path, json ? JsonOutput(...) : text), so that only the output asked is built.
std::string JsonOutput(nlohmann::json j, const Provenance& provenance);

}  // namespace capsubot::app
