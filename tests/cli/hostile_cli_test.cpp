// `capsubot` under hostile input and faults, end to end: every row of the table runs the built
// program in a fresh folder of its own and checks the exit status, the one line on stderr
// (a substring of it), what stdout holds, and that the folder holds exactly the expected files
// afterwards (no temporary or half-written file). Signals and progress need a process of their
// own and have their own tests below.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <functional>
#include <regex>
#include <set>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

#include "test_utils.hpp"

extern char** environ;

namespace capsubot {
namespace {

namespace fs = std::filesystem;

const std::string kSolve = "solve --A 0.05 --c 0.02 --phi0 -2.5 --T0 0.1 --e 0.5";
const std::string kSim = "simulate --A 0.5 --c 0.5 --phi0 0 --alpha 0.5 --x0 0.5 --u0 0 --v0 0";
const std::string kSweep = "sweep --grid A=0:1:3 --c 0.5 --phi0 0";
const std::string kOrbits = "orbits --A 0.5 --c 0.5 --alpha 0.5";
// A short bifurcation diagram and a small map of starts of the small stable orbit's robot.
const std::string kRobot =
    "--A 0.05 --c 0.02 --phi0 -2.842 --T0 0.1 --e 0.5 --alpha 0.2792869076315278";
const std::string kBifurcation = "bifurcation " + kRobot +
                                 " --param T0 --from 0.08 --to 0.12 --steps 3 --transient 20 "
                                 "--record 20";
const std::string kContinue =
    "continue " + kRobot + " --from-orbit --param alpha --from 0.2 --to 0.3";

std::string ReadFile(const fs::path& p) {
  std::ifstream in(p);
  return std::string((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
}

std::set<std::string> Listing(const fs::path& dir) {
  std::set<std::string> names;
  for (const auto& entry : fs::directory_iterator(dir)) {
    names.insert(entry.path().filename().string());
  }
  return names;
}

// A folder of its own for one run, removed at the end.
struct Sandbox {
  fs::path root, work;
  explicit Sandbox(const std::string& name) {
    root = testing::TempPath("capsubot_hostile_" + name);
    fs::remove_all(root);
    work = root / "work";
    fs::create_directories(work);
  }
  ~Sandbox() { fs::remove_all(root); }
};

struct Case {
  const char* name;
  std::string args;             // the command line after `capsubot`, run inside the folder
  int status;                   // expected exit status
  std::string message;          // expected in the single line on stderr ("" : stderr empty)
  std::set<std::string> files;  // the folder's files afterwards
  std::string setup = "";       // shell commands run in the folder first
  std::string stdout_to = "";   // redirect of stdout ("": captured and checked)
  std::string stdout_has = "";  // expected in stdout
  std::function<void(const fs::path&)> verify = nullptr;  // more checks on the folder
};

void PrintTo(const Case& c, std::ostream* os) { *os << c.name; }

std::string SymlinkSetup() {
  return "printf 'old\\n' > target.csv && ln -s target.csv link.csv && ln -s link.csv chain.csv";
}

// The symlinks stay links; their target holds the new output.
void LinksKeptTargetWritten(const fs::path& dir, const std::string& first_line) {
  EXPECT_TRUE(fs::is_symlink(dir / "link.csv"));
  EXPECT_TRUE(fs::is_symlink(dir / "chain.csv"));
  EXPECT_EQ(ReadFile(dir / "target.csv").rfind(first_line, 0), 0U) << ReadFile(dir / "target.csv");
}

// Shell commands that write the 2 shards s0.csv, s1.csv of a robot-mode sweep of 4 points:
// points 0 and 1 have no orbit, points 2 and 3 two orbit rows each.
std::string RobotShardsSetup() {
  std::string setup;
  for (const char* k : {"0", "1"}) {
    setup += std::string(setup.empty() ? "" : " && ") + CAPSUBOT_CLI +
             " sweep --grid alpha=0.5,0.3,0.25,0.2 --A 0.05 --c 0.02 --T0 0.1 --e 0.5 -o s" + k +
             ".csv --shard " + k + "/2";
  }
  return setup;
}

// Shell commands that write the 2 shards b0.csv, b1.csv of a 3 x 2 basin map (x0 major:
// b0.csv holds the starts psi = 0, b1.csv those with psi = pi).
std::string BasinShardsSetup() {
  std::string setup;
  for (const char* k : {"0", "1"}) {
    setup += std::string(setup.empty() ? "" : " && ") + CAPSUBOT_CLI + " basins " + kRobot +
             " --starts 3x2 --transient 20 --record 20 -o b" + k + ".csv --shard " + k +
             "/2 > /dev/null";
  }
  return setup;
}

std::vector<Case> Cases() {
  const std::set<std::string> none;
  const std::set<std::string> links = {"target.csv", "link.csv", "chain.csv"};
  const std::string nums = "expected a decimal number such as 0.5, -2 or 1e-3 (no spaces, no hex)";
  return {
      // Output through symlinks: the target is written, the link kept.
      {"SolveTrajectoryThroughSymlink", kSolve + " --samples 3 --trajectory link.csv", 0, "", links,
       SymlinkSetup(), "/dev/null", "",
       [](const fs::path& d) { LinksKeptTargetWritten(d, "# capsubot "); }},
      // -o of a command that prints one result: its JSON (or text) to the link's target.
      {"DesignJsonThroughSymlinkChain",
       "design --m1 0.2 --L 0.02 --mu 0.3 --e 0.7 --force-amplitude 0.5 --force-bias 0.1 "
       "--frequency 20 --json -o chain.csv",
       0, "", links, SymlinkSetup(), "", "",
       [](const fs::path& d) {
         LinksKeptTargetWritten(d, "{\"");
         EXPECT_EQ(ReadFile(d.parent_path() / "stdout.txt"), "");
       }},
      {"SimulateEventsThroughSymlinkChain", kSim + " --events chain.csv", 0, "", links,
       SymlinkSetup(), "/dev/null", "",
       [](const fs::path& d) { LinksKeptTargetWritten(d, "# capsubot "); }},
      {"SweepOutputThroughSymlink", kSweep + " --no-header-comment -o link.csv", 0, "", links,
       SymlinkSetup(), "", "", [](const fs::path& d) { LinksKeptTargetWritten(d, "A,phi1,"); }},
      {"OptimizeOutputThroughSymlink", "optimize --problem phase --A 0.5 --c 0.5 --output link.csv",
       0, "", links, SymlinkSetup(), "/dev/null", "",
       [](const fs::path& d) { LinksKeptTargetWritten(d, "{"); }},
      {"DanglingSymlinkCreatesTarget",
       kSolve + " --samples 3 --trajectory link.csv",
       0,
       "",
       {"link.csv", "new.csv"},
       "ln -s new.csv link.csv",
       "/dev/null",
       "",
       [](const fs::path& d) { EXPECT_TRUE(fs::is_symlink(d / "link.csv")); }},
      {"SymlinkLoopIsAnError",
       kSolve + " --trajectory a",
       2,
       "more than 40 symbolic links",
       {"a", "b"},
       "ln -s b a && ln -s a b"},
      // One file named twice under other spellings: refused before anything is written.
      {"BifurcationSummaryIsOutputThroughSymlink",
       kBifurcation + " -o i.csv --summary il.csv",
       2,
       "--summary = il.csv is invalid: it is the file of -o = i.csv: expected another file",
       {"i.csv", "il.csv"},
       "printf 'old\\n' > i.csv && ln -s i.csv il.csv",
       "",
       "",
       [](const fs::path& d) { EXPECT_EQ(ReadFile(d / "i.csv"), "old\n"); }},
      {"BifurcationSummaryIsOutputDotSlash",
       kBifurcation + " -o i.csv --summary ./i.csv",
       2,
       "--summary = ./i.csv is invalid: it is the file of -o = i.csv",
       {"i.csv"},
       "printf 'old\\n' > i.csv",
       "",
       "",
       [](const fs::path& d) { EXPECT_EQ(ReadFile(d / "i.csv"), "old\n"); }},
      {"SimulateTrajectoryIsEventsThroughParent",
       kSim + " --events e.csv --trajectory sub/../e.csv", 2,
       "--trajectory = sub/../e.csv is invalid: it is the file of --events = e.csv", none},
      {"OptimizeForceCsvIsOutputAbsolute",
       "optimize --problem phase --A 0.5 --c 0.5 -o o.json --force-csv \"$PWD/o.json\"", 2,
       "is invalid: it is the file of -o = o.json: expected another file", none},
      {"BifurcationOverIsBoundedBeforeItsValuesAreHeld",
       kBifurcation + " --over e=0.4:0.6:1000000000 -o o.csv", 2,
       "--over = e=0.4:0.6:1000000000 is invalid: 1000000000 values: expected at most 100000 "
       "values",
       none},
      // SI inputs whose dimensionless model leaves double precision: named, with what they give.
      {"DesignFrequencyBeyondDoublePrecision",
       "design --m1 0.2 --L 0.02 --mu 0.3 --e 0.7 --force-amplitude 0.5 --force-bias 0.1 "
       "--frequency 1e300",
       2, "inputs m2 = 0.002 kg, f = 1e+300 Hz are invalid: with m1 = 0.2 kg, L = 0.02 m", none},
      {"DesignInnerMassBeyondDoublePrecision",
       "design --m1 0.2 --L 0.02 --mu 0.3 --e 0.7 --force-amplitude 0.5 --force-bias 0.1 "
       "--frequency 20 --m2-range 1:1e300",
       2, "inputs m2 = 1e+300 kg, f = 20 Hz are invalid", none},
      // What a long run holds in memory is bounded before it starts.
      {"AttractorsRecordIsBounded", "attractors " + kRobot + " --starts 1x1 --record 100000000", 2,
       "--record = 100000000 is invalid: expected 2 * max_period = 16 <= record <= 1e7 periods",
       none},
      {"BifurcationRecordedPeriodsAreBounded",
       "bifurcation " + kRobot + " --param T0 --from 0.08 --to 0.12 --steps 10000000 -o o.csv", 2,
       "--steps = 10000000 with --record = 100 is invalid: 1000000000 recorded periods a "
       "continuation: expected steps x record <= 100000000",
       none},
      {"DesignM2GridWithM2Range",
       "design --m1 0.2 --L 0.02 --mu 0.3 --e 0.7 --force-amplitude 0.5 --force-bias 0.1 "
       "--frequency 20 --grid m2=0.2,0.3 --m2-range 0.1:0.2 -o o.csv",
       2,
       "--m2-range = 0.1:0.2 is invalid with --grid m2=0.2,0.3: expected the value from only one",
       none},
      // More threads than useful: lowered with a note, as in every command that takes them.
      {"BasinsThreadsAreLoweredWithANote",
       "basins " + kRobot + " --starts 2x2 --transient 20 --record 20 --threads 100000 -o b.csv",
       0,
       "capsubot basins: note: --threads 100000 lowered to",
       {"b.csv"}},
      {"OptimizeThreadsAreLoweredWithANote",
       "optimize --problem reach --reach-seconds 1e-6 --from-rest-starts 2x2 --reach-starts 2x2 "
       "--threads 1025",
       0, "capsubot optimize: note: --threads 1025 lowered to", none},
      {"DesignFromRestThreadsAreLoweredWithANote",
       "design --m1 0.2 --L 0.02 --mu 0.3 --e 0.7 --force-amplitude 0.5 --force-bias 0.1 "
       "--frequency 20 --from-rest --reach-seconds 1e-6 --from-rest-starts 2x2 --reach-starts 2x2 "
       "--threads 1025",
       0, "capsubot design: note: --threads 1025 lowered to", none},
      {"NegativeThreadsAreRefused",
       "attractors " + kRobot + " --starts 1x1 --transient 20 --record 20 --threads -1", 2,
       "--threads = -1 is invalid: expected 1 <= threads (0: all cores)", none},
      // Standard output holds one output: a file given as -o there and the JSON of --json would
      // be mixed in it (by "-", by /dev/stdout, or by the file standard output is sent to).
      {"ContinueDashOutputWithJson", kContinue + " -o - --json", 2,
       "-o - with --json is invalid: both would be written to standard output, one after the "
       "other: expected -o FILE, another file than standard output, or no -o",
       none},
      {"AttractorsDashOutputWithJson",
       "attractors " + kRobot + " --starts 1x1 --transient 20 --record 20 -o - --json", 2,
       "-o - with --json is invalid", none},
      {"BasinsDevStdoutWithJson",
       "basins " + kRobot + " --starts 1x1 --transient 20 --record 20 -o /dev/stdout --json", 2,
       "-o /dev/stdout with --json is invalid", none},
      {"OptimizeOutputIsStdoutsFileWithJson",
       "optimize --problem phase --A 0.5 --c 0.5 -o o.json --json",
       2,
       "-o o.json with --json is invalid: both would be written to standard output",
       {"o.json"},
       "",
       "o.json",
       "",
       [](const fs::path& d) { EXPECT_EQ(ReadFile(d / "o.json"), ""); }},
      {"OptimizeForceCsvDashWithJson",
       "optimize --problem phase --A 0.5 --c 0.5 --force-csv - --json", 2,
       "--force-csv - with --json is invalid", none},
      // An empty value is refused, never read as an absent option.
      {"EmptyShardIsRefused", kSweep + " --shard '' -o out.csv", 2,
       "--shard = '' is invalid: expected a value", none},
      {"EmptyOutputIsRefused", kBifurcation + " -o '' --summary s.csv", 2,
       "--output = '' is invalid: expected a value", none},
      {"EmptyConfigIsRefused", "design --config ''", 2,
       "--config = '' is invalid: expected a value", none},
      // Non-finite orbits are a status, never valid.
      {"TinyMeanForceIsNonFinite", "solve --A 0.5 --c 1e-19 --phi0 -2.9 --json", 0, "", none, "",
       "",
       "\"status\":\"non_finite\",\"stroke\":null,\"u\":null,\"v_mean\":null,\"v_plus\":null,"
       "\"valid\":false"},
      // T0 tau overflows inside the search for phi1, which still finds phi1 = c tau/T0.
      {"HugeT0KeepsItsOrbit", "solve --A 0.5 --c 0.5 --phi0 -2.9 --T0 1e308 --json", 0, "", none,
       "", "", "\"phi1\":3.141592653589793e-308"},
      {"NonFiniteTableSaysNotValid", "solve --A 0.5 --c 1e-19 --phi0 -2.9", 0, "", none, "", "",
       "valid            no: violated finite"},
      // Size options: a bound, checked before any work, the range in the message.
      {"AttractorsStartsBound",
       "attractors --A 0.05 --c 0.02 --phi0 -2.842 --T0 0.1 --alpha 0.28 --starts 100000x100000", 2,
       "--starts = 100000x100000 is invalid: expected at most 4194304 starts", none},
      {"BasinsStartsBound",
       "basins --A 0.05 --c 0.02 --phi0 -2.842 --T0 0.1 --alpha 0.28 --starts 3000x3000 -o b.csv",
       2, "--starts = 3000x3000 is invalid: expected at most 4194304 starts", none},
      {"SolveSamplesBound", kSolve + " --samples 2e9 --trajectory t.csv", 2,
       "--samples = 2e9 is invalid: expected an integer 2 <= n <= 10000000", none},
      {"SimulateSamplesPerPeriodBound", kSim + " --samples-per-period 2e9 --trajectory t.csv", 2,
       "--samples-per-period = 2e9 is invalid: expected an integer 1 <= n <= 1000000", none},
      {"SimulateTrajectoryRowsBound",
       kSim + " --periods 1e6 --samples-per-period 100 --trajectory t.csv", 2,
       "--samples-per-period = 100 with --transient + --periods = 1000000 is invalid: expected "
       "at most 10000000 rows of the trajectory",
       none},
      // The samples cover the transient too.
      {"SimulateTrajectoryRowsCountTheTransient",
       kSim + " --transient 1e6 --periods 1 --samples-per-period 100 --trajectory t.csv", 2,
       "expected at most 10000000 rows of the trajectory (samples per period x periods + 1 = "
       "100000101)",
       none},
      {"SimulateEventBound", kSim + " --max-events-per-period 2e9", 2,
       "--max-events-per-period = 2e9 is invalid: expected an integer 10 <= n <= 1000000000", none},
      {"OrbitsEvaluationBound", kOrbits + " --max-evaluations 0", 2,
       "--max-evaluations = 0 is invalid: expected an integer 1 <= n <= 1000000000", none},
      // Input files are read with bounds: a device is refused, not read forever.
      {"DesignConfigDeviceIsRefused", "design --config /dev/zero", 2,
       "--config /dev/zero is invalid: expected a file of at most 1048576 bytes", none},
      {"MergeShardDeviceIsRefused",
       "merge m.csv s0.csv /dev/zero",
       2,
       "shard file /dev/zero is invalid: a line longer than 1048576 bytes",
       {"s0.csv"},
       "printf '# shard 0/2 of 2 points\\nphi0\\n1\\n' > s0.csv"},
      // A merge never writes over one of its shards, by any name.
      {"MergeOutputIsAShardThroughSymlink",
       "merge link.csv s0.csv s1.csv",
       2,
       "output link.csv is invalid: it is the shard file s0.csv: expected a file other than the "
       "shards",
       {"s0.csv", "s1.csv", "link.csv"},
       "printf '# shard 0/2 of 2 points\\nphi0\\n1\\n' > s0.csv && printf '# shard 1/2 of 2 "
       "points\\nphi0\\n2\\n' > s1.csv && ln -s s0.csv link.csv",
       "",
       "",
       [](const fs::path& d) {
         EXPECT_EQ(ReadFile(d / "s0.csv"), "# shard 0/2 of 2 points\nphi0\n1\n");
       }},
      // A folder or a converted file among the shards: bad input naming the file.
      {"MergeShardFolderIsRefused",
       "merge m.csv s0.csv dd",
       2,
       "shard file dd is invalid: it is a folder: expected a shard file",
       {"s0.csv", "dd"},
       "printf '# shard 0/2 of 2 points\\nphi0\\n1\\n' > s0.csv && mkdir dd"},
      {"MergeCrLfShardSaysLineEndings",
       "merge m.csv s0.csv s1.csv",
       2,
       "shard file s0.csv is invalid: its line endings are CR LF",
       {"s0.csv", "s1.csv"},
       "printf '# shard 0/2 of 2 points\\r\\nphi0\\r\\n1\\r\\n' > s0.csv && printf '# shard "
       "1/2 of 2 points\\r\\nphi0\\r\\n2\\r\\n' > s1.csv"},
      // The rows of a robot-mode point are those its `orbits` cell counts, numbered 1 ..
      // orbits: a row lost, repeated or moved is refused, never merged.
      {"MergeRobotShardLastRowLost",
       "merge m.csv s0.csv s1.csv",
       2,
       "shard file s1.csv is truncated: it ends in point 3 after 1 of its 2 rows (orbits = 2)",
       {"s0.csv", "s1.csv"},
       RobotShardsSetup() + " && sed -i '$d' s1.csv"},
      {"MergeRobotShardOrbitRowLost",
       "merge m.csv s0.csv s1.csv",
       2,
       "shard file s0.csv point 2 row 1 '0.25,2,2,",
       {"s0.csv", "s1.csv"},
       RobotShardsSetup() + " && sed -i '5d' s0.csv"},
      {"MergeRobotShardOrbitRowRepeated",
       "merge m.csv s0.csv s1.csv",
       2,
       "shard file s0.csv point 2 row 2 '0.25,2,1,",
       {"s0.csv", "s1.csv"},
       RobotShardsSetup() + " && sed -i '5p' s0.csv"},
      // The starts of a basin map are those of its grid: an edited or copied start is named.
      {"MergeBasinStartEdited",
       "merge m.csv b0.csv b1.csv",
       2,
       "shard file b0.csv start 1 (x0 = 0.51, psi = 0) is invalid: expected start 2 of the "
       "map's 3 x 2 grid, x0 = 0.5: a start edited or copied from another",
       {"b0.csv", "b1.csv"},
       BasinShardsSetup() + " && sed -i 's/^0.5,0,/0.51,0,/' b0.csv"},
      {"MergeBasinStartCopied",
       "merge m.csv b0.csv b1.csv",
       2,
       "shard file b0.csv start 1 (x0 = 0.16666666666666666, psi = 0) is invalid: expected "
       "start 2 of the map's 3 x 2 grid, x0 = 0.5",
       {"b0.csv", "b1.csv"},
       BasinShardsSetup() + " && sed -i '4h;5g' b0.csv"},
      // Parts of a bifurcation shard moved within it: named as such, not as missing.
      {"MergeBifurcationPartsReordered",
       "merge m.csv s0.csv s1.csv",
       2,
       "shard file s0.csv holds part 0 of 4 after part 2: expected its parts in increasing order",
       {"s0.csv", "s1.csv"},
       "printf '# shard 0/2 of 2 continuations\\nparam,direction\\n# part 2 of 4: 1 rows\\n"
       "0.1,up\\n# part 0 of 4: 1 rows\\n0.2,up\\n' > s0.csv && printf '# shard 1/2 of 2 "
       "continuations\\nparam,direction\\n# part 1 of 4: 1 rows\\n0.3,down\\n# part 3 of "
       "4: 1 rows\\n0.4,down\\n' > s1.csv"},
      // A state beyond double precision ends the simulation with an error, no file.
      {"SimulateHugeV0",
       "simulate --A 0.5 --c 0.5 --phi0 0 --alpha 0.5 --x0 0.5 --u0 0 "
       "--v0 1.7e308 --trajectory t.csv --events e.csv",
       1, "the state is not finite", none},
      // Write errors on standard output and in files: exit 1.
      {"SolveToDevFull", kSolve, 1,
       "capsubot solve: error: standard output cannot be written: "
       "No space left on device",
       none, "", "/dev/full"},
      {"SolveJsonToDevFull", kSolve + " --json", 1, "standard output cannot be written", none, "",
       "/dev/full"},
      {"SimulateToDevFull", kSim, 1, "standard output cannot be written", none, "", "/dev/full"},
      {"OrbitsToDevFull", kOrbits, 1, "standard output cannot be written", none, "", "/dev/full"},
      {"OptimizeToDevFull", "optimize --problem phase --A 0.5 --c 0.5", 1,
       "standard output cannot be written", none, "", "/dev/full"},
      {"SweepStdoutToDevFull", kSweep + " -o -", 1, "No space left on device", none, "",
       "/dev/full"},
      {"HelpToDevFull", "solve --help", 1, "standard output cannot be written", none, "",
       "/dev/full"},
      {"TrajectoryToDevFull", kSolve + " --trajectory /dev/full", 1,
       "--trajectory /dev/full cannot be written: No space left on device", none, "", "/dev/null"},
      // Empty strings are no number.
      {"EmptyA", "solve --A '' --c 0.5 --phi0 0", 2,
       "capsubot solve: error: --A = '' is invalid: expected a number, not an empty string", none},
      {"EmptyT0", kSim + " --T0 ''", 2, "--T0 = '' is invalid", none},
      {"EmptyInteger", kSolve + " --samples '' --trajectory t.csv", 2,
       "--samples = '' is invalid: expected an integer 2 <= n <= 10000000", none},
      {"EmptyGridOption", kSweep + " -o out.csv --T0 ''", 2, "--T0 = '' is invalid", none},
      {"EmptyOptimizeA", "optimize --problem phase --A '' --c 0.5", 2, "--A = '' is invalid", none},
      {"EmptySinElement", "solve --c 0.5 --sin 0.1,,0.2 --phi0 0", 2,
       "--sin = 0.1,,0.2 is invalid: expected comma-separated numbers (element 2 is '')", none},
      // Hex, spaces and other malformed numbers: rejected the same way everywhere.
      {"HexA", "solve --A 0x1p-2 --c 0.5 --phi0 0", 2, "--A = 0x1p-2 is invalid: " + nums, none},
      {"LeadingSpace", "solve --A ' 1' --c 0.5 --phi0 0", 2, "--A = ' 1' is invalid: " + nums,
       none},
      {"TrailingSpace", "solve --A '1 ' --c 0.5 --phi0 0", 2, "--A = '1 ' is invalid: " + nums,
       none},
      {"HexInteger", kSolve + " --samples 0x10 --trajectory t.csv", 2,
       "--samples = 0x10 is invalid: expected an integer", none},
      {"SpaceInInteger", kOrbits + " --max-evaluations ' 5'", 2,
       "--max-evaluations = ' 5' is invalid", none},
      {"MalformedExponent", "solve --A 1e --c 0.5 --phi0 0", 2, "--A = 1e is invalid", none},
      {"CommaDecimal", kSim + " --periods 1,5", 2, "--periods = 1,5 is invalid", none},
      {"HexInSinList", "solve --c 0.5 --sin 0x1 --phi0 0", 2,
       "--sin = 0x1 is invalid: expected comma-separated numbers", none},
      // NaN, infinity and numbers beyond double.
      {"NanA", "solve --A nan --c 0.5 --phi0 0", 2,
       "--A = nan is invalid: expected a finite "
       "number",
       none},
      {"InfC", "solve --A 0.5 --c inf --phi0 0", 2, "--c = inf is invalid: expected a finite",
       none},
      {"MinusInfT0", kSim + " --T0 -inf", 2, "--T0 = -inf is invalid", none},
      {"OverflowA", "solve --A 1e999 --c 0.5 --phi0 0", 2,
       "--A = 1e999 is invalid: expected a number within the range of double", none},
      {"UnderflowC", "solve --A 0.5 --c 1e-400 --phi0 0", 2,
       "--c = 1e-400 is invalid: expected a number within the range of double", none},
      // Integers out of range: the range in the message, never clamped.
      {"HugeInteger", kSolve + " --samples 99999999999999999999 --trajectory t.csv", 2,
       "expected an integer 2 <= n <= 10000000", none},
      {"HugeInt64", kOrbits + " --max-evaluations 99999999999999999999", 2,
       "expected an integer 1 <= n <= 1000000000", none},
      {"IntOverflow", kSweep + " -o out.csv --threads 3000000000", 2,
       "--threads = 3000000000 is invalid: expected an integer -2147483648 <= n <= 2147483647",
       none},
      {"FractionalInteger", kSolve + " --samples 2.5 --trajectory t.csv", 2,
       "--samples = 2.5 is invalid: expected an integer", none},
      // Subnormal numbers are numbers.
      {"SubnormalAccepted", "solve --A 1e-310 --c 0.5 --phi0 0 --json", 0, "", none, "", "",
       "\"A\":1e-310"},
      {"SmallestDoubleAccepted", "solve --A 4.9406564584124654e-324 --c 0.5 --phi0 0 --json", 0, "",
       none, "", "", "\"A\":5e-324"},
      // Unknown options and unwritable paths.
      {"UnknownOption", kSolve + " --bogus 1", 2, "The following arguments were not expected",
       none},
      {"UnknownCommand", "frobnicate", 2, "capsubot: error:", none},
      {"MissingFolder", kSolve + " --trajectory nothere/t.csv", 2,
       "--trajectory nothere/t.csv cannot be written: No such file or directory", none},
      {"FolderAsOutput", kSolve + " --trajectory .", 2, "--trajectory . cannot be written", none},
      {"SweepMissingFolder", kSweep + " -o nothere/out.csv", 2, "nothere/out.csv", none},
      // Threads are capped at 4 per core, with a note.
      {"ThreadsCapped",
       kSweep + " -o out.csv --threads 1024",
       0,
       "--threads 1024 lowered to",
       {"out.csv"}},
      // Conflicting options name both.
      {"GridAndOption", "sweep --grid A=0:1:5 --A 5 --c 0.5 --phi0 0 -o out.csv", 2,
       "--A = 5 is invalid with --grid A=0:1:5: expected the value from only one of them", none},
      {"GridT0AndT0", kSweep + " --grid T0=0.5:1:2 --T0 1 -o out.csv", 2,
       "--T0 = 1 is invalid with --grid T0=0.5:1:2: expected the value from only one", none},
      {"AWithSin", "solve --A 0.5 --sin 0.1 --c 0.5 --phi0 0", 2, "--A excludes --sin", none},
      {"FromOrbitWithX0", "simulate --A 0.5 --c 0.5 --phi0 -2.9 --from-orbit --x0 0.5", 2,
       "--x0 excludes --from-orbit", none},
      {"SamplesWithoutTrajectory", kSolve + " --samples 5", 2, "--samples requires --trajectory",
       none},
      {"SamplesPerPeriodWithoutTrajectory", kSim + " --samples-per-period 5", 2,
       "--samples-per-period requires --trajectory", none},
      {"StableOnlyWithoutOptimize", kSweep + " -o out.csv --stable-only", 2,
       "--stable-only requires --optimize", none},
      {"OptimizeAWithMainJob", "optimize --A 0.5", 2,
       "--A conflicts with the main job (no --problem): expected --A only with --problem phase",
       none},
      {"OptimizeHarmonicsWithForcing", "optimize --problem forcing --harmonics 3", 2,
       "--harmonics conflicts with --problem forcing: expected --harmonics only with --problem "
       "fourier",
       none},
      // A config file nested thousands deep is refused before it is parsed (the parser would
      // descend once per level and exhaust the stack).
      {"ConfigDeepDottedKeyIsRefused",
       "design --config dk.toml",
       2,
       "config file dk.toml line 1 is invalid: keys and values nested more than 32 deep",
       {"dk.toml"},
       "{ yes a | head -n 50000 | tr '\\n' .; echo 'b = 1'; } > dk.toml"},
      {"ConfigDeepTableHeaderIsRefused",
       "design --config dk.toml",
       2,
       "config file dk.toml line 2 is invalid: keys and values nested more than 32 deep",
       {"dk.toml"},
       "{ echo '# robot'; printf '[['; yes a | head -n 50000 | tr '\\n' .; echo 'b]]'; } > "
       "dk.toml"},
      {"ConfigDeepArrayIsRefused",
       "design --config dk.toml",
       2,
       "config file dk.toml line 1 is invalid: keys and values nested more than 32 deep",
       {"dk.toml"},
       "{ printf 'm1 = '; yes '[' | head -n 50000 | tr -d '\\n'; echo; } > dk.toml"},
      {"ConfigDeepInlineTableIsRefused",
       "design --config dk.toml",
       2,
       "config file dk.toml line 1 is invalid: keys and values nested more than 32 deep",
       {"dk.toml"},
       "{ printf 'm1 = '; yes '{a=' | head -n 50000 | tr -d '\\n'; echo; } > dk.toml"},
      {"ConfigLongKeyIsCut",
       "design --config k.toml",
       2,
       "kkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkkk... = 1 in k.toml is "
       "invalid: unknown key",
       {"k.toml"},
       "{ head -c 40000 /dev/zero | tr '\\0' k; echo ' = 1'; } > k.toml",
       "",
       "",
       [](const fs::path& d) { EXPECT_LT(fs::file_size(d / ".." / "stderr.txt"), 400U); }},
      {"ConfigNumbersEchoedShortest",
       "design --config c.toml",
       2,
       "m1 = {a = 0.3} in c.toml is invalid: expected a number",
       {"c.toml"},
       "echo 'm1 = {a = 0.3}' > c.toml"},
      {"ConfigHugeShellMassIsNamed",
       "design --config c.toml",
       2,
       "shell mass m1 = 1e+308 kg is invalid: expected m1 <= 1.7976931348623158e+307 kg",
       {"c.toml"},
       "printf 'm1 = 1e308\\nL = 0.02\\nmu = 0.3\\ne = 0.7\\nforce-amplitude = 0.5\\n"
       "force-bias = 0.1\\nfrequency = 20\\n' > c.toml"},
      {"ConfigFolderIsRefused", "design --config .", 2,
       "--config . is invalid: expected a file of at most 1048576 bytes, not a folder", none},
      // Ranges that hold no map or diagram, refused before any work.
      {"BifurcationFromEqualsTo",
       "bifurcation " + kRobot + " --param T0 --from 0.1 --to 0.1 --steps 3 -o o.csv", 2,
       "--to = 0.1 is invalid with --from = 0.1: expected a range, to other than from", none},
      {"BasinsInvertedURangeOnThePsiPlane",
       "basins " + kRobot + " --starts 2x2 --u-min 5 --u-max -5 -o b.csv", 2,
       "--u-min = 5 and --u-max = -5 are invalid: expected u-min < u-max", none},
      // Values in reports and messages in their shortest round-trip form, never rounded.
      {"AttractorsAlphaNearOneIsNotRounded",
       "attractors --A 0.05 --c 0.02 --phi0 -2.842 --T0 0.1 --e 0.5 --alpha 0.999999999999 "
       "--starts 1x1 --transient 20 --record 20",
       0, "", none, "", "", "alpha = 0.999999999999\n"},
      {"SimulateAlphaNearOneIsNotRounded",
       "simulate --A 0.5 --c 0.5 --phi0 0 --alpha 0.999999999999 --x0 0.5 --u0 0 --v0 0 "
       "--periods 1",
       0, "", none, "", "", "T0 = 1, e = 1, alpha = 0.999999999999\n"},
      // One convention for a missing value in tables: "-".
      {"MissingValuesAreDashes", "solve --A 0.2 --c 0.03 --phi0 0", 0, "", none, "", "",
       "alpha  = -   (m2/(m1+m2))", nullptr},
      // Phases are radians: reduced modulo the true 2 pi up to 1e6 rad, refused beyond, where a
      // double names no angle (the phase was lost when added).
      {"SolveHugePhaseIsRefused", "solve --A 0.5 --c 0.5 --phi0 1e300", 2,
       "phi0 = 1e+300 is invalid: expected a phase |phi0| <= 1e+06 rad (phases are in radians",
       none},
      {"AttractorsHugePhaseIsRefused",
       "attractors --A 0.05 --c 0.02 --phi0 1e16 --T0 0.1 --alpha 0.28 --starts 1x1", 2,
       "phi0 = 1e+16 is invalid: expected a phase |phi0| <= 1e+06 rad", none},
      {"BifurcationHugePhaseRangeIsRefused",
       "bifurcation " + kRobot + " --param phi0 --from 0 --to 1e300 --steps 3 -o o.csv", 2,
       "phi0 = 1e+300 is invalid: expected a phase |phi0| <= 1e+06 rad", none},
      {"SweepHugePhaseGridIsRefused", "sweep --grid phi0=0:1e300:3 --A 0.5 --c 0.5 -o o.csv", 2,
       "--grid phi0=0:1e300:3 is invalid: expected phases |phi0| <= 1e6 rad (phases are in "
       "radians)",
       none},
      {"PeriodicHugeStartPhaseIsRefused", "periodic " + kRobot + " --from-rest 0.5,1e300", 2,
       "psi = 1e+300 is invalid: expected a phase |psi| <= 1e+06 rad", none},
      // -2.9 + 10^5 turns as a double: its exact remainder (300-bit arithmetic), not -2.9.
      {"SolveLargePhaseIsReducedExactly", "solve --A 0.5 --c 0.5 --phi0 628315.6307179587 --json",
       0, "--phi0 = 628315.6307179587 is 1e+05 turns: phases are in radians", none, "", "",
       "\"phi0\":-2.899999999974789"},
      // A phase of more than a turn is most often meant in degrees: the note says how it is read.
      {"SolvePhaseInDegreesGetsANote", "solve --A 0.3 --c 0.4 --phi0 90", 0,
       "capsubot: note: --phi0 = 90 is 14.32 turns: phases are in radians", none, "", "",
       "one-impact periodic orbit"},
      // A friction bound that dwarfs the motor: the design answers after a bounded number of
      // robots (it refined every orbit search to its bound, a minute and more).
      {"DesignHugeFrictionStopsAtItsWorkBound",
       "design --m1 0.2 --L 0.02 --mu 1e6 --e 0.7 --force-amplitude 0.5 --force-bias 0.1 "
       "--frequency 20",
       0, "", none, "", "", "the search stopped after 8 robots"},
      // A finite-difference step wider than the range took the parameter out of the robots
      // (the message named a mass ratio alpha < 0 that nobody gave).
      {"ContinueStepWiderThanTheRange", kContinue + " --step 0.3", 2,
       "--step = 0.3 is invalid: expected 3 step max(1, |from|, |to|) <= to - from", none},
      {"ContinueStepWiderThanTheCurveRange",
       kContinue + " --param2 A --from2 0.04 --to2 0.06 --follow fold --step 0.01", 2,
       "--step = 0.01 is invalid: expected 3 step max(1, |from2|, |to2|) <= to2 - from2", none},
      // A after a1: A is b1 of the harmonic family, so the curve in (a1, A) is the one in (a1,
      // b1) (its range A = 0.0485088414898 .. 0.06 printed by the b1 run); it stopped with
      // "parameter = A is invalid for a Fourier force" once a1 left 0.
      {"ContinueCurveInA1AndA",
       "continue " + kRobot +
           " --from-orbit --param a1 --from -0.01 --to 0.01 --param2 A --from2 0.04 --to2 0.06 "
           "--follow speed_extremum",
       0, "", none, "", "", "A = 0.0485088414898 .. 0.06"},
      // The main job's reach effort is named by its flags (it was named by the reach search's
      // own field "max_seconds = 0").
      {"OptimizeMainJobReachSecondsNamed", "optimize --from-rest-starts 3x3 --reach-seconds 0", 2,
       "--reach-seconds = 0 is invalid: expected a time > 0", none},
      // A grid of phases beyond one turn gets the note of --phi0 (it had none).
      {"SweepGridPhaseInDegreesGetsANote",
       "sweep --grid phi0=-100,1 --A 0.5 --c 0.5 -o o.csv",
       0,
       "capsubot: note: --grid phi0 = -100 is -15.92 turns: phases are in radians",
       {"o.csv"}},
      // A plastic robot's robustness in e: no change in percent from e = 0 (it said "+inf %").
      {"DesignRobustnessFromPlasticImpact",
       "design --m1 0.2 --L 0.02 --mu 0.3 --e 0 --force-amplitude 0.5 --force-bias 0.1 "
       "--frequency 20",
       0, "", none, "", "", "the motion changes stability at e = ",
       [](const fs::path& work) {
         // A limit above e = 0, the value alone: no change in percent after it.
         const std::string out = ReadFile(work.parent_path() / "stdout.txt");
         std::smatch m;
         ASSERT_TRUE(std::regex_search(
             out, m, std::regex("the motion changes stability at e = ([0-9.e+-]+)\n")))
             << out;
         EXPECT_GT(std::stod(m[1].str()), 0.0) << out;
         EXPECT_LT(std::stod(m[1].str()), 1.0) << out;
       }},
      // An unknown second parameter is named as --param2 (it was "parameter = mu", as --param).
      {"ContinueUnknownParam2IsNamed",
       kContinue + " --param2 mu --from2 0.1 --to2 0.5 --follow fold", 2,
       "--param2 = mu is invalid: expected one of A, c, alpha, T0, e, phi0", none},
  };
}

class HostileCli : public ::testing::TestWithParam<Case> {};

TEST_P(HostileCli, ExitStatusMessageAndNoStrayFile) {
  const Case& c = GetParam();
  Sandbox box(c.name);
  const fs::path out = box.root / "stdout.txt", err = box.root / "stderr.txt";
  std::string command = "cd '" + box.work.string() + "' && ";
  if (!c.setup.empty()) command += "(" + c.setup + ") && ";
  command += std::string(CAPSUBOT_CLI) + " " + c.args + " >" +
             (c.stdout_to.empty() ? "'" + out.string() + "'" : c.stdout_to) + " 2>'" +
             err.string() + "'";
  const std::set<std::string> before = Listing(box.work);  // empty: setup runs in `command`
  ASSERT_TRUE(before.empty());
  const int raw = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(raw)) << command;
  const std::string stderr_text = ReadFile(err);
  EXPECT_EQ(WEXITSTATUS(raw), c.status) << command << "\n" << stderr_text;
  if (c.message.empty()) {
    EXPECT_EQ(stderr_text, "") << command;
  } else {
    EXPECT_NE(stderr_text.find(c.message), std::string::npos) << command << "\n" << stderr_text;
    EXPECT_EQ(std::count(stderr_text.begin(), stderr_text.end(), '\n'), 1) << stderr_text;
  }
  if (!c.stdout_has.empty()) {
    EXPECT_NE(ReadFile(out).find(c.stdout_has), std::string::npos) << ReadFile(out);
  }
  // No number printed as "nan" (the word "provenance" holds the letters, not the number).
  EXPECT_FALSE(std::regex_search(ReadFile(out), std::regex("\\bnan\\b"))) << ReadFile(out);
  EXPECT_EQ(Listing(box.work), c.files) << command;
  if (c.verify) c.verify(box.work);
}

INSTANTIATE_TEST_SUITE_P(Table, HostileCli, ::testing::ValuesIn(Cases()),
                         [](const ::testing::TestParamInfo<Case>& info) {
                           return std::string(info.param.name);
                         });

TEST(HostileCliTable, RowNamesAreUnique) {
  // A row's name is its test's name: two rows of one name would run as one.
  std::set<std::string> names;
  for (const Case& c : Cases()) {
    EXPECT_TRUE(names.insert(c.name).second) << "row name used twice: " << c.name;
  }
  EXPECT_FALSE(names.empty());
}

// A pipe (FIFO) given as the output of a long run is checked without being opened, then
// written once: its reader gets the whole file (a check that opened it would end the reader's
// file early and leave the real write waiting for a reader forever).
TEST(HostileCliFifo, WholeRunsWriteAPipeOnce) {
  const std::vector<std::pair<std::string, std::string>> runs = {
      {"attractors " + kRobot + " --transient 20 --record 20 --starts 4x3 -o ff", "x0,psi,"},
      {"basins " + kRobot + " --transient 20 --record 20 --starts 4x3 -o ff", "x0,psi,"},
      {kBifurcation + " -o ff", "param,direction,"}};
  for (const auto& [args, header] : runs) {
    Sandbox box("fifo");
    const std::string command = "cd '" + box.work.string() +
                                "' && mkfifo ff && { timeout 60 cat ff > got & } && timeout 60 " +
                                std::string(CAPSUBOT_CLI) + " " + args +
                                " > /dev/null; s=$?; wait; exit $s";
    const int raw = std::system(command.c_str());
    ASSERT_TRUE(WIFEXITED(raw)) << command;
    EXPECT_EQ(WEXITSTATUS(raw), 0) << command;
    const std::string got = ReadFile(box.work / "got");
    EXPECT_NE(got.find(header), std::string::npos) << args << ": " << got;
    EXPECT_GT(std::count(got.begin(), got.end(), '\n'), 4) << args << ": " << got;
    EXPECT_EQ(Listing(box.work), (std::set<std::string>{"ff", "got"})) << args;
  }
}

// A pipe given as --config is refused at once, also without a writer (an open that waited
// for one would block forever).
TEST(HostileCliFifo, ConfigPipeWithoutWriterIsRefused) {
  Sandbox box("config_fifo");
  const std::string command = "cd '" + box.work.string() + "' && mkfifo ff && timeout 20 " +
                              std::string(CAPSUBOT_CLI) + " design --config ff 2>err.txt";
  const int raw = std::system(command.c_str());
  ASSERT_TRUE(WIFEXITED(raw)) << command;
  EXPECT_EQ(WEXITSTATUS(raw), 2) << command;
  EXPECT_NE(ReadFile(box.work / "err.txt")
                .find("--config ff is invalid: expected a file of at most 1048576 bytes, not a "
                      "pipe or device"),
            std::string::npos)
      << ReadFile(box.work / "err.txt");
}

// Starts `capsubot args...` with stdout and stderr to files (or stderr to `stderr_path`).
pid_t Spawn(const std::vector<std::string>& args, const std::string& stdout_path,
            const std::string& stderr_path) {
  std::vector<std::string> all = {CAPSUBOT_CLI};
  all.insert(all.end(), args.begin(), args.end());
  std::vector<char*> argv;
  for (std::string& a : all) argv.push_back(a.data());
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, STDOUT_FILENO, stdout_path.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  posix_spawn_file_actions_addopen(&actions, STDERR_FILENO, stderr_path.c_str(),
                                   O_WRONLY | O_CREAT | O_TRUNC, 0644);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, CAPSUBOT_CLI, &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return rc == 0 ? pid : -1;
}

// A long simulation writing a large trajectory, killed by SIGINT or SIGTERM while its
// temporary file exists: it dies of that signal (status 128 + signal in a shell) and leaves
// no file behind.
TEST(HostileCliSignals, InterruptRemovesTemporaryFiles) {
  for (int signal_number : {SIGINT, SIGTERM}) {
    Sandbox box("signal" + std::to_string(signal_number));
    const fs::path trajectory = box.work / "t.csv";
    const pid_t pid = Spawn({"simulate", "--A", "0.5", "--c", "0.5", "--phi0", "-2.944899971002",
                             "--T0", "1", "--from-orbit", "--periods", "9e5",
                             "--samples-per-period", "10", "--trajectory", trajectory.string()},
                            (box.root / "stdout.txt").string(), (box.root / "stderr.txt").string());
    ASSERT_GT(pid, 0);
    const fs::path temp = trajectory.string() + ".tmp." + std::to_string(pid);
    // Wait (bounded) until the temporary file holds some rows.
    for (int i = 0; i < 1000 && !(fs::exists(temp) && fs::file_size(temp) > 0); ++i) {
      std::this_thread::sleep_for(std::chrono::milliseconds(10));
    }
    ASSERT_TRUE(fs::exists(temp)) << "no temporary file " << temp;
    ASSERT_EQ(::kill(pid, signal_number), 0);
    int raw = 0;
    ASSERT_EQ(::waitpid(pid, &raw, 0), pid);
    ASSERT_TRUE(WIFSIGNALED(raw)) << "exit status " << raw;
    EXPECT_EQ(WTERMSIG(raw), signal_number);
    EXPECT_TRUE(Listing(box.work).empty()) << "left: " << *Listing(box.work).begin();
  }
}

// Reads the master side of a pseudo-terminal until the other side is closed.
std::string DrainTerminal(int master) {
  std::string text;
  char buffer[4096];
  for (;;) {
    const ssize_t n = ::read(master, buffer, sizeof buffer);
    if (n <= 0) return text;  // EIO once the program has exited and closed the terminal
    text.append(buffer, static_cast<std::size_t>(n));
  }
}

// Runs capsubot with stderr on a pseudo-terminal and stdout to `stdout_path`; returns what the
// terminal showed, and the exit status in `status` (-1 when it did not exit normally).
std::string RunWithTerminalStderr(const std::vector<std::string>& args,
                                  const std::string& stdout_path, int& status) {
  status = -1;
  const int master = ::posix_openpt(O_RDWR | O_NOCTTY);
  if (master < 0 || ::grantpt(master) != 0 || ::unlockpt(master) != 0) return "";
  const std::string terminal = ::ptsname(master);
  // Held open until the program is done, so the reader never sees a terminal without users.
  const int slave = ::open(terminal.c_str(), O_RDWR | O_NOCTTY);
  std::string shown;
  std::thread reader([&] { shown = DrainTerminal(master); });
  const pid_t pid = Spawn(args, stdout_path, terminal);
  int raw = 0;
  const bool waited = pid > 0 && ::waitpid(pid, &raw, 0) == pid;
  ::close(slave);
  reader.join();
  ::close(master);
  if (waited && WIFEXITED(raw)) status = WEXITSTATUS(raw);
  return shown;
}

struct ProgressCase {
  const char* name;
  std::vector<std::string> args;
  const char* progress;  // shown on the terminal, never on stdout or in a log file
  const char* result;    // on stdout
};

class HostileCliProgress : public ::testing::TestWithParam<ProgressCase> {};

// Progress of long runs goes to stderr when it is a terminal, and never to stdout.
TEST_P(HostileCliProgress, ShownOnATerminalOnly) {
  const ProgressCase& c = GetParam();
  Sandbox box("progress");
  int status = 0;
  const std::string shown =
      RunWithTerminalStderr(c.args, (box.root / "stdout.txt").string(), status);
  EXPECT_EQ(status, 0);
  EXPECT_NE(shown.find(c.progress), std::string::npos) << shown;
  const std::string out = ReadFile(box.root / "stdout.txt");
  EXPECT_EQ(out.find(c.progress), std::string::npos) << out;
  EXPECT_NE(out.find(c.result), std::string::npos) << out;
  // The same run with stderr to a file: no progress at all.
  int raw = 0;
  const pid_t quiet =
      Spawn(c.args, (box.root / "stdout2.txt").string(), (box.root / "stderr2.txt").string());
  ASSERT_EQ(::waitpid(quiet, &raw, 0), quiet);
  EXPECT_EQ(ReadFile(box.root / "stderr2.txt").find(c.progress), std::string::npos);
}

const ProgressCase kProgressCases[] = {
    {"LongSimulation",
     {"simulate", "--A", "0.5", "--c", "0.5", "--phi0", "-2.944899971002", "--from-orbit",
      "--periods", "2e5"},
     "200000/200000 periods",
     "event-driven simulation"},
    {"Bifurcation",
     {"bifurcation", "--A",  "0.05",     "--c",     "0.02",    "--phi0", "-2.842",
      "--T0",        "0.1",  "--e",      "0.5",     "--param", "alpha",  "--from",
      "0.2",         "--to", "0.3",      "--steps", "5",       "-o",     "/dev/null",
      "--transient", "20",   "--record", "16"},
     "10/10 parameter values",
     "bifurcation diagram over alpha"},
    {"OptimizeStages",
     {"optimize", "--problem", "phase", "--A", "0.05", "--c", "0.05", "--T0", "0.1",
      "--from-rest-starts", "2x2"},
     "optimize: the optimum checked from rest",
     "capsubot optimize --problem phase"},
};

INSTANTIATE_TEST_SUITE_P(Runs, HostileCliProgress, ::testing::ValuesIn(kProgressCases),
                         [](const auto& info) { return std::string(info.param.name); });

}  // namespace
}  // namespace capsubot
