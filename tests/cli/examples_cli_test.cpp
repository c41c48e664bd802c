// The examples at the end of each command's help run: each is run as printed, in a scratch
// directory of its own. An example whose description says it "takes about" a while is stopped after
// kLongExampleSeconds: still running then means its command line was accepted (bad input
// exits with status 2 before any work, docs/errors.md).

#include <gtest/gtest.h>

#include <string>

#include "cli/cli_text.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

constexpr int kLongExampleSeconds = 3;
constexpr int kShortExampleSeconds = 300;  // far above what any short example needs
constexpr int kTimedOut = 124;             // the exit status of timeout(1) when it stopped one

// The input files the examples read, made in `dir`: the shards of a sweep that `merge` joins.
void MakeInputs(const std::string& dir) {
  for (int k = 0; k < 3; ++k) {
    const auto r = testing::RunCli(
        "sweep --grid phi0=-3:-2.4:6 --A 0.05 --c 0.02 --T0 0.1 --shard " + std::to_string(k) +
        "/3 -o " + dir + "/part" + std::to_string(k) + ".csv 2>&1");
    ASSERT_EQ(r.status, 0) << r.out;
  }
}

TEST(HelpExamples, EveryExampleRuns) {
  int examples = 0;
  for (const std::string& command : testing::HelpCommands()) {
    for (const testing::HelpExample& example : testing::HelpExamples(command, 200)) {
      SCOPED_TRACE(example.command);
      testing::ScratchDir dir;
      ASSERT_FALSE(dir.path().empty());
      MakeInputs(dir.path());
      const std::string program = "capsubot ";
      ASSERT_EQ(example.command.rfind(program, 0), 0u);
      const bool long_run = example.what.find("takes about") != std::string::npos;
      const int seconds = long_run ? kLongExampleSeconds : kShortExampleSeconds;
      const auto r = testing::RunShell("cd " + dir.path() + " && timeout -s INT " +
                                       std::to_string(seconds) + " " + CAPSUBOT_CLI + " " +
                                       example.command.substr(program.size()) + " 2>&1");
      if (long_run && r.status == kTimedOut) continue;
      EXPECT_EQ(r.status, 0) << r.out;
      ++examples;
    }
  }
  EXPECT_GE(examples, 15);  // all but the long ones run to the end
}

}  // namespace
}  // namespace capsubot
