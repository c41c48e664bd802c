// The one syntax of option values (capsubot/cli/strict_values.hpp), on a command built here:
// numbers as ParseNumber reads them, "inf" only where allowed, phases with multiples of pi,
// integers in their range, no empty value, and --threads capped.

#include "capsubot/cli/strict_values.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>
#include <string>
#include <vector>

#include "capsubot/model/forcing.hpp"
#include "capsubot/model/limits.hpp"

namespace capsubot::cli {
namespace {

// A command with one option of each kind, its values read from `args` ("--x", "1", ...).
struct Parsed {
  double x = 0, bound = 0, phase = 0;
  int n = 0, size = 0, threads = 0;
  std::string text = "unset";
};

Parsed Parse(std::vector<std::string> args) {
  Parsed p;
  CLI::App app{"test"};
  app.add_option("--x", p.x);
  app.add_option("--bound", p.bound)->type_name(kFloatOrInf);
  app.add_option("--phase", p.phase)->type_name(kPhase);
  app.add_option("--n", p.n);
  Bounded(app.add_option("--size", p.size), 1, 5);
  app.add_option("--text", p.text);
  AddThreadsOption(app, p.threads);
  UseStrictValues(app);
  std::reverse(args.begin(), args.end());  // CLI11 takes the arguments last first
  app.parse(args);
  return p;
}

// The message of the refusal of `args`; empty when they are read.
std::string Refusal(const std::vector<std::string>& args) {
  try {
    Parse(args);
    return "";
  } catch (const CLI::ParseError& e) {
    return e.what();
  }
}

TEST(StrictValues, ReadsNumbersInTheLibrarysSyntax) {
  EXPECT_EQ(Parse({"--x", "1e3"}).x, 1000.0);
  EXPECT_EQ(Parse({"--x", "-0.25"}).x, -0.25);
  EXPECT_EQ(Parse({"--bound", "inf"}).bound, std::numeric_limits<double>::infinity());
  EXPECT_EQ(Parse({"--phase", "-pi/2"}).phase, -kTau / 4);
  EXPECT_EQ(Parse({"--n", "2e3"}).n, 2000);  // a whole number written as a float
  EXPECT_EQ(Parse({"--size", "5"}).size, 5);
  EXPECT_EQ(Parse({"--text", "a b"}).text, "a b");
}

TEST(StrictValues, RefusesWhatIsNotAValueOfItsKindNamingTheOption) {
  struct Case {
    std::vector<std::string> args;
    const char* said;  // a part of the message
  };
  const std::vector<Case> cases = {
      {{"--x", "abc"}, "--x = abc is invalid"},
      {{"--x", "nan"}, "--x = nan is invalid"},
      {{"--x", "inf"}, "--x = inf is invalid"},  // only --bound takes inf
      {{"--x", "1e400"}, "--x = 1e400 is invalid"},
      {{"--x", ""}, "--x = '' is invalid"},
      {{"--phase", "pi/0"}, "--phase = pi/0 is invalid"},
      {{"--n", "2.5"}, "--n = 2.5 is invalid"},
      {{"--size", "6"}, "--size = 6 is invalid: expected an integer 1 <= n <= 5"},
      {{"--size", "0"}, "--size = 0 is invalid: expected an integer 1 <= n <= 5"},
      {{"--text", ""}, "--text = '' is invalid: expected a value"},
      {{"--threads", "-1"}, "--threads = -1 is invalid"},
  };
  for (const Case& c : cases) {
    const std::string refusal = Refusal(c.args);
    EXPECT_NE(refusal.find(c.said), std::string::npos)
        << c.args[0] << " " << c.args[1] << ": " << refusal;
  }
}

TEST(StrictValues, ThreadsAboveTheCapAreLoweredToIt) {
  EXPECT_EQ(Parse({"--threads", "0"}).threads, 0);
  EXPECT_EQ(Parse({"--threads", "1"}).threads, 1);
  const int many = kMaxThreads * 4;
  EXPECT_EQ(Parse({"--threads", std::to_string(many)}).threads, capsubot::CapThreads(many));
  EXPECT_LT(capsubot::CapThreads(many), many);  // the case checks a lowering
}

}  // namespace
}  // namespace capsubot::cli
