// A command line that helps: mistyped commands and flags get the nearest name, `capsubot help
// [COMMAND]` prints the help wrapped to the terminal's width with examples, the problems'
// short names P1 to P3 are understood.

#include <gtest/gtest.h>

#include <algorithm>
#include <string>

#include "cli/cli_text.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::RunCli;

struct HelpCase {
  const char* name;
  const char* args;
  int status;
  const char* expected;  // a substring of stdout + stderr
  friend void PrintTo(const HelpCase& c, std::ostream* os) { *os << c.name; }
};

class HelpCli : public ::testing::TestWithParam<HelpCase> {};

TEST_P(HelpCli, AnswersWithTheNearestNameOrTheHelp) {
  const HelpCase& c = GetParam();
  const auto r = RunCli(std::string(c.args) + " 2>&1");
  EXPECT_EQ(r.status, c.status) << r.out;
  EXPECT_NE(r.out.find(c.expected), std::string::npos) << r.out;
  if (c.status == 2) {  // one line
    EXPECT_EQ(r.out.find('\n'), r.out.size() - 1) << r.out;
  }
}

const HelpCase kHelpCases[] = {
    {"MisspeltCommand", "optimise", 2, "unknown command 'optimise'; did you mean 'optimize'?"},
    {"MisspeltCommandWithFlags", "solv --A 0.5", 2, "did you mean 'solve'?"},
    {"UnknownCommandFarFromAll", "frobnicate", 2, "unknown command 'frobnicate'; expected one of"},
    {"MisspeltVersion", "--versoin", 2, "unknown option '--versoin'; did you mean '--version'?"},
    {"HelpAlone", "help", 0, "Subcommands:"},
    {"HelpOfACommand", "help optimize", 0, "--problem"},
    {"HelpOfEveryCommand", "--help-all", 0, "Usage: capsubot bifurcation [OPTIONS]"},
    {"MisspeltHelpAll", "--help-al", 2, "did you mean '--help-all'?"},
    {"HelpOfAMisspeltCommand", "help optimise", 2, "did you mean 'optimize'?"},
    {"FlagInTheWrongCase", "solve --A 0.5 --c 0.5 --phi0 -2.9 --t0 1", 2,
     "--t0 is an unknown flag; did you mean --T0?"},
    {"MisspeltFlag", "solve --A 0.5 --c 0.5 --phi0 -2.9 --stabilty", 2,
     "did you mean --stability?"},
    {"ProblemShortName", "optimize --problem P2 --T0 0.1 --json", 0, "\"problem\":\"forcing\""},
    {"ProblemShortNameLowerCase", "optimize --problem p1 --A 0.2 --c 0.03 --json", 0,
     "\"problem\":\"phase\""},
};

// A bare `capsubot` (no arguments) prints the help with the list of commands, exit status 0,
// nothing on stderr: the same bytes as `capsubot --help`.
TEST(HelpCli, BareCommandPrintsTheListOfCommands) {
  const auto bare = RunCli("2>&1");
  const auto help = RunCli("--help");
  EXPECT_EQ(bare.status, 0) << bare.out;
  EXPECT_EQ(bare.out, help.out);
  EXPECT_NE(bare.out.find("Subcommands:"), std::string::npos) << bare.out;
  EXPECT_NE(bare.out.find("  sweep "), std::string::npos) << bare.out;
}

