// Every output of `capsubot` carries its provenance: the program, its version, the command and
// the value of every option that determines the content (docs/errors.md, "Provenance of the
// outputs"). One row per command that writes JSON; one row per CSV file a command writes: the
// file starts with the provenance line, reads as a table (here, by gnuplot) and is made again
// by the command of its line; written to standard output it is the same.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <algorithm>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <vector>

#include "capsubot/model/version.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::CommandResult;
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
// A robot driven by a pulse force (tests/cli/pulse_cli_test.cpp); --switches in the syntax of a
// phase, recorded as given.
const std::string kPulseRobot = "--levels 0.3,-0.05 --switches 0,pi/2 --T0 0.1 --e 0.5 --alpha 0.3";

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
      {"SimulatePulse",
       "simulate",
       kPulseRobot + " --x0 0.5 --u0 0 --v0 0 --periods 3 --json",
       "--levels",
       "0.3,-0.05",
       {"--A", "--c", "--phi0", "--sin"}},
      {"AttractorsPulse",
       "attractors",
       kPulseRobot + " --starts 2x2 --transient 40 --record 16 --threads 1 --json",
       "--switches",
       "0,pi/2",
       {"--A", "--c", "--threads"}},
      {"PeriodicPulse",
       "periodic",
       kPulseRobot + " --waveform pulse --from-rest 0.5,1 --transient 60 --json",
       "--waveform",
       "pulse",
       {"--c"}},
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
      // The reach problem of the sine runs no drive search: its budgets are left out.
      {"OptimizeReachSine",
       "optimize",
       "--problem reach --from-rest-starts 2x2 --reach-starts 2x2 --reach-evaluations 10 "
       "--reach-local-evaluations 5 --hops 2 --starts 3 --json",
       "--reach-evaluations",
       "10",
       {"--drive-evaluations", "--drive-polishes", "--drive-local-evaluations",
        "--drive-refine-evaluations", "--drive-screens", "--pulse-levels"}},
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

