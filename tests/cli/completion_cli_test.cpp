// The bash completion the build wrote (capsubot.bash, installed as
// share/bash-completion/completions/capsubot) proposes every command and, for each command,
// exactly the flags its help lists, and the values of the flags that have a few or name a file.

#include <gtest/gtest.h>

#include <algorithm>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_text.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

// The words bash's completion function proposes for the command line `words` completed at its
// last word (COMP_CWORD), run in `dir`; sorted.
std::vector<std::string> Complete(const std::string& words, const std::string& dir = "/tmp") {
  const std::string script = "source '" + std::string(CAPSUBOT_COMPLETION) + "'; COMP_WORDS=(" +
                             words +
                             "); COMP_CWORD=$((${#COMP_WORDS[@]} - 1)); _capsubot; "
                             "printf '%s\\n' \"${COMPREPLY[@]}\"";
  const auto r = testing::RunShell("cd " + dir + " && bash 2>&1 <<'EOF'\n" + script + "\nEOF\n");
  EXPECT_EQ(r.status, 0) << r.out;
  std::vector<std::string> proposed;
  for (const std::string& line : testing::Lines(r.out)) {
    if (!line.empty()) proposed.push_back(line);
  }
  std::sort(proposed.begin(), proposed.end());
  return proposed;
}

std::vector<std::string> Sorted(std::vector<std::string> words) {
  std::sort(words.begin(), words.end());
  return words;
}

TEST(Completion, ProposesEveryCommandAndTheProgramsFlags) {
  std::vector<std::string> expected = testing::HelpCommands();
  ASSERT_GE(expected.size(), 12u);
  for (const char* flag : {"-h", "--help", "--help-all", "--version"}) expected.emplace_back(flag);
  EXPECT_EQ(Complete("capsubot ''"), Sorted(expected));
  EXPECT_EQ(Complete("capsubot swe"), std::vector<std::string>{"sweep"});
  EXPECT_EQ(Complete("capsubot help bif"), std::vector<std::string>{"bifurcation"});
}

// For each command: after a dash, exactly the flags of its help (so a flag added to the
// program without its completion, or the reverse, fails here).
TEST(Completion, ProposesExactlyTheFlagsOfEachCommandsHelp) {
  for (const std::string& command : testing::HelpCommands()) {
    const std::vector<std::string> flags = Sorted(testing::HelpFlags(command));
    ASSERT_GE(flags.size(), 2u) << command;  // at least -h, --help
    EXPECT_EQ(Complete("capsubot " + command + " -"), flags) << command;
  }
  const std::vector<std::string> sweep = Complete("capsubot sweep --");
  for (const char* flag : {"--grid", "--optimize", "--shard", "--progress", "--no-progress"}) {
    EXPECT_NE(std::find(sweep.begin(), sweep.end(), flag), sweep.end()) << flag;
  }
}

TEST(Completion, ProposesTheValuesOfAFlagThatHasAFewOrNamesAFile) {
  EXPECT_EQ(Complete("capsubot sweep --optimize ''"),
            Sorted({"phi0", "forcing", "fourier", "reach"}));
  EXPECT_EQ(Complete("capsubot optimize --problem f"), Sorted({"forcing", "fourier"}));
  EXPECT_EQ(Complete("capsubot optimize --rho-max ''"), std::vector<std::string>{"inf"});
  testing::ScratchDir dir;
  std::ofstream(dir.path() + "/results.csv") << "x\n";
  EXPECT_EQ(Complete("capsubot sweep -o res", dir.path()), std::vector<std::string>{"results.csv"});
  EXPECT_EQ(Complete("capsubot merge out.csv res", dir.path()),
            std::vector<std::string>{"results.csv"});
  EXPECT_TRUE(Complete("capsubot sweep --A ''", dir.path()).empty());  // a number to type
}

// The script the build installs is the one the program writes.
TEST(Completion, TheBuildsScriptIsTheProgramsOwn) {
  std::ifstream in(CAPSUBOT_COMPLETION);
  std::ostringstream built;
  built << in.rdbuf();
  const auto r = testing::RunCli("completion bash");
  ASSERT_EQ(r.status, 0);
  EXPECT_EQ(built.str(), r.out);
}

}  // namespace
}  // namespace capsubot
