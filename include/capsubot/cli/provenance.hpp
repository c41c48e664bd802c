#pragma once
// What made an output file: the program, its version, the subcommand and the value of every
// option that determines the content, as one command line (the comment line that starts every
// CSV file) or a JSON object. Options that only change how or where the work is done (threads,
// output paths, shards, resume) are left out, so that the same content always carries the same
// provenance.

#include <CLI/CLI.hpp>
#include <nlohmann/json.hpp>
#include <string>
#include <utility>
#include <vector>

namespace capsubot::cli {

struct Provenance {
  std::string command;  ///< the subcommand, e.g. "sweep"
  /// The options in the order the command declares them: {"--grid", "phi0=-pi:pi:5"}; a
  /// flag has an empty value; an option given several times appears several times.
  std::vector<std::pair<std::string, std::string>> options;

  /// "capsubot 1.0.0 sweep --grid phi0=-pi:pi:5 --A 0.5 ...": a command that reproduces the
  /// content (values shell-quoted where needed).
  std::string CommandLine() const;
  /// "# " + CommandLine() + "\n": the line that starts a CSV file (pandas: comment='#';
  /// gnuplot skips it).
  std::string CommentLine() const;
  /// {"program": "capsubot", "version": ..., "command": ..., "command_line": ...,
  ///  "options": {"--grid": ["phi0=-pi:pi:5"], "--stability": [], ...}}.
  nlohmann::json Json() const;
};

/// The provenance of a parsed subcommand: every option that was given (with its values as
/// given) or has a default value (with the default), flags only when set, in declaration
/// order; `exclude` lists long names ("--threads") that do not change the content.
Provenance CommandProvenance(const CLI::App& command, const std::vector<std::string>& exclude);

/// The provenance of an output of the parsed subcommand `command`: every option, but not those
/// that change no output's content (--json, --threads, the paths of output files -o/--output,
/// --summary, --trajectory, --events, --force-csv, --from-rest-csv, --plot, and --shard,
/// --resume, --checkpoint-seconds, --no-header-comment), nor the options in `unused` (long
/// names of options the run does not use or that do not shape this output).
Provenance OutputProvenance(const CLI::App& command, const std::vector<std::string>& unused = {});

/// The provenance of a JSON output ("provenance"): OutputProvenance(command, unused) without
/// what only shapes the CSV files (--samples, --samples-per-period).
Provenance JsonProvenance(const CLI::App& command, const std::vector<std::string>& unused = {});

}  // namespace capsubot::cli
