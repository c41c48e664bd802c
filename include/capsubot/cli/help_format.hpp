#pragma once
// The layout of `capsubot --help`: the text wrapped to the terminal's width, and an
// "Examples:" section at the end of each command's help.

#include <CLI/CLI.hpp>
#include <cstddef>
#include <string>
#include <vector>

namespace capsubot::cli {

/// The width of the help: COLUMNS when it is a number, else the width of the terminal on
/// standard output, else 80 (not a terminal); bounded to [kMinHelpWidth, kMaxHelpWidth].
std::size_t HelpWidth();
inline constexpr std::size_t kMinHelpWidth = 60;
inline constexpr std::size_t kMaxHelpWidth = 200;

/// A runnable example of a command, shown at the end of its --help.
struct Example {
  const char* what;  ///< what it shows, one sentence: "the paper's worked example"
  const char* args;  ///< the arguments after `capsubot`: "solve --A 0.5 --c 0.5 --phi0 -2.9"
};

/// Adds the section "Examples:" at the end of the help of `command`: each example as a
/// comment line "# what" and the command line "capsubot args", wrapped with " \" when it is
/// wider than the help.
void SetExamples(CLI::App& command, const std::vector<Example>& examples);

/// CLI11's help with the descriptions (of the program, of each command and option) and the
/// examples wrapped to `width`; the list of commands shows the first sentence of each
/// description; --help-all shows every command's whole help.
class HelpFormatter : public CLI::Formatter {
 public:
  explicit HelpFormatter(std::size_t width) : width_(width) {}
  std::string make_description(const CLI::App* app) const override;
  std::string make_option(const CLI::Option* option, bool is_positional) const override;
  std::string make_subcommand(const CLI::App* sub) const override;
  std::string make_expanded(const CLI::App* sub) const override;
  std::string make_footer(const CLI::App* app) const override;

 private:
  std::size_t width_;
};

}  // namespace capsubot::cli
