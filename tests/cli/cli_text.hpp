#pragma once
// What the tests of the command line read from the help: the commands, the flags of a
// command, the examples of a command.

#include <stdlib.h>

#include <filesystem>
#include <sstream>
#include <string>
#include <vector>

#include "test_utils.hpp"

namespace capsubot::testing {

/// A new directory under /tmp, removed with its files at the end of the scope.
class ScratchDir {
 public:
  ScratchDir() {
    char pattern[] = "/tmp/capsubot_cli_test_XXXXXX";
    path_ = ::mkdtemp(pattern) != nullptr ? pattern : "";
  }
  ~ScratchDir() {
    std::error_code ignored;
    if (!path_.empty()) std::filesystem::remove_all(path_, ignored);
  }
  ScratchDir(const ScratchDir&) = delete;
  ScratchDir& operator=(const ScratchDir&) = delete;
  const std::string& path() const { return path_; }

 private:
  std::string path_;
};

/// `capsubot <args>` with the help `columns` wide (the environment variable COLUMNS).
inline CommandResult RunCliAt(int columns, const std::string& args) {
  return RunShell("COLUMNS=" + std::to_string(columns) + " " + CAPSUBOT_CLI + " " + args);
}

/// The lines of `text`.
inline std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) lines.push_back(line);
  return lines;
}

/// The commands listed under "Subcommands:" in `capsubot --help`, in their order.
inline std::vector<std::string> HelpCommands() {
  std::vector<std::string> commands;
  bool listed = false;
  for (const std::string& line : Lines(RunCli("--help").out)) {
    if (line == "Subcommands:") {
      listed = true;
    } else if (listed && line.rfind("  ", 0) == 0 && line[2] != ' ') {
      commands.push_back(line.substr(2, line.find(' ', 2) - 2));
    }
  }
  return commands;
}

/// The flag names ("-o", "--output", ...) of the help of `capsubot <command>` (COLUMNS wide):
/// the lines of an option begin with two spaces and a dash, its names separated by commas.
inline std::vector<std::string> HelpFlags(const std::string& command, int columns = 200) {
  std::vector<std::string> flags;
  const std::string help = RunCliAt(columns, "help " + command).out;
  for (const std::string& line : Lines(help)) {
    if (line.rfind("  -", 0) != 0) continue;
    std::istringstream names(line.substr(2, line.find(' ', 2) - 2));
    std::string name;
    while (std::getline(names, name, ',')) flags.push_back(name);
  }
  return flags;
}

/// An example of a command's help: what it shows and the command line.
struct HelpExample {
  std::string what;
  std::string command;  ///< "capsubot solve --A 0.5 ...", continuation lines joined
};

/// The examples of `capsubot <command> --help` at `columns`: after "Examples:", "# what"
/// comment lines, then the command line, whose lines ending in " \" go on on the next.
inline std::vector<HelpExample> HelpExamples(const std::string& command, int columns) {
  std::vector<HelpExample> examples;
  bool in_examples = false, continued = false;
  for (const std::string& line : Lines(RunCliAt(columns, "help " + command).out)) {
    if (line == "Examples:") in_examples = true;
    if (!in_examples || line.find_first_not_of(' ') == std::string::npos || line == "Examples:") {
      continue;
    }
    const std::string text = line.substr(line.find_first_not_of(' '));
    if (continued) {
      examples.back().command += " " + text;
    } else if (text.rfind("# ", 0) == 0) {
      if (examples.empty() || !examples.back().command.empty()) examples.emplace_back();
      std::string& what = examples.back().what;
      what += (what.empty() ? "" : " ") + text.substr(2);
    } else if (!examples.empty()) {
      examples.back().command = text;
    }
    const std::string& current = examples.empty() ? text : examples.back().command;
    continued = current.size() >= 2 && current.compare(current.size() - 2, 2, " \\") == 0;
    if (continued) examples.back().command.resize(current.size() - 2);
  }
  return examples;
}

}  // namespace capsubot::testing
