// A command line that helps: mistyped commands and flags get the nearest name, `capsubot help
// [COMMAND]` prints the help, the problems' short names P1 to P3 are understood.

#include <gtest/gtest.h>

#include <string>

#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::RunCli;

struct HelpCase {
  const char* name;
  const char* args;
  int status;
  const char* expected;  // a substring of stdout + stderr
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
    {"HelpOfAMisspeltCommand", "help optimise", 2, "did you mean 'optimize'?"},
    {"FlagInTheWrongCase", "solve --A 0.5 --c 0.5 --phi0 -2.9 --t0 1", 2,
     "--t0 is an unknown flag; did you mean --T0?"},
    {"MisspeltFlag", "solve --A 0.5 --c 0.5 --phi0 -2.9 --stabilty", 2,
     "did you mean --stability?"},
    {"ProblemShortName", "optimize --problem P2 --T0 0.1 --json", 0, "\"problem\":\"forcing\""},
    {"ProblemShortNameLowerCase", "optimize --problem p1 --A 0.2 --c 0.03 --json", 0,
     "\"problem\":\"phase\""},
};

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

INSTANTIATE_TEST_SUITE_P(Table, HelpCli, ::testing::ValuesIn(kHelpCases),
                         [](const ::testing::TestParamInfo<HelpCase>& info) {
                           return std::string(info.param.name);
                         });

}  // namespace
}  // namespace capsubot
