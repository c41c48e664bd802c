#include "capsubot/cli/help_format.hpp"

#include <sys/ioctl.h>
#include <unistd.h>

#include <algorithm>
#include <cctype>
#include <cstdlib>
#include <sstream>

#include "capsubot/io/wrap_text.hpp"

namespace capsubot::cli {
namespace {

constexpr const char* kProgram = "capsubot ";
constexpr const char* kCommentLead = "  # ";
constexpr const char* kCommandLead = "  capsubot ";
constexpr std::size_t kCommandIndent = 6;   // a wrapped command line goes on under its command
constexpr std::size_t kCommandColumn = 15;  // the list of commands: their names' column
constexpr std::size_t kExpandedIndent = 2;  // --help-all: a command's help under its name

std::string Indented(const std::vector<std::string>& lines, std::size_t first, std::size_t others) {
  std::string out;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    out += std::string(i == 0 ? first : others, ' ') + lines[i] + '\n';
  }
  return out;
}

// `name` in the first column (`column` wide) and `description` wrapped beside it; a name as
// wide as the column stands on lines of its own (wrapped to `width`, then indented by 4).
std::string TwoColumns(const std::string& name, const std::string& description, std::size_t column,
                       std::size_t width) {
  const std::vector<std::string> lines = WrapText(description, width - column);
  if (name.size() < column) return name + Indented(lines, column - name.size(), column);
  return Indented(WrapText(name.substr(2), width - 6), 2, 6) + Indented(lines, column, column);
}

bool IsFlag(const std::string& word) {  // --grid, -o; not a negative number (-2.8)
  return word.size() >= 2 && word[0] == '-' &&
         (word[1] == '-' || std::isalpha(static_cast<unsigned char>(word[1])) != 0);
}

// One line of a command line to run, broken at spaces but never between a flag and its
// value: every line but the last ends with " \" (the shell joins them), so that a copied
// example still runs.
std::string WrapCommand(const std::string& line, std::size_t width) {
  if (line.size() <= width) return line + '\n';
  const std::size_t lead = line.find_first_not_of(' ');
  std::istringstream in(line.substr(lead));
  std::vector<std::string> units;  // "--grid T0=0.01:1:65:log", "-o", "part0.csv", ...
  std::string word;
  bool glue = false;  // the previous word is a flag: this one is its value
  while (in >> word) {
    if (glue && !IsFlag(word)) {
      units.back() += " " + word;
    } else {
      units.push_back(word);
    }
    glue = IsFlag(word);
  }
  const std::vector<std::string> lines =
      WrapWords(units, width - kCommandIndent - 2);  // 2: the " \"
  std::string out;
  for (std::size_t i = 0; i < lines.size(); ++i) {
    out += std::string(i == 0 ? lead : kCommandIndent, ' ') + lines[i] +
           (i + 1 < lines.size() ? " \\\n" : "\n");
  }
  return out;
}

// The examples section (the footer SetExamples wrote), each line wrapped to `width`. With
// `prompt` (--help-all, under the command's name) the heading is indented and each command
// line begins with "$ " four columns in: help2man keeps such lines verbatim in the manual.
std::string WrapExamples(const std::string& footer, std::size_t width, bool prompt) {
  std::istringstream in(footer);
  std::string out;
  std::string line;
  while (std::getline(in, line)) {
    if (line.rfind(kCommentLead, 0) == 0) {
      const std::size_t lead = std::string(kCommentLead).size();
      const std::vector<std::string> lines = WrapText(line.substr(lead), width - lead);
      for (const std::string& l : lines) out += kCommentLead + l + '\n';
    } else if (line.rfind(kCommandLead, 0) == 0) {
      out += WrapCommand(prompt ? "    $ " + line.substr(2) : line, width);
    } else {
      // The heading: with `prompt` on a paragraph of its own (help2man joins lines).
      out += Indented(WrapText(line, width), prompt ? 2 : 0, prompt ? 2 : 0) + (prompt ? "\n" : "");
    }
  }
  return out;
}

std::vector<std::string> Lines(const std::string& text) {
  std::vector<std::string> lines;
  std::istringstream in(text);
  std::string line;
  while (std::getline(in, line)) lines.push_back(line);
  return lines;
}

// The first sentence of a command's description (up to a '.', ':' or ';' that ends a word,
// outside parentheses and `quotes`): what the list of commands shows.
std::string Summary(const std::string& description) {
  int depth = 0;        // inside parentheses
  bool quoted = false;  // inside `...`
  for (std::size_t i = 0; i < description.size(); ++i) {
    const char c = description[i];
    if (c == '(') ++depth;
    if (c == ')' && depth > 0) --depth;
    if (c == '`') quoted = !quoted;
    const bool ends = i + 1 == description.size() || description[i + 1] == ' ';
    if (depth == 0 && !quoted && ends && (c == '.' || c == ':' || c == ';')) {
      return description.substr(0, i);
    }
  }
  return description;
}

}  // namespace

