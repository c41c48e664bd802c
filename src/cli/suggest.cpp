#include "capsubot/cli/suggest.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>

namespace capsubot::cli {
namespace {

std::string Lower(std::string s) {
  for (char& ch : s) ch = static_cast<char>(std::tolower(static_cast<unsigned char>(ch)));
  return s;
}

// Levenshtein distance (names are short: a row of size b + 1 suffices).
std::size_t EditDistance(const std::string& a, const std::string& b) {
  std::vector<std::size_t> row(b.size() + 1);
  for (std::size_t j = 0; j <= b.size(); ++j) row[j] = j;
  for (std::size_t i = 1; i <= a.size(); ++i) {
    std::size_t diagonal = row[0];
    row[0] = i;
    for (std::size_t j = 1; j <= b.size(); ++j) {
      const std::size_t above = row[j];
      row[j] = std::min({row[j] + 1, row[j - 1] + 1, diagonal + (a[i - 1] == b[j - 1] ? 0 : 1)});
      diagonal = above;
    }
  }
  return row[b.size()];
}

// The long and short flag names of a command ("--T0", "-o", ...).
std::vector<std::string> FlagNames(const CLI::App& command) {
  std::vector<std::string> names;
  for (const CLI::Option* o : command.get_options()) {
    for (const std::string& n : o->get_lnames()) names.push_back("--" + n);
    for (const std::string& n : o->get_snames()) names.push_back("-" + n);
  }
  return names;
}

}  // namespace

std::optional<std::string> Nearest(const std::string& word,
                                   const std::vector<std::string>& candidates) {
  for (const std::string& c : candidates) {
    if (Lower(c) == Lower(word)) return c;
  }
  const std::size_t bound = std::max<std::size_t>(1, word.size() / 3);
  std::optional<std::string> best;
  std::size_t best_distance = bound + 1;
  for (const std::string& c : candidates) {
    const std::size_t d = EditDistance(Lower(word), Lower(c));
    if (d < best_distance) {
      best_distance = d;
      best = c;
    }
  }
  return best;
}

std::vector<std::string> ReadHelpCommand(std::vector<std::string> args) {
  if (args.empty() || args.front() != "help") return args;
  if (args.size() == 1) return {"--help"};
  return {args[1], "--help"};
}

std::optional<std::string> UnknownCommand(const CLI::App& app, const std::string& first) {
  std::vector<std::string> commands;
  for (const CLI::App* sub : app.get_subcommands({})) commands.push_back(sub->get_name());
  const bool flag = !first.empty() && first.front() == '-';
  if (flag) {
    if (first == "--help" || first == "-h" || first == "--help-all" || first == "--version") {
      return std::nullopt;
    }
    const auto near = Nearest(first, {"--help", "--help-all", "--version"});
    return fmt::format(
        "unknown option '{}'{}; expected a command ({}) or --help, --help-all or --version", first,
        near ? fmt::format("; did you mean '{}'?", *near) : "", fmt::join(commands, ", "));
  }
  if (std::find(commands.begin(), commands.end(), first) != commands.end()) return std::nullopt;
  const auto near = Nearest(first, commands);
  return fmt::format(
      "unknown command '{}'{}; expected one of {} (capsubot help COMMAND explains "
      "one)",
      first, near ? fmt::format("; did you mean '{}'?", *near) : "", fmt::join(commands, ", "));
}

std::optional<std::string> UnknownFlag(const CLI::App& command,
                                       const std::vector<std::string>& extras) {
  const std::vector<std::string> names = FlagNames(command);
  for (const std::string& extra : extras) {
    if (extra.size() < 2 || extra.front() != '-') continue;
    const std::string flag = extra.substr(0, extra.find('='));
    if (const auto near = Nearest(flag, names)) {
      return fmt::format("{} is an unknown flag; did you mean {}? (see capsubot {} --help)", flag,
                         *near, command.get_name());
    }
  }
  return std::nullopt;
}

}  // namespace capsubot::cli