// Phases in the syntax of the grids: pi multiples give exactly what their decimal value gives.
TEST(PhaseSyntax, PiMultiplesEqualTheirDecimalValue) {
  const auto pi = testing::RunCli("solve --A 0.5 --c 0.5 --phi0 -pi/2 --json");
  const auto decimal = testing::RunCli("solve --A 0.5 --c 0.5 --phi0 -1.5707963267948966 --json");
  ASSERT_EQ(pi.status, 0) << pi.out;
  EXPECT_EQ(pi.out, decimal.out);  // the provenance records the value read
  const auto grid = testing::RunCli("sweep --grid phi0=-pi/2:3*pi/4:3 --A 0.5 --c 0.5 -o -");
  ASSERT_EQ(grid.status, 0) << grid.out;
  EXPECT_NE(grid.out.find("\n-1.5707963267948966,"), std::string::npos) << grid.out;
  const auto bad = testing::RunCli("solve --A 0.5 --c 0.5 --phi0 2pi 2>&1");
  EXPECT_EQ(bad.status, 2);
  EXPECT_NE(bad.out.find("--phi0 = 2pi is invalid: expected a phase in radians"), std::string::npos)
      << bad.out;
}

// The help is as wide as COLUMNS says, within [60, 200]; 80 when COLUMNS is not a number and
// standard output is not a terminal (here a pipe).
struct WidthCase {
  const char* name;
  const char* columns;  // the value of COLUMNS, or nullptr: unset
  std::size_t width;    // the width expected
  friend void PrintTo(const WidthCase& c, std::ostream* os) { *os << c.name; }
};

class HelpWidth : public ::testing::TestWithParam<WidthCase> {};

TEST_P(HelpWidth, WrapsEveryLineToTheWidth) {
  const WidthCase& c = GetParam();
  const std::string env = c.columns != nullptr ? std::string("COLUMNS=") + c.columns + " "
                                               : std::string("env -u COLUMNS ");
  for (const char* command : {"--help", "help sweep", "help optimize"}) {
    const auto r = testing::RunShell(env + CAPSUBOT_CLI + " " + command);
    ASSERT_EQ(r.status, 0) << r.out;
    std::size_t widest = 0;
    for (const std::string& line : testing::Lines(r.out)) {
      EXPECT_LE(line.size(), c.width) << command << ": " << line;
      widest = std::max(widest, line.size());
    }
    // The room is used: long descriptions fill the lines to within a word of the width.
    EXPECT_GT(widest, c.width - 16) << command;
  }
}

const WidthCase kWidthCases[] = {
    {"Columns100", "100", 100},
    {"Columns60", "60", 60},
    {"BelowTheBound", "20", 60},
    {"AboveTheBound", "500", 200},
    {"NotATerminalNoColumns", nullptr, 80},
    {"ColumnsNotANumber", "wide", 80},
};

INSTANTIATE_TEST_SUITE_P(Table, HelpWidth, ::testing::ValuesIn(kWidthCases),
                         [](const ::testing::TestParamInfo<WidthCase>& info) {
                           return std::string(info.param.name);
                         });

// Every command's help ends with one or two examples of the command itself; wrapped to 60
// columns (lines ending in " \") they are the same command lines as at 200 columns.
TEST(HelpExamples, EveryCommandEndsItsHelpWithExamplesThatWrapIntoTheSameCommand) {
  const std::vector<std::string> commands = testing::HelpCommands();
  ASSERT_GE(commands.size(), 12u);
  for (const std::string& command : commands) {
    const auto wide = testing::HelpExamples(command, 200);
    const auto narrow = testing::HelpExamples(command, 60);
    ASSERT_GE(wide.size(), 1u) << command;
    EXPECT_LE(wide.size(), 2u) << command;
    ASSERT_EQ(narrow.size(), wide.size()) << command;
    for (std::size_t i = 0; i < wide.size(); ++i) {
      EXPECT_EQ(wide[i].command.rfind("capsubot " + command + " ", 0), 0u) << wide[i].command;
      EXPECT_FALSE(wide[i].what.empty()) << wide[i].command;
      EXPECT_EQ(narrow[i].command, wide[i].command);
      EXPECT_EQ(narrow[i].what, wide[i].what);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Table, HelpCli, ::testing::ValuesIn(kHelpCases),
                         [](const ::testing::TestParamInfo<HelpCase>& info) {
                           return std::string(info.param.name);
                         });

}  // namespace
}  // namespace capsubot