std::size_t HelpWidth() {
  std::size_t width = 80;
  const char* columns = std::getenv("COLUMNS");
  char* end = nullptr;
  const long from_env = columns != nullptr ? std::strtol(columns, &end, 10) : 0;
  winsize size{};
  if (columns != nullptr && end != columns && *end == '\0' && from_env > 0) {
    width = static_cast<std::size_t>(from_env);
  } else if (::isatty(STDOUT_FILENO) != 0 && ::ioctl(STDOUT_FILENO, TIOCGWINSZ, &size) == 0 &&
             size.ws_col > 0) {
    width = size.ws_col;
  }
  return std::clamp(width, kMinHelpWidth, kMaxHelpWidth);
}

void SetExamples(CLI::App& command, const std::vector<Example>& examples) {
  std::string footer = "Examples:\n";
  for (const Example& e : examples) {
    footer += std::string(kCommentLead) + e.what + "\n" + kCommandLead + e.args + "\n";
  }
  command.footer(footer);
}

std::string HelpFormatter::make_description(const CLI::App* app) const {
  const std::string text = CLI::Formatter::make_description(app);
  return text.empty() ? text : Indented(WrapText(text, width_), 0, 0) + '\n';
}

// The options' descriptions begin at CLI11's column (30), nearer the names in a narrow help.
std::string HelpFormatter::make_option(const CLI::Option* option, bool is_positional) const {
  return TwoColumns("  " + make_option_name(option, is_positional) + make_option_opts(option),
                    make_option_desc(option), std::min(get_column_width(), width_ * 2 / 5), width_);
}

std::string HelpFormatter::make_subcommand(const CLI::App* sub) const {
  return TwoColumns("  " + sub->get_display_name(true), Summary(sub->get_description()),
                    kCommandColumn, width_);
}

// --help-all: after the program's help, each command's whole help under "capsubot NAME:",
// indented (help2man makes the name a subsection of the manual page).
std::string HelpFormatter::make_expanded(const CLI::App* sub) const {
  const HelpFormatter inner(width_ - kExpandedIndent);
  const std::string body =
      inner.make_description(sub) + inner.make_usage(sub, kProgram + sub->get_name()) +
      inner.make_positionals(sub) + inner.make_groups(sub, CLI::AppFormatMode::Normal);
  std::string out = "\n" + (kProgram + sub->get_name()) + ":\n";
  for (const std::string& line : Lines(body)) {
    out += (line.empty() ? "" : std::string(kExpandedIndent, ' ')) + line + '\n';
  }
  const std::string footer = sub->get_footer();
  return footer.empty() ? out : out + '\n' + WrapExamples(footer, width_, true);
}

std::string HelpFormatter::make_footer(const CLI::App* app) const {
  const std::string footer = app->get_footer();
  return footer.empty() ? footer : WrapExamples(footer, width_, false);
}

}  // namespace capsubot::cli
