// What made an output (capsubot/cli/provenance.hpp): the options that shape the content, in the
// command's order, as a command line that reproduces it and as JSON; the options that only
// change how or where the work is done are left out.

#include "capsubot/cli/provenance.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <utility>
#include <vector>

#include "capsubot/model/version.hpp"

namespace capsubot::cli {
namespace {

using Options = std::vector<std::pair<std::string, std::string>>;

// A command like the program's: a value with a default, a list, a flag, an option that needs
// another, the threads and an output file; parsed from `args` (in their order).
struct Command {
  CLI::App app{"test", "run"};
  double A = 0.5, rho_max = 1;
  std::vector<std::string> grid;
  bool stable = false;
  int samples = 100;
  int threads = 0;
  std::string output;

  explicit Command(std::vector<std::string> args) {
    app.add_option("--A", A)->capture_default_str();
    app.add_option("--grid", grid);
    app.add_flag("--stable", stable);
    CLI::Option* optimize = app.add_flag("--optimize");
    app.add_option("--rho-max", rho_max)->capture_default_str()->needs(optimize);
    app.add_option("--threads", threads)->capture_default_str();
    app.add_option("-o,--output", output);
    app.add_option("--samples", samples)->capture_default_str();
    std::reverse(args.begin(), args.end());
    app.parse(args);
  }
};

TEST(Provenance, GivenValuesAndDefaultsInTheCommandsOrder) {
  const Command c({"--grid", "phi0=-pi:pi:5", "--grid", "e=0:1:3", "--stable", "--threads", "2"});
  EXPECT_EQ(CommandProvenance(c.app, {}).options,
            (Options{{"--A", "0.5"},
                     {"--grid", "phi0=-pi:pi:5"},
                     {"--grid", "e=0:1:3"},
                     {"--stable", ""},
                     {"--threads", "2"},
                     {"--samples", "100"}}));  // --rho-max: its default needs --optimize
}

TEST(Provenance, AnOutputLeavesOutWhatDoesNotShapeIt) {
  const Command c(
      {"--A", "0.25", "--stable", "--threads", "2", "-o", "out file.csv", "--optimize"});
  const Provenance p = OutputProvenance(c.app, {"--stable"});  // given, but unused
  EXPECT_EQ(
      p.options,
      (Options{{"--A", "0.25"}, {"--optimize", ""}, {"--rho-max", "1"}, {"--samples", "100"}}));
  EXPECT_EQ(p.CommandLine(), std::string("capsubot ") + Version() +
                                 " run --A 0.25 --optimize --rho-max 1 --samples 100");
  EXPECT_EQ(p.CommentLine(), "# " + p.CommandLine() + "\n");
  // The JSON of a result leaves out what shapes only the CSV files too (--samples).
  EXPECT_EQ(JsonProvenance(c.app).options,
            (Options{{"--A", "0.25"}, {"--stable", ""}, {"--optimize", ""}, {"--rho-max", "1"}}));
}

TEST(Provenance, AValueThatIsNotOneShellWordIsQuoted) {
  const Provenance p{"run", {{"--grid", "a b"}, {"--name", "it's"}, {"--x", "-1.5e-3"}}};
  EXPECT_EQ(p.CommandLine(), std::string("capsubot ") + Version() +
                                 " run --grid 'a b' --name 'it'\\''s' --x -1.5e-3");
  const nlohmann::json j = p.Json();
  EXPECT_EQ(j["command"], "run");
  EXPECT_EQ(j["options"]["--grid"], nlohmann::json::array({"a b"}));
  EXPECT_EQ(j["command_line"], p.CommandLine());
}

}  // namespace
}  // namespace capsubot::cli
