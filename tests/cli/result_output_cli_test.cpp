// -o FILE of the commands that print one result (solve, simulate, orbits, periodic, design):
// the file holds exactly what the command prints without -o (the text, or the JSON object
// with --json), standard output then holds nothing, and -o - is standard output.

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

#include "cli/cli_text.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::ReadFile;
using testing::RunCli;

// One quick run of every command that prints one result.
const std::vector<std::string> kRuns = {
    "solve --A 0.05 --c 0.02 --phi0 -2.842 --T0 0.1 --e 0.5",
    "simulate --A 0.5 --c 0.5 --phi0 0 --alpha 0.5 --x0 0.5 --u0 0 --v0 0 --periods 20",
    "orbits --A 0.05 --c 0.02 --T0 0.1 --e 0.5 --alpha 0.28",
    "periodic --A 0.34063197373861814 --c 0.06410131873607934 --phi0 -3.1181183398453047 "
    "--alpha 0.6435592358295166 --T0 1 --e 1 --from-rest 0.5,1",
    "design --m1 0.2 --L 0.02 --mu 0.3 --e 0.7 --force-amplitude 0.5 --force-bias 0.1 "
    "--frequency 20",
};

TEST(ResultOutput, TheFileHoldsWhatTheCommandPrints) {
  ASSERT_FALSE(kRuns.empty());
  testing::ScratchDir dir;
  const std::string file = dir.path() + "/result";
  for (const std::string& run : kRuns) {
    for (const std::string json : {"", " --json"}) {
      const auto printed = RunCli(run + json);
      ASSERT_EQ(printed.status, 0) << run << json << "\n" << printed.out;
      ASSERT_FALSE(printed.out.empty()) << run << json;
      const auto written = RunCli(run + json + " -o " + file);
      ASSERT_EQ(written.status, 0) << run << json << "\n" << written.out;
      EXPECT_EQ(written.out, "") << run << json;
      EXPECT_EQ(ReadFile(file), printed.out) << run << json;
      const auto dash = RunCli(run + json + " -o -");
      EXPECT_EQ(dash.out, printed.out) << run << json;
      std::filesystem::remove(file);
    }
  }
}

TEST(ResultOutput, AFileThatCannotBeWrittenIsRefusedBeforeTheWork) {
  testing::ScratchDir dir;
  const auto r = RunCli(
      "design --m1 0.2 --L 0.02 --mu 0.3 --e 0.7 --force-amplitude 0.5 "
      "--force-bias 0.1 --frequency 20 --json -o " +
      dir.path() + "/missing/d.json 2>&1");
  EXPECT_EQ(r.status, 2) << r.out;
  EXPECT_EQ(r.out.rfind("capsubot design: error: -o " + dir.path() + "/missing/d.json", 0), 0U)
      << r.out;
  EXPECT_EQ(r.out.find('\n'), r.out.size() - 1) << r.out;
}

}  // namespace
}  // namespace capsubot
