#include "capsubot/cli/completion_script.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <string>
#include <vector>

#include "capsubot/io/io.hpp"
#include "capsubot/model/version.hpp"

namespace capsubot::cli {
namespace {

std::vector<std::string> FlagNames(const CLI::Option& option) {
  std::vector<std::string> names;
  for (const std::string& n : option.get_snames()) names.push_back("-" + n);
  for (const std::string& n : option.get_lnames()) names.push_back("--" + n);
  return names;
}

bool IsTypeName(const std::string& word) {  // FLOAT, INT, TEXT: a value to type, not a choice
  return std::none_of(word.begin(), word.end(),
                      [](char c) { return std::islower(static_cast<unsigned char>(c)) != 0; });
}

// The values to propose after `option`: the choices its type name lists ("phi0|forcing|...";
// "FLOAT|inf" gives inf), "FILE" for a path, or none (a number, a grid, "b1,b2,...": a value
// to type).
std::vector<std::string> ValueWords(const CLI::Option& option) {
  const std::string type = option.get_type_name();
  if (type == "FILE") return {"FILE"};
  const std::string list = type.substr(0, type.find(':'));  // ":..." a check's description
  std::vector<std::string> words;
  if (list.find('|') == std::string::npos) return words;
  for (const std::string& word : SplitText(list, '|')) {
    if (!word.empty() && !IsTypeName(word)) words.push_back(word);
  }
  return words;
}

std::string Join(const std::vector<std::string>& words, const char* separator) {
  return fmt::format("{}", fmt::join(words, separator));
}

// The branch of the script for `command`: what follows a flag that takes a value, its flags,
// whether words that are not flags are file names (its positional arguments).
std::string CommandBranch(const CLI::App& command) {
  std::vector<std::string> flags;
  std::string values;
  std::vector<std::string> typed;  // flags followed by a value to type (a number, a grid)
  bool positional = false;
  for (const CLI::Option* option : command.get_options()) {
    const std::vector<std::string> names = FlagNames(*option);
    if (names.empty()) positional = true;
    flags.insert(flags.end(), names.begin(), names.end());
    if (names.empty() || option->get_expected_max() == 0) continue;
    const std::vector<std::string> words = ValueWords(*option);
    if (words.empty()) {
      typed.insert(typed.end(), names.begin(), names.end());
    } else if (words.front() == "FILE") {
      values += fmt::format("        {}) _capsubot_files; return ;;\n", Join(names, "|"));
    } else {
      values += fmt::format("        {}) _capsubot_words \"{}\"; return ;;\n", Join(names, "|"),
                            Join(words, " "));
    }
  }
  if (!typed.empty()) values += fmt::format("        {}) return ;;\n", Join(typed, "|"));
  return fmt::format(
      "    {})\n      case $prev in\n{}      esac\n      flags=\"{}\"\n      positional={}\n"
      "      ;;\n",
      command.get_name(), values, Join(flags, " "), positional ? 1 : 0);
}

constexpr const char* kHead =
    R"(# bash completion of capsubot {version}: commands, their flags and the values of
# flags that have a few (--optimize, --problem) or name a file. Written by
# `capsubot completion bash` from the program's own commands and flags.

_capsubot_words() {{ mapfile -t COMPREPLY < <(compgen -W "$1" -- "$cur"); }}
_capsubot_files() {{
  compopt -o filenames 2>/dev/null
  mapfile -t COMPREPLY < <(compgen -f -- "$cur")
}}

_capsubot() {{
  local cur=${{COMP_WORDS[COMP_CWORD]}} prev=${{COMP_WORDS[COMP_CWORD - 1]}}
  local command="" flags="" positional=0 i
  for ((i = 1; i < COMP_CWORD; i++)); do
    if [[ ${{COMP_WORDS[i]}} != -* ]]; then
      command=${{COMP_WORDS[i]}}
      break
    fi
  done
  case $command in
    "") _capsubot_words "{commands} {top_flags}"; return ;;
    help) _capsubot_words "{commands}"; return ;;
)";

constexpr const char* kTail = R"(    *) return ;;
  esac
  if [[ $cur == -* || $positional == 0 ]]; then
    _capsubot_words "$flags"
  else
    _capsubot_files
  fi
}
complete -F _capsubot capsubot
)";

}  // namespace

std::string BashCompletion(const CLI::App& app) {
  std::vector<std::string> commands, top_flags;
  std::string branches;
  for (const CLI::App* command : app.get_subcommands({})) {
    commands.push_back(command->get_name());
    branches += CommandBranch(*command);
  }
  for (const CLI::Option* option : app.get_options()) {
    const std::vector<std::string> names = FlagNames(*option);
    top_flags.insert(top_flags.end(), names.begin(), names.end());
  }
  return fmt::format(kHead, fmt::arg("version", Version()),
                     fmt::arg("commands", Join(commands, " ")),
                     fmt::arg("top_flags", Join(top_flags, " "))) +
         branches + kTail;
}

}  // namespace capsubot::cli
