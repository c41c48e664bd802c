#pragma once
// What a command prints at its end: the text of its result, or with --json its JSON object
// with the provenance (JsonOutput). With -o FILE (solve, simulate, orbits, periodic, design)
// it goes to FILE instead of standard output, written atomically (capsubot::AtomicFile: a
// symlink's target is written, a device or pipe in place, never replaced); "-" is standard
// output.

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "capsubot/cli/provenance.hpp"

namespace capsubot::cli {

/// Whether output path `path` is standard output: "-", or a path to the file, pipe or terminal
/// standard output writes to (/dev/stdout, or the file it is redirected to).
bool IsStandardOutput(const std::string& path);

/// Refuses (std::invalid_argument) `output` of `option` ("-o") on standard output
/// (IsStandardOutput) together with --json (`json`), which prints its object there too: the
/// two would be mixed in one stream ("-o - with --json is invalid: ...").
void RequireOutputApartFromJson(const std::string& output, const char* option, bool json);

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

/// The --json and -o of a command: in which form its result is printed, and where.
struct ResultOutput {
  bool json = false;  ///< --json: the JSON object of the result with its provenance
  std::string path;   ///< -o: the file written; empty or "-": standard output

  /// Adds --json (`json_help`) and -o (AddResultOutputOption with `what`) to `cmd`.
  void Add(CLI::App& cmd, const std::string& json_help, const std::string& what);

  /// Writes `result`: with --json `to_json(result)` with JsonProvenance(cmd, unused), else
  /// `to_text(result)` (only the form asked is built), by WriteResult.
  template <class Result, class ToJson, class ToText>
  void Write(const CLI::App& cmd, const Result& result, ToJson to_json, ToText to_text,
             const std::vector<std::string>& unused = {}) const {
    WriteResult(path,
                json ? JsonOutput(to_json(result), JsonProvenance(cmd, unused)) : to_text(result));
  }
};

}  // namespace capsubot::cli
