// --progress: plain progress lines on stderr (no carriage returns) with the time elapsed and
// left, also when stderr is a file (a Slurm log); by default or with --no-progress nothing
// there; the output files the same either way.

#include <gtest/gtest.h>

#include <fstream>
#include <regex>
#include <sstream>
#include <string>
#include <vector>

#include "cli/cli_text.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::ReadFile;

// `capsubot <args>` with stderr into `dir`/err (a file, not a terminal); returns stderr.
std::string RunStderrToFile(const std::string& dir, const std::string& args, int* status) {
  const auto r =
      testing::RunShell("cd " + dir + " && " + CAPSUBOT_CLI + " " + args + " > /dev/null 2> err");
  *status = r.status;
  return ReadFile(dir + "/err");
}

struct ProgressCase {
  const char* name;
  const char* args;  // a small run of a command with counted progress, writing into its folder
  const char* unit;  // what its lines count
  int total;         // how many of them
  int least_lines;   // at least this many lines: one every 5 % of a run in many blocks
  friend void PrintTo(const ProgressCase& c, std::ostream* os) { *os << c.name; }
};

class ProgressLines : public ::testing::TestWithParam<ProgressCase> {};

// "capsubot sweep:  45%  1800/4000 points  00:00 elapsed  00:01 left", rising to 100 %.
TEST_P(ProgressLines, ArePlainLinesWithTheTimeElapsedAndLeft) {
  const ProgressCase& c = GetParam();
  testing::ScratchDir dir;
  int status = -1;
  const std::string err = RunStderrToFile(dir.path(), std::string(c.args) + " --progress", &status);
  ASSERT_EQ(status, 0) << err;
  EXPECT_EQ(err.find('\r'), std::string::npos) << err;
  const std::string command = std::string(c.args).substr(0, std::string(c.args).find(' '));
  const std::regex line("capsubot " + command + ": +([0-9]+)%  ([0-9]+)/" +
                        std::to_string(c.total) + " " + c.unit +
                        "  [0-9][0-9]:[0-9][0-9] elapsed  ([0-9][0-9]:[0-9][0-9]|--:--) left");
  int lines = 0, last_percent = -1, last_done = -1;
  for (const std::string& text : testing::Lines(err)) {
    std::smatch m;
    if (!std::regex_match(text, m, line)) continue;  // a summary line after the last
    const int percent = std::stoi(m[1]);
    EXPECT_GT(percent, last_percent) << err;
    last_percent = percent;
    last_done = std::stoi(m[2]);
    ++lines;
  }
  EXPECT_GE(lines, c.least_lines) << err;
  EXPECT_EQ(last_percent, 100) << err;
  EXPECT_EQ(last_done, c.total) << err;
}

const ProgressCase kProgressCases[] = {
    {"Sweep", "sweep --grid phi0=-pi:pi:4000 --A 0.5 --c 0.5 --threads 1 -o a.csv", "points", 4000,
     5},  // in 8 blocks of 500 points on one thread
    {"Attractors",
     "attractors --A 0.05 --c 0.02 --phi0 -2.842 --T0 0.1 --e 0.5 --alpha 0.2792869076315278 "
     "--starts 8x8 --threads 1",
     "starts", 64, 1},
    {"Basins",
     "basins --A 0.05 --c 0.02 --phi0 -2.842 --T0 0.1 --e 0.5 --alpha 0.2792869076315278 "
     "--starts 8x8 --threads 1 -o b.csv",
     "starts", 64, 1},
    {"Bifurcation",
     "bifurcation --A 0.05 --c 0.02 --phi0 -2.842 --e 0.5 --alpha 0.2792869076315278 --param T0 "
     "--from 0.08 --to 0.12 --steps 4 --transient 40 --record 20 -o i.csv",
     "parameter values", 8, 1},  // 4 values up and down
};

INSTANTIATE_TEST_SUITE_P(Table, ProgressLines, ::testing::ValuesIn(kProgressCases),
                         [](const ::testing::TestParamInfo<ProgressCase>& info) {
                           return std::string(info.param.name);
                         });

// Without --progress stderr is quiet when it is not a terminal (as before --progress existed),
// and --no-progress too; the CSV is the same with or without progress (its provenance line
// leaves the progress flags out).
TEST(Progress, NoneByDefaultOrWithNoProgressAndTheFileIsTheSame) {
  testing::ScratchDir dir;
  const std::string sweep = "sweep --grid phi0=-pi:pi:50 --A 0.5 --c 0.5 -o ";
  int status = -1;
  RunStderrToFile(dir.path(), sweep + "shown.csv --progress", &status);
  ASSERT_EQ(status, 0);
  EXPECT_EQ(RunStderrToFile(dir.path(), sweep + "default.csv", &status), "");
  EXPECT_EQ(status, 0);
  EXPECT_EQ(RunStderrToFile(dir.path(), sweep + "quiet.csv --no-progress", &status), "");
  EXPECT_EQ(status, 0);
  const std::string shown = ReadFile(dir.path() + "/shown.csv");
  EXPECT_NE(shown.find("\n-3.141592653589793,"), std::string::npos) << shown;
  EXPECT_EQ(ReadFile(dir.path() + "/default.csv"), shown);
  EXPECT_EQ(ReadFile(dir.path() + "/quiet.csv"), shown);
}

TEST(Progress, ProgressAndNoProgressExcludeEachOther) {
  const auto r =
      testing::RunCli("sweep --grid phi0=0:1:2 --A 0.5 --c 0.5 -o - --progress --no-progress 2>&1");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("progress excludes --"), std::string::npos) << r.out;
}

// A command that runs in stages (optimize) prints a line per stage with the time elapsed.
TEST(Progress, StagesAreLinesWithTheTimeElapsed) {
  testing::ScratchDir dir;
  int status = -1;
  const std::string err =
      RunStderrToFile(dir.path(), "optimize --problem phase --A 0.2 --c 0.03 --progress", &status);
  ASSERT_EQ(status, 0) << err;
  const std::vector<std::string> lines = testing::Lines(err);
  ASSERT_EQ(lines.size(), 2u) << err;
  const std::regex elapsed(".*  [0-9][0-9]:[0-9][0-9] elapsed");
  EXPECT_EQ(lines[0].rfind("capsubot optimize: --problem phase  ", 0), 0u) << err;
  EXPECT_EQ(lines[1].rfind("capsubot optimize: the optimum checked from rest", 0), 0u) << err;
  for (const std::string& line : lines) EXPECT_TRUE(std::regex_match(line, elapsed)) << line;
}

}  // namespace
}  // namespace capsubot
