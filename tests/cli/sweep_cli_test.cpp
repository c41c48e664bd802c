// `capsubot sweep` as a user runs it: a sweep killed mid-way (SIGKILL or SIGINT, the real
// process) leaves no CSV under the final name and `--resume` completes it to the same bytes
// as an uninterrupted run; bad command lines exit with status 2 and a message naming the
// option, its value and the rule; the provenance line; damaged checkpoints; write errors.
// `--shard K/N` and `capsubot merge`: N shards merged give the bytes of the single run
// (plain, robot mode with several rows a point, an optimisation); merge refuses shards of
// another run, a missing, duplicated or truncated shard, extra rows.

#include <fcntl.h>
#include <gtest/gtest.h>
#include <signal.h>
#include <spawn.h>
#include <sys/wait.h>
#include <unistd.h>

#include <algorithm>
#include <chrono>
#include <cstdint>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <string>
#include <thread>
#include <vector>

extern char** environ;

namespace {

const std::string kCli = CAPSUBOT_CLI;

class TempDir {
 public:
  TempDir() {
    char pattern[] = "/tmp/capsubot_sweep_cli_test_XXXXXX";
    path_ = ::mkdtemp(pattern);
  }
  ~TempDir() { std::system(("rm -rf '" + path_ + "'").c_str()); }
  std::string File(const std::string& name) const { return path_ + "/" + name; }

