// Every JSON output of `capsubot` carries its provenance: the program, its version, the command
// and the value of every option that determines the content (docs/errors.md, "Provenance of
// the outputs"). One row per command that writes JSON.

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <string>
#include <vector>

#include "capsubot/version.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::RunCli;

struct ProvenanceCase {
  const char* name;
  const char* command;  ///< the subcommand
  std::string args;     ///< its options, --json included
  const char* option;   ///< a non-default option the provenance must record ...
  const char* value;    ///< ... with this value ("" for a flag)
  /// Options given that must not be recorded (they do not change the content).
  std::vector<std::string> absent;
  friend void PrintTo(const ProvenanceCase& c, std::ostream* os) { *os << c.name; }
};

class ProvenanceCli : public ::testing::TestWithParam<ProvenanceCase> {};

TEST_P(ProvenanceCli, JsonRecordsTheVersionCommandAndOptions) {
  const ProvenanceCase& c = GetParam();
  const auto r = RunCli(std::string(c.command) + " " + c.args);
  ASSERT_EQ(r.status, 0) << r.out;
  const auto j = nlohmann::json::parse(r.out);
  ASSERT_TRUE(j.contains("provenance")) << r.out;
  const auto& p = j["provenance"];
  EXPECT_EQ(p["program"], "capsubot");
  EXPECT_EQ(p["version"], Version());
  EXPECT_EQ(p["command"], c.command);
  const std::string line = p["command_line"];
  EXPECT_EQ(line.rfind(std::string("capsubot ") + Version() + " " + c.command + " ", 0), 0U)
      << line;
  const auto& options = p["options"];
  ASSERT_TRUE(options.contains(c.option)) << options.dump();
  const auto expected =
      *c.value == '\0' ? nlohmann::json::array() : nlohmann::json::array({std::string(c.value)});
  EXPECT_EQ(options[c.option], expected) << options.dump();
  EXPECT_NE(line.find(c.option), std::string::npos) << line;
  for (const std::string& name : c.absent) {
    EXPECT_FALSE(options.contains(name)) << name << " in " << options.dump();
  }
  EXPECT_FALSE(options.contains("--json"));
}

const std::string kOrbit = "--A 0.05 --c 0.02 --phi0 -2.842 --T0 0.1 --e 0.5";
const std::string kRobot = kOrbit + " --alpha 0.2792869076315278";

std::vector<ProvenanceCase> Cases() {
  const std::string basins_csv = testing::TempPath("capsubot_provenance_basins.csv").string();
  return {
      {"Solve",
       "solve",
       kOrbit + " --stability --from-rest-starts 2x2 --threads 1 --json",
       "--from-rest-starts",
       "2x2",
       {"--threads"}},
      // Without --stability the orbit is not checked from rest: the grid of that check is out.
      {"SolveWithoutStability", "solve", kOrbit + " --json", "--T0", "0.1", {"--from-rest-starts"}},
      {"Simulate", "simulate", kOrbit + " --from-orbit --periods 3 --json", "--periods", "3", {}},
      {"SimulateFlag", "simulate", kOrbit + " --from-orbit --json", "--from-orbit", "", {}},
      {"Orbits",
       "orbits",
       "--A 0.05 --c 0.02 --T0 0.1 --e 0.5 --alpha 0.28 --json",
       "--alpha",
       "0.28",
       {}},
      // Options the chosen problem does not use are left out, defaults or not.
      {"Optimize",
       "optimize",
       "--problem phase --A 0.2 --c 0.03 --from-rest-starts 1x1 --threads 1 --json",
       "--from-rest-starts",
       "1x1",
       {"--threads", "--harmonics", "--hops", "--reach-starts", "--global-evaluations"}},
      {"Attractors",
       "attractors",
       kRobot + " --starts 2x2 --transient 40 --record 16 --threads 1 --json",
       "--starts",
       "2x2",
       {"--threads"}},
      {"Basins",
       "basins",
       kRobot + " --starts 2x2 --transient 40 --record 16 -o " + basins_csv + " --json",
       "--transient",
       "40",
       {"--output"}},
      {"Periodic",
       "periodic",
       kRobot + " --from-rest 0.5,1 --transient 60 --json",
       "--from-rest",
       "0.5,1",
       {}},
      {"Design",
       "design",
       "--m1 0.2 --L 0.02 --mu 0.3 --e 0.7 --force-amplitude 0.5 --force-bias 0.1 --frequency "
       "20 --json",
       "--frequency",
       "20",
       {}},
  };
}

INSTANTIATE_TEST_SUITE_P(EveryJsonOutput, ProvenanceCli, ::testing::ValuesIn(Cases()),
                         [](const auto& info) { return std::string(info.param.name); });

// The JSON file of `optimize -o` carries the same provenance as the printed object.
TEST(ProvenanceCli, OptimizeFileHasTheProvenanceOfTheOutput) {
  const auto path = testing::TempPath("capsubot_provenance_optimize.json");
  const auto r = RunCli("optimize --problem phase --A 0.2 --c 0.03 --from-rest-starts 1x1 -o " +
                        path.string() + " --json");
  ASSERT_EQ(r.status, 0) << r.out;
  std::ifstream file(path);
  const auto written = nlohmann::json::parse(file);
  EXPECT_EQ(written["provenance"], nlohmann::json::parse(r.out)["provenance"]);
  EXPECT_FALSE(written["provenance"]["options"].contains("--output"));
  std::filesystem::remove(path);
}

// The provenance does not depend on the thread count: the outputs stay byte-identical.
TEST(ProvenanceCli, OutputIsTheSameForAnyThreadCount) {
  const std::string args =
      "attractors " + kRobot + " --starts 2x2 --transient 40 --record 16 --json";
  const auto one = RunCli(args + " --threads 1");
  const auto two = RunCli(args + " --threads 2");
  ASSERT_EQ(one.status, 0) << one.out;
  EXPECT_EQ(one.out, two.out);
}

}  // namespace
}  // namespace capsubot
