#include "capsubot/cli/provenance.hpp"

#include <algorithm>
#include <cctype>

#include "capsubot/model/version.hpp"

namespace capsubot::cli {
namespace {

// The value as a shell word: unchanged when it holds only safe characters, else in single
// quotes (a quote inside becomes '\'').
std::string ShellWord(const std::string& value) {
  const bool safe = !value.empty() && std::all_of(value.begin(), value.end(), [](char ch) {
    return std::isalnum(static_cast<unsigned char>(ch)) != 0 ||
           std::string("_.,:=+-/@%").find(ch) != std::string::npos;
  });
  if (safe) return value;
  std::string quoted = "'";
  for (char ch : value) quoted += ch == '\'' ? std::string("'\\''") : std::string(1, ch);
  return quoted + "'";
}

// The default of an option that needs others (--rho-max needs --optimize) is recorded only
// with them, and not beside an option it excludes (--stable-only): either would make the
// replayed command invalid.
bool DefaultApplies(const CLI::Option& option) {
  for (const CLI::Option* needed : option.get_needs()) {
    if (needed->count() == 0) return false;
  }
  for (const CLI::Option* excluded : option.get_excludes()) {
    if (excluded->count() > 0) return false;
  }
  return true;
}

}  // namespace

std::string Provenance::CommandLine() const {
  std::string line = std::string("capsubot ") + Version() + " " + command;
  for (const auto& [name, value] : options) {
    line += " " + name;
    if (!value.empty()) line += " " + ShellWord(value);
  }
  return line;
}

std::string Provenance::CommentLine() const { return "# " + CommandLine() + '\n'; }

nlohmann::json Provenance::Json() const {
  nlohmann::json values = nlohmann::json::object();
  for (const auto& [name, value] : options) {
    nlohmann::json& list = values[name];
    if (list.is_null()) list = nlohmann::json::array();
    if (!value.empty()) list.push_back(value);
  }
  return {{"program", "capsubot"},
          {"version", Version()},
          {"command", command},
          {"command_line", CommandLine()},
          {"options", values}};
}

Provenance CommandProvenance(const CLI::App& command, const std::vector<std::string>& exclude) {
  Provenance p;
  p.command = command.get_name();
  for (const CLI::Option* option : command.get_options()) {
    if (option->get_lnames().empty()) continue;  // positional arguments
    const std::string name = "--" + option->get_lnames().front();
    // --help and the progress flags change only what the terminal shows, never the content.
    if (name == "--help" || name == "--progress" || name == "--no-progress" ||
        std::find(exclude.begin(), exclude.end(), name) != exclude.end()) {
      continue;
    }
    const bool flag = option->get_expected_max() == 0;
    if (flag) {
      if (option->count() > 0) p.options.emplace_back(name, "");
    } else if (option->count() > 0) {
      for (const std::string& value : option->results()) p.options.emplace_back(name, value);
    } else if (!option->get_default_str().empty() && DefaultApplies(*option)) {
      p.options.emplace_back(name, option->get_default_str());
    }
  }
  return p;
}

Provenance OutputProvenance(const CLI::App& command, const std::vector<std::string>& unused) {
  std::vector<std::string> exclude = {"--json",
                                      "--threads",
                                      "--output",
                                      "--summary",
                                      "--trajectory",
                                      "--events",
                                      "--force-csv",
                                      "--from-rest-csv",
                                      "--plot",
                                      "--shard",
                                      "--resume",
                                      "--checkpoint-seconds",
                                      "--no-header-comment"};
  exclude.insert(exclude.end(), unused.begin(), unused.end());
  return CommandProvenance(command, exclude);
}

Provenance JsonProvenance(const CLI::App& command, const std::vector<std::string>& unused) {
  std::vector<std::string> exclude = {"--samples", "--samples-per-period"};
  exclude.insert(exclude.end(), unused.begin(), unused.end());
  return OutputProvenance(command, exclude);
}

}  // namespace capsubot::cli