 private:
  std::string path_;
};

std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

bool Exists(const std::string& path) { return ::access(path.c_str(), F_OK) == 0; }

struct Outcome {
  int status = -1;     // exit status
  std::string output;  // stdout and stderr
};

Outcome RunCli(const std::string& args, const std::string& log) {
  const int raw = std::system((kCli + " " + args + " > '" + log + "' 2>&1").c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, ReadFile(log)};
}

// The cells of one CSV line.
std::vector<std::string> Cells(const std::string& line) {
  std::vector<std::string> cells;
  std::string cell;
  std::istringstream in(line);
  while (std::getline(in, cell, ',')) cells.push_back(cell);
  if (!line.empty() && line.back() == ',') cells.emplace_back();
  return cells;
}

// Complete grid points recorded in a checkpoint file (0 if absent or unreadable).
long CheckpointPoints(const std::string& path) {
  std::ifstream in(path);
  std::string line, key;
  long points = 0;
  std::getline(in, line);
  in >> key >> points;
  return key == "points" ? points : 0;
}

// A sweep slow enough to be caught mid-way: P1 at each of 960 points (about 1 s).
// Checkpoints every 50 ms (each one fsyncs: every block would be slow on a real disk).
std::vector<std::string> SlowSweep(const std::string& output, int threads) {
  return {kCli,
          "sweep",
          "--grid",
          "A=0.05:0.95:24",
          "--grid",
          "c=0.01:0.5:40",
          "--optimize",
          "phi0",
          "--stability",
          "--T0",
          "1",
          "--threads",
          std::to_string(threads),
          "--checkpoint-seconds",
          "0.05",
          "-o",
          output};
}

pid_t Spawn(const std::vector<std::string>& args) {
  std::vector<char*> argv;
  for (const std::string& a : args) argv.push_back(const_cast<char*>(a.c_str()));
  argv.push_back(nullptr);
  posix_spawn_file_actions_t actions;
  posix_spawn_file_actions_init(&actions);
  posix_spawn_file_actions_addopen(&actions, 1, "/dev/null", O_WRONLY, 0);
  posix_spawn_file_actions_addopen(&actions, 2, "/dev/null", O_WRONLY, 0);
  pid_t pid = -1;
  const int rc = posix_spawn(&pid, argv[0], &actions, nullptr, argv.data(), environ);
  posix_spawn_file_actions_destroy(&actions);
  return rc == 0 ? pid : -1;
}

std::string Join(const std::vector<std::string>& args) {
  std::string s;
  for (std::size_t i = 1; i < args.size(); ++i) s += "'" + args[i] + "' ";
  return s;
}

class SweepCliKilled : public ::testing::TestWithParam<int> {};

TEST_P(SweepCliKilled, ResumesToTheBytesOfAnUninterruptedRun) {
  const int signal = GetParam();
  TempDir dir;
  const std::string reference = dir.File("reference.csv"), killed = dir.File("killed.csv");
  ASSERT_EQ(RunCli(Join(SlowSweep(reference, 2)), dir.File("ref.log")).status, 0);

  const pid_t pid = Spawn(SlowSweep(killed, 1));
  ASSERT_GT(pid, 0);
  // Wait until some rows are checkpointed, then kill the process mid-way.
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  long done = 0;
  while ((done = CheckpointPoints(killed + ".checkpoint")) == 0 &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ASSERT_EQ(::kill(pid, signal), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  ASSERT_TRUE(WIFSIGNALED(status)) << "the sweep ended before it could be killed";
  EXPECT_EQ(WTERMSIG(status), signal);
  EXPECT_GT(done, 0);
  EXPECT_FALSE(Exists(killed)) << "a killed sweep left a CSV under its final name";
  EXPECT_TRUE(Exists(killed + ".partial"));
  const long checkpointed = CheckpointPoints(killed + ".checkpoint");
  EXPECT_GT(checkpointed, 0);
  EXPECT_LT(checkpointed, 960);

  std::vector<std::string> resume = SlowSweep(killed, 2);
  resume.emplace_back("--resume");
  const Outcome r = RunCli(Join(resume), dir.File("resume.log"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(ReadFile(killed) == ReadFile(reference)) << "resumed file differs";
  EXPECT_FALSE(Exists(killed + ".partial"));
  EXPECT_FALSE(Exists(killed + ".checkpoint"));
}

INSTANTIATE_TEST_SUITE_P(Signals, SweepCliKilled, ::testing::Values(SIGKILL, SIGINT),
                         [](const auto& info) {
                           return info.param == SIGKILL ? std::string("SIGKILL")
                                                        : std::string("SIGINT");
                         });

TEST(SweepCli, WritesTheCsvQuietlyWhenStderrIsNotATerminal) {
  TempDir dir;
  const Outcome r =
      RunCli("sweep --grid phi0=-pi:pi:5 --A 0.5 --c 0.5 -o " + dir.File("a.csv"), dir.File("log"));
  EXPECT_EQ(r.status, 0);
  EXPECT_EQ(r.output, "");
  const std::string csv = ReadFile(dir.File("a.csv"));
  const std::size_t header = csv.find('\n') + 1;  // after the provenance comment
  EXPECT_EQ(csv.substr(header, csv.find('\n', header) - header),
            "phi0,phi1,alpha,u,v_plus,I,v_mean,x_min,x_max,valid,violations");
  EXPECT_EQ(std::count(csv.begin(), csv.end(), '\n'), 7);
}

// The grid's values are the decimals asked for, in shortest round-trip form: the middle of
// -2.8:-2.4:3 is -2.6, not the -2.5999999999999996 of (-2.8 + -2.4)/2 in doubles.
TEST(SweepCli, GridValuesAreTheDecimalsAsked) {
  TempDir dir;
  const Outcome r =
      RunCli("sweep --grid phi0=-2.8:-2.4:3 --grid c=0.1:0.5:5 --A 0.5 -o " + dir.File("a.csv"),
             dir.File("log"));
  ASSERT_EQ(r.status, 0) << r.output;
  std::istringstream csv(ReadFile(dir.File("a.csv")));
  std::string line;
  std::vector<std::string> phi0, c;
  std::getline(csv, line);  // the provenance comment
  std::getline(csv, line);
  ASSERT_EQ(line.rfind("phi0,c,", 0), 0U) << line;
  while (std::getline(csv, line)) {
    const std::vector<std::string> cells = Cells(line);
    ASSERT_GE(cells.size(), 2U) << line;
    if (std::find(phi0.begin(), phi0.end(), cells[0]) == phi0.end()) phi0.push_back(cells[0]);
    if (std::find(c.begin(), c.end(), cells[1]) == c.end()) c.push_back(cells[1]);
  }
  EXPECT_EQ(phi0, (std::vector<std::string>{"-2.8", "-2.6", "-2.4"}));
  EXPECT_EQ(c, (std::vector<std::string>{"0.1", "0.2", "0.3", "0.4", "0.5"}));
}

TEST(SweepCli, DashWritesTheSameCsvToStandardOutput) {
  TempDir dir;
  const std::string args = "sweep --grid phi0=-pi:pi:7 --grid c=0.1:0.5:3 --A 0.5";
  ASSERT_EQ(RunCli(args + " -o " + dir.File("a.csv"), dir.File("log1")).status, 0);
  const int raw = std::system((kCli + " " + args + " -o - > " + dir.File("b.csv")).c_str());
  ASSERT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 0);
  EXPECT_EQ(ReadFile(dir.File("b.csv")), ReadFile(dir.File("a.csv")));
  EXPECT_FALSE(Exists("-.partial"));
  const Outcome r = RunCli(args + " -o - --resume", dir.File("log2"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.output.find("--resume with output - is invalid"), std::string::npos) << r.output;
}

struct BadCommand {
  const char* args;
  const char* message;  // expected substring of the one-line error
};

class SweepCliRejects : public ::testing::TestWithParam<BadCommand> {};

TEST_P(SweepCliRejects, WithStatus2AndAMessage) {
  TempDir dir;
  const Outcome r =
      RunCli(std::string("sweep ") + GetParam().args + " -o " + dir.File("x.csv"), dir.File("log"));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_NE(r.output.find(GetParam().message), std::string::npos) << r.output;
  EXPECT_EQ(std::count(r.output.begin(), r.output.end(), '\n'), 1) << r.output;
  // nothing is left behind: no output, no partial file, no checkpoint
  EXPECT_FALSE(Exists(dir.File("x.csv")));
  EXPECT_FALSE(Exists(dir.File("x.csv.partial")));
  EXPECT_FALSE(Exists(dir.File("x.csv.checkpoint")));
}

INSTANTIATE_TEST_SUITE_P(
    BadCommands, SweepCliRejects,
    ::testing::Values(
        BadCommand{"--grid q=0:1:3 --A 0.5 --c 0.5 --phi0 1",
                   "capsubot sweep: error: --grid q=0:1:3 is invalid: unknown parameter 'q'"},
        BadCommand{"--grid phi0=0:1:0 --A 0.5 --c 0.5",
                   "--grid phi0=0:1:0 is invalid: n = 0: expected n >= 1 points"},
        BadCommand{"--grid phi0=0:1:3 --grid phi0=1:2:3 --A 0.5 --c 0.5",
                   "parameter phi0 already has a grid"},
        BadCommand{"--grid alpha=0.1:0.5:3 --grid phi0=0:1:3 --A 0.5 --c 0.5",
                   "--grid alpha together with grid phi0 is invalid"},
        BadCommand{"--grid phi0=nan:1:3 --A 0.5 --c 0.5", "expected finite bounds"},
        BadCommand{"--grid c=0:1:3 --A 0.5", "--phi0 is missing: give the impact phase phi0"},
        BadCommand{"--grid phi0=0:1:3 --A 0.5", "--c is missing: give the mean force c"},
        BadCommand{"--grid A=0:1:3 --c 0.5 --optimize phi1",
                   "--optimize = phi1 is invalid: expected one of phi0, forcing, fourier"},
        BadCommand{"--grid A=0:1:3 --A 5 --c 0.5 --phi0 1",
                   "--A = 5 is invalid with --grid A=0:1:3: expected the value from only one"},
        BadCommand{"--grid T0=0.1,0.2 --A 0.5 --c 0.1 --optimize forcing",
                   "--A is invalid with --optimize forcing: expected it only with no --optimize, "
                   "--optimize phi0"},
        BadCommand{"--grid T0=0.1,0.2 --optimize forcing --bound 0.15",
                   "force_bound = 0.15 is invalid"},
        BadCommand{"--grid phi0=0:1:3 --A 0.5 --c 0.5 --grid e=0.5:1:1000000 --grid "
                   "margin=0:0.1:1001",
                   "--grid phi0=0:1:3 e=0.5:1:1000000 margin=0:0.1:1001 is invalid: more than "
                   "1000000000 points"},
        BadCommand{"--grid phi0=-1.7e308:1.7e308:5 --A 0.5 --c 0.5",
                   "capsubot sweep: error: --grid phi0=-1.7e308:1.7e308:5 is invalid: the "
                   "bounds are too large for 5 points"},
        BadCommand{"--grid A=0:1e308:10 --c 0.5 --phi0 1",
                   "capsubot sweep: error: --grid A=0:1e308:10 is invalid: the bounds are too "
                   "large for 10 points"},
        BadCommand{"--grid c=0:1:3:log --A 0.5 --phi0 1",
                   "--grid c=0:1:3:log is invalid: expected lo > 0 and hi > 0 for a log grid"},
        BadCommand{"--grid A=0:1:3 --c 0.5 --phi0 1 --optimize phi0",
                   "--phi0 is invalid with --optimize phi0: expected it only with no --optimize"},
        BadCommand{"--grid phi0=0:1:3 --A 0.5 --c 0.5 --threads -2",
                   "--threads = -2 is invalid: expected 1 <= threads"},
        BadCommand{"--grid phi0=0:1:3 --A 0.5 --c 0.5 --T0 0", "friction bound T0 = 0 is invalid"},
        // An option the sweep would not use is refused, not silently ignored.
        BadCommand{"--grid phi0=0:1:3 --A 0.5 --c 0.5 --harmonics 3",
                   "--harmonics is invalid without --optimize: expected it only with --optimize "
                   "fourier"},
        BadCommand{"--grid T0=0.5,1 --optimize forcing --reach-starts 2x2",
                   "--reach-starts is invalid with --optimize forcing: expected it only with "
                   "--optimize reach"},
        BadCommand{"--grid T0=0.5,1 --optimize reach --stability",
                   "--stability is invalid with --optimize reach: expected it only with no "
                   "--optimize, --optimize phi0, --optimize forcing, --optimize fourier"},
        BadCommand{"--grid T0=0.5,1 --optimize reach --A 0.1",
                   "--A is invalid with --optimize reach: expected it only with no --optimize"},
        BadCommand{"--grid T0=0.5,1 --optimize reach --reach-evaluations 0",
                   "--reach-evaluations = 0 is invalid: expected from 1 to 10000000 evaluations"},
        BadCommand{"--grid T0=0.5,1 --optimize reach --alpha 1.5",
                   "--alpha = 1.5 is invalid: expected 0 < alpha < 1"},
        BadCommand{"--grid T0=0.5,1 --optimize reach --grid rho_max=0.5,0.9 --stable-only",
                   "--stable-only (--rho-max = 1) is invalid with --grid rho_max=0.5,0.9"},
        BadCommand{"--grid T0=0.5,1 --optimize forcing --global-evaluations 50",
                   "--global-evaluations is invalid with --global-algorithm multistart"}));

// The first line records what made the file; it leaves out the thread count and the output,
// so that the same content carries the same line, and replaying it gives the same bytes.
TEST(SweepCli, TheProvenanceLineReproducesTheFile) {
  TempDir dir;
  const std::string args =
      "sweep --grid e=0.5,1 --grid c=0.01:0.1:3:log --A 0.2 --phi0 -2.7 --stability";
  ASSERT_EQ(RunCli(args + " --threads 1 -o " + dir.File("a.csv"), dir.File("log")).status, 0);
  ASSERT_EQ(
      RunCli(args + " --threads 2 --checkpoint-seconds 0 -o " + dir.File("b.csv"), dir.File("log"))
          .status,
      0);
  const std::string a = ReadFile(dir.File("a.csv"));
  EXPECT_TRUE(a == ReadFile(dir.File("b.csv"))) << "thread count or checkpoints changed the bytes";
  const std::string version = RunCli("--version", dir.File("v")).output;
  const std::string line = a.substr(0, a.find('\n'));
  EXPECT_EQ(line, "# capsubot " + version.substr(0, version.find('\n')) +
                      " sweep --grid e=0.5,1 --grid c=0.01:0.1:3:log --A 0.2 --phi0 -2.7 "
                      "--T0 1 --margin 0 --margin-stroke 0 --stick-margin 0 --stability");
  // Not how or where it ran, nor the options of optimisers this sweep does not run.
  for (const char* left_out :
       {"--threads", "--output", "-o ", "--checkpoint", "--resume", "--e ", "--rho-max",
        "--scan-points", "--bound", "--harmonics", "--starts", "--hops", "--global-algorithm",
        "--local-algorithm", "--global-evaluations", "--alpha", "--from-rest-starts", "--reach"}) {
    EXPECT_EQ(line.find(left_out), std::string::npos) << left_out << " in " << line;
  }
  // Replay: the command after "# capsubot <version> " with a new output.
  const std::string command = line.substr(line.find(" sweep ") + 1);
  ASSERT_EQ(RunCli(command + " -o " + dir.File("c.csv"), dir.File("log")).status, 0);
  EXPECT_TRUE(ReadFile(dir.File("c.csv")) == a) << "replaying " << command;
  // --no-header-comment: the same file without that line.
  ASSERT_EQ(RunCli(args + " --no-header-comment -o " + dir.File("d.csv"), dir.File("log")).status,
            0);
  EXPECT_EQ(ReadFile(dir.File("d.csv")), a.substr(a.find('\n') + 1));
}

// An optimising sweep records the options of its optimiser (defaults included), and only
// those: P2 has no harmonics, scan points or reach budgets.
TEST(SweepCli, TheProvenanceLineOfAnOptimisingSweepHasItsOptimiserOptions) {
  TempDir dir;
  const Outcome r =
      RunCli("sweep --grid T0=0.1,0.2 --optimize forcing --starts 2 --no-header-comment -o " +
                 dir.File("plain.csv") + " && " + kCli +
                 " sweep --grid T0=0.1,0.2 --optimize forcing --starts 2 -o " + dir.File("p2.csv"),
             dir.File("log"));
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string text = ReadFile(dir.File("p2.csv"));
  const std::string line = text.substr(0, text.find('\n'));
  const std::string options = line.substr(line.find(" sweep ") + 1);
  EXPECT_EQ(options,
            "sweep --grid T0=0.1,0.2 --e 1 --margin 0 --margin-stroke 0 --stick-margin 0 "
            "--optimize forcing --rho-max inf --starts 2 --hops 20 --global-algorithm multistart "
            "--local-algorithm LN_COBYLA");
  EXPECT_EQ(text.substr(text.find('\n') + 1), ReadFile(dir.File("plain.csv")));
}

// `sweep --optimize reach` equals `optimize --problem reach` at each point with the same
// options: the same defaults (the robust seed: rho_max 0.9, d_s = s = 0.02), the same flags.
TEST(SweepCli, ReachSweepEqualsOptimizeProblemReachAtEachPoint) {
  TempDir dir;
  const std::string budget =
      " --starts 2 --hops 1 --from-rest-starts 2x2 --reach-starts 2x2 --reach-evaluations 8 "
      "--reach-local-evaluations 4";
  const Outcome r = RunCli("sweep --grid T0=0.5,1 --optimize reach --threads 2" + budget + " -o " +
                               dir.File("reach.csv"),
                           dir.File("log"));
  ASSERT_EQ(r.status, 0) << r.output;
  const std::string text = ReadFile(dir.File("reach.csv"));
  std::istringstream lines(text);
  std::string comment, header;
  std::getline(lines, comment);
  std::getline(lines, header);
  EXPECT_NE(comment.find(" --rho-max 0.9 "), std::string::npos) << comment;
  EXPECT_NE(comment.find(" --margin-stroke 0.02 --stick-margin 0.02 "), std::string::npos)
      << comment;
  EXPECT_NE(comment.find(" --reach-evaluations 8 --reach-local-evaluations 4"), std::string::npos)
      << comment;
  const std::vector<std::string> names = Cells(header);
  ASSERT_EQ(names.size(), 19u) << header;
  int checked = 0;
  for (const char* T0 : {"0.5", "1"}) {
    std::string row;
    std::getline(lines, row);
    const std::vector<std::string> cells = Cells(row);
    ASSERT_EQ(cells.size(), names.size()) << row;
    EXPECT_EQ(cells[0], T0);
    const Outcome o = RunCli(std::string("optimize --problem reach --json --T0 ") + T0 + budget,
                             dir.File("json"));
    ASSERT_EQ(o.status, 0) << o.output;
    const nlohmann::json j = nlohmann::json::parse(o.output);
    const nlohmann::json& seed = j["seed"];
    const std::vector<std::pair<std::string, nlohmann::json>> expected = {
        {"A", j["A"]},
        {"c", j["c"]},
        {"phi0", j["phi0"]},
        {"alpha", j["alpha"]},
        {"mean_velocity", j["mean_velocity"]},
        {"seed_won", j["seed_won"].get<bool>() ? 1 : 0},
        {"robust_to_settings", j["robust_to_settings"].get<bool>() ? 1 : 0},
        {"max_relative_deviation", j["spread"]["max_relative_deviation"]},
        {"evaluations", j["evaluations"]},
        {"seed_A", seed["A"]},
        {"seed_c", seed["c"]},
        {"seed_phi0", seed["phi0"]},
        {"seed_alpha", seed["alpha"]},
        {"seed_I", seed["I"]},
        {"seed_v_mean", seed["v_mean"]},
        {"seed_mean_velocity_from_rest", seed["mean_velocity_from_rest"]},
        {"seed_reached", seed["reached"]}};
    for (std::size_t i = 0; i < expected.size(); ++i) {
      EXPECT_EQ(names[i + 1], expected[i].first);
      if (expected[i].second.is_null()) {
        // JSON has no infinity: a spread run that hit the simulator's work bound makes the
        // deviation infinite, null in JSON and inf in the CSV.
        EXPECT_EQ(expected[i].first, "max_relative_deviation");
        EXPECT_EQ(cells[i + 1], "inf") << "at T0 = " << T0;
        continue;
      }
      EXPECT_EQ(std::stod(cells[i + 1]), expected[i].second.get<double>())
          << expected[i].first << " at T0 = " << T0;
    }
    EXPECT_EQ(cells.back(), j["status"].get<std::string>());
    EXPECT_EQ(cells.back(), "ok");
    ++checked;
  }
  EXPECT_EQ(checked, 2);
}

// gnuplot reads the file as it is: it skips the comment line and takes the header's names.
TEST(SweepCli, GnuplotReadsTheFileWithItsCommentLine) {
  if (std::system("command -v gnuplot > /dev/null 2>&1") != 0) GTEST_SKIP() << "no gnuplot";
  TempDir dir;
  ASSERT_EQ(
      RunCli("sweep --grid phi0=-pi:pi:9 --A 0.5 --c 0.5 -o " + dir.File("g.csv"), dir.File("log"))
          .status,
      0);
  const std::string script = "set datafile separator ','; set datafile columnheaders; stats '" +
                             dir.File("g.csv") +
                             "' using 'phi1' nooutput; print STATS_records, STATS_max";
  const int raw =
      std::system(("gnuplot -e \"" + script + "\" > " + dir.File("gp") + " 2>&1").c_str());
  ASSERT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 0) << ReadFile(dir.File("gp"));
  // 9 rows; the largest phi1 is at phi0 = +-pi (the paper's example: 2.7337...)
  EXPECT_EQ(ReadFile(dir.File("gp")).rfind("9 2.733716", 0), 0u) << ReadFile(dir.File("gp"));
}

// A resume of a damaged checkpoint is refused with a message naming the flag, not trusted.
TEST(SweepCli, ACorruptedCheckpointIsRefused) {
  TempDir dir;
  const std::string out = dir.File("k.csv");
  const std::vector<std::string> slow = SlowSweep(out, 1);
  const pid_t pid = Spawn(slow);
  ASSERT_GT(pid, 0);
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::seconds(60);
  while (CheckpointPoints(out + ".checkpoint") == 0 &&
         std::chrono::steady_clock::now() < deadline) {
    std::this_thread::sleep_for(std::chrono::milliseconds(2));
  }
  ASSERT_EQ(::kill(pid, SIGKILL), 0);
  int status = 0;
  ASSERT_EQ(::waitpid(pid, &status, 0), pid);
  std::string checkpoint = ReadFile(out + ".checkpoint");
  const std::size_t at = checkpoint.find("points ") + 7;
  checkpoint[at] = checkpoint[at] == '9' ? '8' : '9';  // more points than were written
  std::ofstream(out + ".checkpoint", std::ios::trunc) << checkpoint;
  std::vector<std::string> resume = slow;
  resume.emplace_back("--resume");
  const Outcome r = RunCli(Join(resume), dir.File("log"));
  EXPECT_EQ(r.status, 2);
  EXPECT_EQ(r.output, "capsubot sweep: error: --resume: checkpoint " + out +
                          ".checkpoint is not a valid capsubot sweep checkpoint (checksum "
                          "mismatch): delete it and its .partial file to start the sweep again\n");
  EXPECT_FALSE(Exists(out));
}

TEST(SweepCli, ACheckpointPointingAtAnEndlessFileIsNotRead) {
  TempDir dir;
  const std::string out = dir.File("z.csv");
  const std::string args = "sweep --grid phi0=-pi:pi:50 --A 0.5 --c 0.5 --resume -o " + out;
  std::ofstream(out + ".partial") << "x";
  ASSERT_EQ(::symlink("/dev/zero", (out + ".checkpoint").c_str()), 0);
  const Outcome r = RunCli(args, dir.File("log"));
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.output.find("--resume: checkpoint " + out +
                          ".checkpoint is not a valid capsubot sweep checkpoint (not a regular "
                          "file)"),
            std::string::npos)
      << r.output;
}

TEST(SweepCli, AWriteErrorOnADeviceNamesTheDeviceNotAPartialFile) {
  TempDir dir;
  const Outcome r =
      RunCli("sweep --grid phi0=-pi:pi:50000 --A 0.5 --c 0.5 -o /dev/full", dir.File("log"));
  EXPECT_NE(r.status, 0);
  EXPECT_EQ(r.output,
            "capsubot sweep: error: --output /dev/full: cannot write /dev/full: No space left on "
            "device\n");
}

// A write error part-way (the file size limit, as a full disk) can be mended: the partial
// file and its checkpoint stay, the message says so, and --resume completes the same bytes.
TEST(SweepCli, AWriteErrorPartWayKeepsTheRowsForAResume) {
  TempDir dir;
  const std::string args = "sweep --grid phi0=-pi:pi:4000 --A 0.5 --c 0.5 --checkpoint-seconds 0";
  ASSERT_EQ(RunCli(args + " -o " + dir.File("ref.csv"), dir.File("log")).status, 0);
  const std::string out = dir.File("f.csv");
  // 200 blocks of 512 bytes: about a quarter of the file. capsubot ignores SIGXFSZ itself, so
  // the write fails (EFBIG) and is reported instead of killing the run.
  const std::string limited =
      "sh -c \"ulimit -f 200; exec " + kCli + " " + args + " -o " + out + "\"";
  const int raw = std::system((limited + " > " + dir.File("log") + " 2>&1").c_str());
  const std::string message = ReadFile(dir.File("log"));
  ASSERT_TRUE(WIFEXITED(raw)) << message;
  EXPECT_EQ(WEXITSTATUS(raw), 1) << message;  // the input was fine: a write error
  EXPECT_EQ(message.rfind("capsubot sweep: error: --output " + out + ": cannot write " + out +
                              ".partial: File too large; the rows done are kept in " + out +
                              ".partial with its checkpoint " + out +
                              ".checkpoint for a resume: run the same command with --resume to "
                              "continue\n",
                          0),
            0u)
      << message;
  EXPECT_FALSE(Exists(out));
  EXPECT_TRUE(Exists(out + ".partial"));
  EXPECT_TRUE(Exists(out + ".checkpoint"));
  const Outcome r = RunCli(args + " -o " + out + " --resume", dir.File("log2"));
  ASSERT_EQ(r.status, 0) << r.output;
  EXPECT_TRUE(ReadFile(out) == ReadFile(dir.File("ref.csv")));
  EXPECT_FALSE(Exists(out + ".partial"));
  EXPECT_FALSE(Exists(out + ".checkpoint"));
}

// CRC-32 (the polynomial of zlib, reflected 0xEDB88320), bit by bit: an independent
// computation of the checksum a checkpoint carries of itself.
std::uint32_t Crc32(const std::string& text) {
  std::uint32_t crc = 0xFFFFFFFFu;
  for (const char ch : text) {
    crc ^= static_cast<unsigned char>(ch);
    for (int bit = 0; bit < 8; ++bit) crc = (crc >> 1) ^ (0xEDB88320u & (0u - (crc & 1u)));
  }
  return ~crc;
}

// `checkpoint` with its `points` line set to `points` and its own checksum made valid again:
// a checkpoint whose only damage is its point count.
std::string WithPoints(const std::string& checkpoint, long long points) {
  const std::size_t at = checkpoint.find("\npoints ") + 8;
  const std::size_t end = checkpoint.find('\n', at);
  std::string record = checkpoint.substr(0, checkpoint.rfind("crc32 "));
  record.replace(at, end - at, std::to_string(points));
  char line[32];
  std::snprintf(line, sizeof line, "crc32 %08x\n", Crc32(record));
  return record + line;
}

// A checkpoint with a valid checksum but another point count than the rows it vouches for
// (one more: a point skipped; 0: points written twice; beyond the grid) is refused, never
// trusted; a checkpoint without its partial file is named as such, no empty file created.
TEST(SweepCli, ACheckpointWithAWrongPointCountIsRefused) {
  TempDir dir;
  const std::string args = "sweep --grid phi0=-pi:pi:4000 --A 0.5 --c 0.5 --checkpoint-seconds 0";
  const std::string out = dir.File("f.csv");
  const std::string limited =
      "sh -c \"ulimit -f 200; exec " + kCli + " " + args + " -o " + out + "\"";
  const int raw = std::system((limited + " > " + dir.File("log") + " 2>&1").c_str());
  ASSERT_TRUE(WIFEXITED(raw) && WEXITSTATUS(raw) == 1) << ReadFile(dir.File("log"));
  const std::string checkpoint = ReadFile(out + ".checkpoint");
  const long points = CheckpointPoints(out + ".checkpoint");
  ASSERT_GT(points, 0) << checkpoint;
  // The untouched checkpoint rewritten by WithPoints is the same file: the helper is exact.
  ASSERT_EQ(WithPoints(checkpoint, points), checkpoint);
  int checked = 0;
  for (const long long wrong : {static_cast<long long>(points) + 1, 0LL, 4001LL}) {
    std::ofstream(out + ".checkpoint", std::ios::trunc) << WithPoints(checkpoint, wrong);
    const Outcome r = RunCli(args + " -o " + out + " --resume", dir.File("log2"));
    EXPECT_EQ(r.status, 2) << wrong << ": " << r.output;
    EXPECT_NE(r.output.find("--resume: checkpoint " + out +
                            ".checkpoint is not a valid capsubot sweep checkpoint (it says " +
                            std::to_string(wrong) + " points, but the "),
              std::string::npos)
        << r.output;
    EXPECT_NE(r.output.find(" bytes it vouches for hold " + std::to_string(points) +
                            " of the sweep's 4000 points)"),
              std::string::npos)
        << r.output;
    EXPECT_FALSE(Exists(out));
    ++checked;
  }
  EXPECT_EQ(checked, 3);
  // Without its partial file.
  std::ofstream(out + ".checkpoint", std::ios::trunc) << checkpoint;
  std::remove((out + ".partial").c_str());
  const Outcome r = RunCli(args + " -o " + out + " --resume", dir.File("log3"));
  EXPECT_EQ(r.status, 2) << r.output;
  EXPECT_EQ(r.output, "capsubot sweep: error: --resume: " + out +
                          ".partial is missing, but its "
                          "checkpoint " +
                          out + ".checkpoint says it holds " + std::to_string(points) +
                          " points (" +
                          checkpoint.substr(checkpoint.find("bytes ") + 6,
                                            checkpoint.find('\n', checkpoint.find("bytes ")) -
                                                checkpoint.find("bytes ") - 6) +
                          " bytes): expected the partial file of the interrupted sweep beside its "
                          "checkpoint (delete the checkpoint to start the sweep again)\n");
  EXPECT_FALSE(Exists(out + ".partial"));
}

// Runs `sweep` whole and in `n` shards, merges them; returns the shard paths.
std::vector<std::string> RunShards(const std::string& sweep, int n, const TempDir& dir) {
  EXPECT_EQ(RunCli(sweep + " -o " + dir.File("whole.csv"), dir.File("log")).status, 0);
  std::vector<std::string> shards;
  for (int k = 0; k < n; ++k) {
    shards.push_back(dir.File("shard" + std::to_string(k) + ".csv"));
    const Outcome r = RunCli(
        sweep + " --shard " + std::to_string(k) + "/" + std::to_string(n) + " -o " + shards.back(),
        dir.File("log"));
    EXPECT_EQ(r.status, 0) << r.output;
  }
  return shards;
}

std::string Merge(const std::string& out, const std::vector<std::string>& shards,
                  const TempDir& dir, int* status = nullptr) {
  std::string args = "merge " + out;
  for (const std::string& s : shards) args += " " + s;
  const Outcome r = RunCli(args, dir.File("log"));
  if (status != nullptr) *status = r.status;
  return r.output;
}

class ShardsMerged : public ::testing::TestWithParam<const char*> {};

TEST_P(ShardsMerged, AreByteIdenticalToTheSingleRun) {
  TempDir dir;
  std::vector<std::string> shards = RunShards(GetParam(), 3, dir);
  std::swap(shards[0], shards[2]);  // any order
  int status = -1;
  const std::string message = Merge(dir.File("merged.csv"), shards, dir, &status);
  ASSERT_EQ(status, 0) << message;
  const std::string whole = ReadFile(dir.File("whole.csv"));
  EXPECT_GT(whole.size(), 1000u);
  EXPECT_TRUE(ReadFile(dir.File("merged.csv")) == whole);
  EXPECT_NE(ReadFile(shards[1]).find("\n# shard 1/3 of "), std::string::npos);
}

INSTANTIATE_TEST_SUITE_P(
    Sweeps, ShardsMerged,
    ::testing::Values("sweep --grid phi0=-pi:pi:301 --grid c=0.1,0.5 --A 0.5 --stability",
                      // robot mode: 0, 1 or 2 rows a point
                      "sweep --grid alpha=0.05:0.95:37 --A 0.5 --c 0.5",
                      "sweep --grid c=0.01:0.3:10 --A 0.2 --optimize phi0 --scan-points 90"));

TEST(MergeRefuses, ShardsOfAnotherRunMissingDuplicatedTruncatedOrLonger) {
  TempDir dir;
  const std::string sweep = "sweep --grid phi0=-pi:pi:100 --A 0.5 --c 0.5";
  const std::vector<std::string> s = RunShards(sweep, 3, dir);
  const std::string other = dir.File("other.csv");
  ASSERT_EQ(RunCli(sweep + " --T0 0.9 --shard 1/3 -o " + other, dir.File("log")).status, 0);
  const std::string text = ReadFile(s[1]);
  const std::string cut_row = dir.File("cut_row.csv"), cut_line = dir.File("cut_line.csv"),
                    longer = dir.File("longer.csv");
  std::ofstream(cut_row) << text.substr(0, text.rfind('\n', text.size() - 2) + 1);  // a row less
  std::ofstream(cut_line) << text.substr(0, text.size() - 5);                       // mid-line
  std::ofstream(longer) << text << text.substr(text.rfind('\n', text.size() - 2) + 1);
  const std::string out = dir.File("merged.csv");
  struct Case {
    std::vector<std::string> files;
    std::string message;
  };
  const std::vector<Case> cases = {
      {{s[0], other, s[2]},
       "capsubot merge: error: shard files " + s[0] + " and " + other +
           " are of different sweeps: expected the same comment lines, header, shard count N "
           "and point count T\n"},
      {{s[0], s[2]},
       "capsubot merge: error: shard files: shard 1/3 missing: expected all 3 shards\n"},
      {{s[0], s[1], s[1], s[2]},
       "capsubot merge: error: shard files " + s[1] + " and " + s[1] + " are both shard 1/3\n"},
      {{s[0], cut_row, s[2]},
       "capsubot merge: error: shard file " + cut_row +
           " is truncated: it ends after 32 of its "
           "33 points\n"},
      {{s[0], cut_line, s[2]},
       "capsubot merge: error: shard file " + cut_line +
           " is truncated: its last line has no line break\n"},
      {{s[0], longer, s[2]},
       "capsubot merge: error: shard file " + longer +
           " holds more rows than its 33 points: expected a shard of this sweep\n"},
      {{s[0], dir.File("whole.csv"), s[2]},
       "capsubot merge: error: shard file " + dir.File("whole.csv") +
           " is invalid: expected a file of `capsubot sweep --shard K/N` (a line '# shard K/N "
           "of T points' with 0 <= K < N, N >= 2, N <= T)\n"},
  };
  int checked = 0;
  for (const Case& c : cases) {
    int status = -1;
    EXPECT_EQ(Merge(out, c.files, dir, &status), c.message);
    EXPECT_EQ(status, 2);
    EXPECT_NE(::access(out.c_str(), F_OK), 0) << "a refused merge wrote " << out;
    ++checked;
  }
  EXPECT_EQ(checked, 7);
}

TEST(MergeRefuses, AnOutputThatIsOneOfTheShardsByAnyName) {
  TempDir dir;
  const std::vector<std::string> s =
      RunShards("sweep --grid phi0=-pi:pi:14 --A 0.5 --c 0.5", 3, dir);
  const std::string bytes = ReadFile(s[0]);
  const std::string link = dir.File("link.csv"), hard = dir.File("hard.csv");
  ASSERT_EQ(::symlink(s[0].c_str(), link.c_str()), 0);
  ASSERT_EQ(::link(s[0].c_str(), hard.c_str()), 0);
  int checked = 0;
  for (const std::string& out : {s[0], link, hard}) {
    int status = -1;
    EXPECT_EQ(Merge(out, s, dir, &status), "capsubot merge: error: output " + out +
                                               " is invalid: it is the shard file " + s[0] +
                                               ": expected a file other than the shards\n");
    EXPECT_EQ(status, 2);
    EXPECT_TRUE(ReadFile(s[0]) == bytes) << "the shard was overwritten through " << out;
    ++checked;
  }
  EXPECT_EQ(checked, 3);
}

TEST(MergeRefuses, ForgedShardNumbersAndEndlessLines) {
  TempDir dir;
  const std::vector<std::string> s =
      RunShards("sweep --grid phi0=-pi:pi:14 --A 0.5 --c 0.5", 3, dir);
  const std::string text = ReadFile(s[1]);
  const std::string line = "# shard 1/3 of 14 points";
  ASSERT_NE(text.find(line), std::string::npos) << text;
  const std::string out = dir.File("merged.csv");
  int checked = 0;
  // Numbers that a 32-bit parse would wrap to 1/3 or 1/3: refused, not merged.
  for (const char* forged :
       {"# shard 1/4294967299 of 14 points", "# shard 4294967297/3 of 14 points",
        "# shard 1/3 of 99999999999999999999 points"}) {
    std::string bad = text;
    bad.replace(bad.find(line), line.size(), forged);
    const std::string file = dir.File("forged" + std::to_string(checked) + ".csv");
    std::ofstream(file) << bad;
    int status = -1;
    EXPECT_NE(Merge(out, {s[0], file, s[2]}, dir, &status)
                  .find("capsubot merge: error: shard file " + file +
                        " is invalid: expected a "
                        "file of `capsubot sweep --shard K/N`"),
              std::string::npos)
        << forged;
    EXPECT_EQ(status, 2);
    EXPECT_NE(::access(out.c_str(), F_OK), 0);
    ++checked;
  }
  // A device that never ends a line: refused at the line limit (1 MiB), not read forever.
  int status = -1;
  EXPECT_EQ(Merge(out, {s[0], "/dev/zero", s[2]}, dir, &status),
            "capsubot merge: error: shard file /dev/zero is invalid: a line longer than 1048576 "
            "bytes\n");
  EXPECT_EQ(status, 2);
  EXPECT_NE(::access(out.c_str(), F_OK), 0);
  EXPECT_EQ(checked, 3);
}

TEST(SweepShard, BadShardSpecsAreRefused) {
  TempDir dir;
  const std::string sweep = "sweep --grid phi0=-pi:pi:5 --A 0.5 --c 0.5 -o " + dir.File("x.csv");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"3/3", "--shard = 3/3 is invalid: expected K/N with N >= 1 shards and 0 <= K < N"},
      {"-1/3", "--shard -1/3 is invalid: expected K/N"},
      {"1/2/3", "--shard 1/2/3 is invalid: expected K/N"},
      {"0/4294967297", "--shard 0/4294967297 is invalid: expected K/N"},  // not 0/1
      {"4294967297/3", "--shard 4294967297/3 is invalid: expected K/N"},
      {"1/6", "--shard = 1/6 is invalid: the grid has only 5 points"}};
  for (const auto& [spec, message] : cases) {
    const Outcome r = RunCli(sweep + " --shard " + spec, dir.File("log"));
    EXPECT_EQ(r.status, 2) << spec;
    EXPECT_NE(r.output.find(message), std::string::npos) << r.output;
  }
}

}  // namespace