std::string ReadAll(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

// The words of a command line (no value of these tests holds a space).
std::vector<std::string> Words(const std::string& line) {
  std::istringstream in(line);
  std::vector<std::string> words;
  for (std::string w; in >> w;) words.push_back(w);
  return words;
}

// The number of cells of a CSV line.
long Cells(const std::string& line) { return std::count(line.begin(), line.end(), ',') + 1; }

struct CsvCase {
  const char* name;
  const char* command;  ///< the subcommand
  std::string args;     ///< its options but the CSV's path
  const char* output;   ///< the option that names the CSV ("-o", "--trajectory", ...)
  std::string others;   ///< the paths of the run's other files ("-o FILE" of --summary, ...)
  const char* header;   ///< the beginning of the header line
  const char* column;   ///< a column that holds a number in every row (read by gnuplot)
  std::vector<std::string> recorded;  ///< "--option value" the line must hold
  std::vector<std::string> absent;    ///< options given that the line must not hold
  friend void PrintTo(const CsvCase& c, std::ostream* os) { *os << c.name; }
};

// The CSV of case `c` written to `path`; `others`: the run's other files.
CommandResult WriteCsv(const CsvCase& c, const std::string& path) {
  return RunCli(std::string(c.command) + " " + c.args + " " + c.others + " " + c.output + " " +
                path + " 2>&1");
}

// The other file of a run that writes two (-o of --summary, --trajectory of --events). The
// merges of shards of these commands are tested in cluster_cli_test.cpp (sweep, basins,
// attractors, bifurcation) and design_cli_test.cpp (design --grid).
const std::string kOther = testing::TempPath("capsubot_provenance_other.csv").string();
const std::string kQuickReach =
    " --from-rest-starts 2x2 --reach-starts 2x2 --reach-evaluations 10 "
    "--reach-local-evaluations 5 --hops 2 --starts 3";
const std::string kStudy =
    kRobot + " --param T0 --from 0.08 --to 0.12 --steps 3 --transient 40 --record 16";

std::vector<CsvCase> CsvCases() {
  return {
      {"Basins",
       "basins",
       kRobot + " --starts 2x2 --transient 40 --record 16 --threads 1",
       "-o",
       "",
       "x0,psi,attractor,",
       "x0",
       {"--starts 2x2", "--plane x0-psi"},
       {"--threads", "--output", "-o"}},
      {"BasinsPulse",
       "basins",
       kPulseRobot + " --starts 2x2 --transient 40 --record 16 --threads 1",
       "-o",
       "",
       "x0,psi,attractor,",
       "x0",
       {"--levels 0.3,-0.05", "--switches 0,pi/2"},
       {"--threads", "--output", "-o", "--A", "--c"}},
      {"BifurcationPulse",
       "bifurcation",
       kPulseRobot + " --param e --from 0.4 --to 0.5 --steps 2 --transient 40 --record 16",
       "--summary",
       "-o " + kOther,
       "param,direction,period,",
       "param",
       {"--levels 0.3,-0.05", "--switches 0,pi/2", "--param e"},
       {"--summary", "--output", "-o", "--c"}},
      {"AttractorsMap",
       "attractors",
       kRobot + " --starts 2x2 --transient 40 --record 16 --json",
       "-o",
       "",
       "x0,psi,attractor,",
       "x0",
       {"--starts 2x2"},
       {"--json", "--output", "-o"}},
      {"BifurcationImpacts",
       "bifurcation",
       kStudy,
       "-o",
       "",
       "param,direction,period_index,",
       "param",
       {"--param T0", "--steps 3"},
       {"--output", "-o"}},
      {"BifurcationSummary",
       "bifurcation",
       kStudy,
       "--summary",
       "-o " + kOther,
       "param,direction,period,",
       "param",
       {"--from 0.08"},
       {"--summary", "--output", "-o"}},
      // The trajectory of the orbit: not its check (margins, stability, starts from rest).
      {"SolveTrajectory",
       "solve",
       kOrbit + " --stability --from-rest-starts 2x2 --samples 11 --json",
       "--trajectory",
       "",
       "phi,x,u,v",
       "phi",
       {"--samples 11", "--T0 0.1"},
       {"--json", "--stability", "--from-rest-starts", "--margin", "--trajectory"}},
      {"SimulateTrajectory",
       "simulate",
       kOrbit + " --from-orbit --periods 2 --samples-per-period 10",
       "--trajectory",
       "",
       "phi,x,u,v,y,mode",
       "phi",
       {"--samples-per-period 10", "--periods 2"},
       {"--trajectory"}},
      // The events do not depend on the trajectory's grid: the line leaves it out.
      {"SimulatePulseTrajectory",
       "simulate",
       kPulseRobot + " --x0 0.5 --u0 0 --v0 0 --periods 2 --samples-per-period 10",
       "--trajectory",
       "",
       "phi,x,u,v,y,mode",
       "phi",
       {"--levels 0.3,-0.05", "--switches 0,pi/2"},
       {"--trajectory", "--c"}},
      {"SimulateEvents",
       "simulate",
       kOrbit + " --from-orbit --periods 2 --samples-per-period 10",
       "--events",
       "--trajectory " + kOther,
       "phase,kind,x,",
       "phase",
       {"--periods 2"},
       {"--samples-per-period", "--trajectory", "--events"}},
      {"OptimizeFromRest",
       "optimize",
       kQuickReach + " --json",
       "--from-rest-csv",
       "",
       "gait,row,mean_velocity,",
       "period",
       {"--reach-starts 2x2", "--starts 3"},
       {"--json", "--from-rest-csv"}},
      {"OptimizeForce",
       "optimize",
       "--problem phase --A 0.2 --c 0.03 --from-rest-starts 1x1 --json",
       "--force-csv",
       "",
       "phi,F",
       "F",
       {"--A 0.2"},
       {"--json", "--force-csv", "--harmonics"}},
      {"Sweep",
       "sweep",
       "--grid phi0=-pi:pi:5 --A 0.5 --c 0.5 --threads 1",
       "-o",
       "",
       "phi0,phi1,",
       "phi0",
       {"--grid phi0=-pi:pi:5"},
       {"--threads", "--output", "-o"}},
      {"DesignGrid",
       "design",
       "--m1 0.2 --L 0.02 --mu 0.3 --e 0.7 --force-amplitude 0.5 --force-bias 0.1 --frequency 20 "
       "--grid m2=0.2,0.25 --threads 1",
       "-o",
       "",
       "m2_kg,status,frequency_hz,",
       "m2_kg",
       {"--grid m2=0.2,0.25"},
       {"--threads", "--output", "-o"}},
  };
}

class ProvenanceCsv : public ::testing::TestWithParam<CsvCase> {};

// The rows that gnuplot reads from column `column` of `path`: its comment line skipped, its
// header's names taken (-1 when gnuplot fails; 0 when it is not installed).
long GnuplotRecords(const std::string& path, const std::string& column) {
  if (std::system("command -v gnuplot > /dev/null 2>&1") != 0) return 0;
  const std::string log = path + ".gnuplot";
  const std::string script = "set datafile separator ','; set datafile columnheaders; stats '" +
                             path + "' using '" + column + "' nooutput; print STATS_records";
  const int raw = std::system(("gnuplot -e \"" + script + "\" > " + log + " 2>&1").c_str());
  const std::string out = ReadAll(log);
  std::filesystem::remove(log);
  return WIFEXITED(raw) && WEXITSTATUS(raw) == 0 ? std::stol(out) : -1;
}

TEST_P(ProvenanceCsv, FileStartsWithTheLineOfTheCommandThatMakesItAgain) {
  const CsvCase& c = GetParam();
  const auto path = testing::TempPath(std::string("capsubot_provenance_") + c.name + ".csv");
  const CommandResult r = WriteCsv(c, path.string());
  ASSERT_EQ(r.status, 0) << r.out;
  const std::string text = ReadAll(path);
  const testing::CsvLines csv = testing::SplitCsv(text);
  ASSERT_EQ(csv.comments.size(), 1U) << text.substr(0, 400);
  const std::string& line = csv.comments[0];
  const std::string program = std::string("# capsubot ") + Version() + " ";
  ASSERT_EQ(line.rfind(program + c.command + " ", 0), 0U) << line;
  const std::vector<std::string> words = Words(line);
  for (const std::string& option : c.recorded) {
    EXPECT_NE((" " + line + " ").find(" " + option + " "), std::string::npos)
        << option << " not in " << line;
  }
  for (const std::string& option : c.absent) {
    EXPECT_EQ(std::count(words.begin(), words.end(), option), 0) << option << " in " << line;
  }
  // A table: the header, then rows of as many cells, none a comment.
  EXPECT_EQ(csv.header.rfind(c.header, 0), 0U) << csv.header;
  ASSERT_FALSE(csv.rows.empty());
  for (const std::string& row : csv.rows) {
    EXPECT_EQ(Cells(row), Cells(csv.header)) << row;
    EXPECT_NE(row.front(), '#') << row;
  }
  const long records = GnuplotRecords(path.string(), c.column);
  if (records != 0) {  // 0: no gnuplot here
    EXPECT_EQ(records, static_cast<long>(csv.rows.size())) << c.column;
  }
  // The command of the line (after the program and its version), with a new path, writes the
  // same bytes.
  const auto again = testing::TempPath(std::string("capsubot_provenance_again_") + c.name + ".csv");
  const CommandResult replay = RunCli(line.substr(program.size()) + " " + c.others + " " +
                                      c.output + " " + again.string() + " > /dev/null 2>&1");
  ASSERT_EQ(replay.status, 0) << line;
  EXPECT_TRUE(ReadAll(again) == text) << line;
  std::filesystem::remove(path);
  std::filesystem::remove(again);
  std::filesystem::remove(kOther);
}

// Written to standard output (path -), the file is the same: its provenance line first. The
// run goes without --json (its object would go to standard output too: refused; the file does
// not depend on --json).
TEST_P(ProvenanceCsv, StandardOutputGetsTheSameLines) {
  const CsvCase& c = GetParam();
  const auto path = testing::TempPath(std::string("capsubot_provenance_out_") + c.name + ".csv");
  ASSERT_EQ(WriteCsv(c, path.string()).status, 0);
  const std::string text = ReadAll(path);
  std::string args = c.args;
  const std::size_t json = args.find(" --json");
  if (json != std::string::npos) args.erase(json, std::string(" --json").size());
  const CommandResult printed =
      RunCli(std::string(c.command) + " " + args + " " + c.others + " " + c.output + " -");
  ASSERT_EQ(printed.status, 0) << printed.out;
  EXPECT_EQ(printed.out.rfind(text, 0), 0U) << printed.out.substr(0, 400);
  std::filesystem::remove(path);
  std::filesystem::remove(kOther);
}

INSTANTIATE_TEST_SUITE_P(EveryCsvOutput, ProvenanceCsv, ::testing::ValuesIn(CsvCases()),
                         [](const auto& info) { return std::string(info.param.name); });

// The CSV files of a run that also prints JSON carry the provenance of that JSON, where both
// depend on the same options (the files of `optimize` and of a map of starts).
TEST(ProvenanceCli, CsvLineIsTheJsonCommandLineOfTheSameRun) {
  int checked = 0;
  for (const CsvCase& c : CsvCases()) {
    const std::string name = c.name;
    if (name != "OptimizeForce" && name != "AttractorsMap") continue;
    const auto path = testing::TempPath("capsubot_provenance_json_" + name + ".csv");
    const CommandResult r =
        RunCli(std::string(c.command) + " " + c.args + " " + c.output + " " + path.string());
    ASSERT_EQ(r.status, 0) << r.out;
    const auto j = nlohmann::json::parse(r.out);
    const testing::CsvLines csv = testing::ReadCsv(path);
    ASSERT_EQ(csv.comments.size(), 1U);
    EXPECT_EQ(csv.comments[0], "# " + j["provenance"]["command_line"].get<std::string>());
    std::filesystem::remove(path);
    ++checked;
  }
  EXPECT_EQ(checked, 2);
}

}  // namespace
}  // namespace capsubot
