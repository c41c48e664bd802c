#pragma once
// What made an output file: the program, its version, the subcommand and the value of every
// option that determines the content, as one command line (CSV comment lines) or a JSON
// object. Options that only change how or where the work is done (threads, output path,
// resume) are left out, so that the same content always carries the same provenance.

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

namespace capsubot::app {

struct Provenance {
  std::string command;  ///< the subcommand, e.g. "sweep"
  /// The options in the order the command declares them: {"--grid", "phi0=-pi:pi:5"}; a
  /// flag has an empty value; an option given several times appears several times.
  std::vector<std::pair<std::string, std::string>> options;

  /// "capsubot 1.0.0 sweep --grid phi0=-pi:pi:5 --A 0.5 ...": a command that reproduces the
  /// content (values shell-quoted where needed).
  std::string CommandLine() const;
  /// {"program": "capsubot", "version": ..., "command": ..., "command_line": ...,
  ///  "options": {"--grid": ["phi0=-pi:pi:5"], "--stability": [], ...}}.
  nlohmann::json Json() const;
};

/// The provenance of a parsed subcommand: every option that was given (with its values as
/// given) or has a default value (with the default), flags only when set, in declaration
/// order; `exclude` lists long names ("--threads") that do not change the content.
Provenance CommandProvenance(const CLI::App& command, const std::vector<std::string>& exclude);

/// The provenance AddProvenanceJson adds (its options: see there).
Provenance JsonProvenance(const CLI::App& command, const std::vector<std::string>& unused = {});

/// Adds "provenance" (Provenance::Json) to a JSON output of the parsed subcommand `command`:
/// every option that determines the content, but not --json, --threads, the paths of output
/// files (-o/--output, --trajectory, --events, --force-csv, --from-rest-csv, --plot) or what
/// only shapes those files (--samples, --samples-per-period), nor the options in `unused`
/// (long names of options the run does not use).
void AddProvenanceJson(nlohmann::json& j, const CLI::App& command,
                       const std::vector<std::string>& unused = {});

}  // namespace capsubot::app
