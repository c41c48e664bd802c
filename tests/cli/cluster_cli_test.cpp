// Runs split over processes give the bytes of the run on one machine (docs/cluster.md): a
// sweep threaded, in 3 shards merged and under `mpirun -n 2` (and 3 ranks, oversubscribed);
// a basin map threaded, in 3 shards merged and under mpirun; the starts from rest of
// `attractors -o` threaded, in 3 shards merged and under mpirun (the same report); a design
// grid and its shard threaded and under mpirun; a two-parameter bifurcation study
// threaded, in 3 shards merged (both CSVs) and under mpirun (whole and one shard); a killed
// basin shard and a killed bifurcation shard resumed; the commands that run on one process
// refused under mpirun; bad input under mpirun fails with no file written. The merge errors of
// basin shards (another run, missing, duplicated, truncated) are tested here, those of sweep shards
// in sweep_cli_test.cpp. The mpirun tests are skipped only when capsubot is built without MPI.

#include <gtest/gtest.h>
#include <sys/wait.h>

#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>
#include <vector>

#include "test_utils.hpp"

namespace capsubot::testing {
namespace {

using testing::ReadFile;

#ifdef CAPSUBOT_MPIEXEC
constexpr bool kMpi = true;
constexpr const char* kMpiexec = CAPSUBOT_MPIEXEC;
#else
constexpr bool kMpi = false;
constexpr const char* kMpiexec = "";
#endif

// Runs a shell command with stderr folded into the captured output.
CommandResult Shell(const std::string& command) {
  CommandResult r;
  FILE* pipe = popen((command + " 2>&1").c_str(), "r");
  if (pipe == nullptr) return r;
  char buffer[4096];
  std::size_t n = 0;
  while ((n = fread(buffer, 1, sizeof buffer, pipe)) > 0) r.out.append(buffer, n);
  const int raw = pclose(pipe);
  r.status = WIFEXITED(raw) ? WEXITSTATUS(raw) : -1;
  return r;
}

// `capsubot <args>` on `ranks` MPI processes (oversubscribed: this machine may have fewer
// cores). CI runs as root: OpenMPI then needs the two variables set below.
CommandResult Mpirun(int ranks, const std::string& args) {
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  return Shell(std::string(kMpiexec) + " --oversubscribe -n " + std::to_string(ranks) + " " +
               CAPSUBOT_CLI + " " + args);
}

class Dir {
 public:
  Dir() : path_(TempPath("cluster_cli")) { std::filesystem::create_directories(path_); }
  ~Dir() { std::filesystem::remove_all(path_); }
  std::string File(const std::string& name) const { return (path_ / name).string(); }

 private:
  std::filesystem::path path_;
};

constexpr const char* kSweep = "sweep --grid phi0=-pi:pi:400 --grid c=0.2,0.5 --A 0.5 --stability";
// A small map with several attractors (docs/attractors.md, the coexisting gaits).
constexpr const char* kBasins =
    "basins --A 0.05 --c 0.02 --phi0 -2.842 --T0 0.1 --e 0.5 --alpha 0.2792869076315278 "
    "--starts 8x6 --transient 100 --record 40";
// The same robot and starts from rest as kBasins (its x0-psi plane is the from-rest grid).
constexpr const char* kAttractors =
    "attractors --A 0.05 --c 0.02 --phi0 -2.842 --T0 0.1 --e 0.5 --alpha 0.2792869076315278 "
    "--starts 8x6 --transient 100 --record 40";
// A 3 x 3 design grid whose every point has a gait (m2 searched: about 20 ms a point); the
// robot of design_cli_test.cpp, margins off.
constexpr const char* kDesignGrid =
    "design --m1 0.2 --L 0.02 --mu 0.3 --force-bias 0.1 --frequency 20 --margin 0 "
    "--margin-stroke 0 --stick-margin 0 --rho-max 1 --grid e=0.5,0.7,0.9 "
    "--grid force-amplitude=0.4,0.5,0.6";

TEST(Cluster, SweepThreadedShardedAndUnderMpirunIsTheSameFile) {
  Dir dir;
  const std::string whole = dir.File("whole.csv");
  ASSERT_EQ(RunCli(std::string(kSweep) + " --threads 2 -o " + whole).status, 0);
  const std::string bytes = ReadFile(whole);
  ASSERT_GT(bytes.size(), 10000u);
  ASSERT_EQ(bytes.rfind("# capsubot ", 0), 0u) << "no provenance line";

  std::string merge = "merge " + dir.File("merged.csv");
  for (int k = 0; k < 3; ++k) {
    const std::string shard = dir.File("shard" + std::to_string(k) + ".csv");
    ASSERT_EQ(
        RunCli(std::string(kSweep) + " --shard " + std::to_string(k) + "/3 -o " + shard).status, 0);
    merge += " " + shard;
  }
  const CommandResult merged = RunCli(merge + " 2>&1");
  ASSERT_EQ(merged.status, 0) << merged.out;
  EXPECT_TRUE(ReadFile(dir.File("merged.csv")) == bytes);

  if (!kMpi) GTEST_SKIP() << "capsubot built without MPI (CAPSUBOT_MPI=OFF)";
  int runs = 0;
  for (const char* ranks_threads : {"2 1", "3 2"}) {
    int ranks = 0, threads = 0;
    std::sscanf(ranks_threads, "%d %d", &ranks, &threads);
    const std::string out = dir.File("mpi" + std::to_string(ranks) + ".csv");
    const CommandResult r =
        Mpirun(ranks, std::string(kSweep) + " --threads " + std::to_string(threads) + " -o " + out);
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_TRUE(ReadFile(out) == bytes) << ranks << " ranks";
    EXPECT_FALSE(std::filesystem::exists(out + ".partial"));
    ++runs;
  }
  EXPECT_EQ(runs, 2);
}

TEST(Cluster, BasinMapThreadedAndUnderMpirunIsTheSameFile) {
  if (!kMpi) GTEST_SKIP() << "capsubot built without MPI (CAPSUBOT_MPI=OFF)";
  Dir dir;
  const CommandResult one = RunCli(std::string(kBasins) + " --threads 2 -o " + dir.File("one.csv"));
  ASSERT_EQ(one.status, 0) << one.out;
  const std::string bytes = ReadFile(dir.File("one.csv"));
  ASSERT_GT(bytes.size(), 1000u);
  const CommandResult two =
      Mpirun(2, std::string(kBasins) + " --threads 1 -o " + dir.File("two.csv"));
  ASSERT_EQ(two.status, 0) << two.out;
  EXPECT_TRUE(ReadFile(dir.File("two.csv")) == bytes);
  EXPECT_NE(two.out.find("basins: 48 starts (8 x 6, plane x0-psi) written to "), std::string::npos)
      << two.out;
  // Printed once: by rank 0 only.
  EXPECT_EQ(two.out.find("basins: 48 starts"), two.out.rfind("basins: 48 starts")) << two.out;
}

TEST(Cluster, AttractorsAndDesignGridUnderMpirunAreTheThreadedRun) {
  if (!kMpi) GTEST_SKIP() << "capsubot built without MPI (CAPSUBOT_MPI=OFF)";
  Dir dir;
  // The same -o path for every run: the report names it.
  const std::string map = dir.File("map.csv");
  const CommandResult one = RunCli(std::string(kAttractors) + " --threads 2 -o " + map + " 2>&1");
  ASSERT_EQ(one.status, 0) << one.out;
  EXPECT_NE(one.out.find("attractors from rest: 48 starts"), std::string::npos) << one.out;
  const std::string bytes = ReadFile(map);
  ASSERT_GT(bytes.size(), 1000u);
  int runs = 0;
  for (const char* ranks_threads : {"2 1", "3 2"}) {
    int ranks = 0, threads = 0;
    std::sscanf(ranks_threads, "%d %d", &ranks, &threads);
    std::filesystem::remove(map);
    const CommandResult r = Mpirun(
        ranks, std::string(kAttractors) + " --threads " + std::to_string(threads) + " -o " + map);
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_EQ(r.out, one.out) << ranks << " ranks";  // printed once, by rank 0
    EXPECT_TRUE(ReadFile(map) == bytes) << ranks << " ranks";
    ++runs;
  }
  EXPECT_EQ(runs, 2);

  const std::string grid = dir.File("grid.csv");
  ASSERT_EQ(RunCli(std::string(kDesignGrid) + " --threads 2 -o " + grid).status, 0);
  const std::string rows = ReadFile(grid);
  EXPECT_NE(rows.find("\n0.9,0.6,ok,"), std::string::npos) << rows;
  const CommandResult two =
      Mpirun(2, std::string(kDesignGrid) + " --threads 1 -o " + dir.File("grid_mpi.csv"));
  ASSERT_EQ(two.status, 0) << two.out;
  EXPECT_TRUE(ReadFile(dir.File("grid_mpi.csv")) == rows);
  EXPECT_FALSE(std::filesystem::exists(dir.File("grid_mpi.csv.partial")));
  // A shard to standard output: printed once, by rank 0 (the workers write nothing).
  const CommandResult shard = RunCli(std::string(kDesignGrid) + " --shard 1/2 -o - 2>&1");
  ASSERT_EQ(shard.status, 0) << shard.out;
  EXPECT_NE(shard.out.find("\n# shard 1/2 of 9 points\n"), std::string::npos) << shard.out;
  const CommandResult sharded =
      Mpirun(3, std::string(kDesignGrid) + " --threads 1 --shard 1/2 -o -");
  ASSERT_EQ(sharded.status, 0) << sharded.out;
  EXPECT_EQ(sharded.out, shard.out);
}

// The 3 shard files of kBasins (with `extra` options) in `dir`, as <name>0.csv, <name>1.csv,
// <name>2.csv.
std::vector<std::string> BasinShards(const Dir& dir, const std::string& name = "shard",
                                     const std::string& extra = "") {
  std::vector<std::string> files;
  for (int k = 0; k < 3; ++k) {
    files.push_back(dir.File(name + std::to_string(k) + ".csv"));
    const CommandResult r = RunCli(std::string(kBasins) + extra + " --shard " + std::to_string(k) +
                                   "/3 -o " + files.back());
    EXPECT_EQ(r.status, 0) << r.out;
  }
  return files;
}

CommandResult Merge(const std::string& out, const std::vector<std::string>& shards) {
  std::string args = "merge " + out;
  for (const std::string& s : shards) args += " " + s;
  return RunCli(args + " 2>&1");
}

TEST(Cluster, BasinMapThreadedAndInShardsMergedIsTheSameFile) {
  Dir dir;
  ASSERT_EQ(RunCli(std::string(kBasins) + " --threads 2 -o " + dir.File("one.csv")).status, 0);
  const std::string bytes = ReadFile(dir.File("one.csv"));
  ASSERT_GT(bytes.size(), 1000u);
  ASSERT_EQ(bytes.rfind("# capsubot ", 0), 0u) << "no provenance line";
  std::vector<std::string> shards = BasinShards(dir);
  // 48 starts: shard 1 holds starts 1, 4, ..., 46 with empty attractor cells.
  const std::string one = ReadFile(shards[1]);
  EXPECT_NE(one.find("\n# shard 1/3 of 48 starts\nx0,psi,attractor,"), std::string::npos) << one;
  EXPECT_NE(one.find("\n0.0625,1.0471975511965976,,1,1,0,"), std::string::npos) << one;
  std::swap(shards[0], shards[2]);  // any order
  const CommandResult merged = Merge(dir.File("merged.csv"), shards);
  ASSERT_EQ(merged.status, 0) << merged.out;
  EXPECT_TRUE(ReadFile(dir.File("merged.csv")) == bytes);
}

// --shard 0/1, the one shard of the whole run, writes the file of the run without --shard
// (as sweep and design --grid do), which `merge` need not join.
TEST(Cluster, BasinsAndAttractorsShardZeroOfOneIsTheWholeMap) {
  Dir dir;
  int checked = 0;
  for (const char* command : {kBasins, kAttractors}) {
    const std::string whole = dir.File("whole.csv"), one = dir.File("one.csv");
    ASSERT_EQ(RunCli(std::string(command) + " -o " + whole).status, 0);
    const CommandResult r = RunCli(std::string(command) + " --shard 0/1 -o " + one + " 2>&1");
    ASSERT_EQ(r.status, 0) << r.out;
    EXPECT_GT(ReadFile(whole).size(), 1000u);
    EXPECT_TRUE(ReadFile(one) == ReadFile(whole)) << command;
    const CommandResult resume =
        RunCli(std::string(command) + " --shard 0/1 --resume -o " + one + " 2>&1");
    EXPECT_EQ(resume.status, 2);
    EXPECT_NE(resume.out.find("--resume is invalid without --shard K/N, N >= 2"), std::string::npos)
        << resume.out;
    ++checked;
  }
  EXPECT_EQ(checked, 2);
}

TEST(Cluster, BasinShardMergeErrorsWriteNothing) {
  Dir dir;
  const std::vector<std::string> s = BasinShards(dir);
  const std::string other = BasinShards(dir, "other", " --max-period 7")[1];
  const std::string cut_row = dir.File("cut_row.csv");
  {
    std::string text = ReadFile(s[1]);
    text.erase(text.rfind('\n', text.size() - 2) + 1);  // drop the last row
    std::ofstream(cut_row, std::ios::binary) << text;
  }
  const std::string cut_line = dir.File("cut_line.csv");
  {
    std::string text = ReadFile(s[1]);
    text.erase(text.size() - 5);  // the last row without its end
    std::ofstream(cut_line, std::ios::binary) << text;
  }
  const std::string labelled = dir.File("labelled.csv");
  {
    std::string text = ReadFile(s[1]);
    text.replace(text.find(",,"), 2, ",1,");
    std::ofstream(labelled, std::ios::binary) << text;
  }
  const std::string out = dir.File("merged.csv");
  const std::vector<std::pair<std::vector<std::string>, std::string>> cases = {
      {{s[0], other, s[2]},
       "capsubot merge: error: shard files " + s[0] + " and " + other +
           " are of different basin maps: expected the same comment lines, header, shard count "
           "N and start count T\n"},
      {{s[0], s[2]},
       "capsubot merge: error: shard files: shard 1/3 missing: expected all 3 "
       "shards\n"},
      {{s[0], s[1], s[1], s[2]},
       "capsubot merge: error: shard files " + s[1] + " and " + s[1] + " are both shard 1/3\n"},
      {{s[0], cut_row, s[2]},
       "capsubot merge: error: shard file " + cut_row +
           " is truncated: it ends after 15 of its 16 starts\n"},
      {{s[0], cut_line, s[2]},
       "capsubot merge: error: shard file " + cut_line +
           " is truncated: its last line has no line break\n"},
      {{s[0], labelled, s[2]},
       "capsubot merge: error: shard file " + labelled +
           " start 0 is invalid: expected a row of 8 cells with an empty attractor cell\n"}};
  int checked = 0;
  for (const auto& [files, message] : cases) {
    const CommandResult r = Merge(out, files);
    EXPECT_EQ(r.status, 2) << r.out;
    EXPECT_EQ(r.out, message);
    EXPECT_FALSE(std::filesystem::exists(out)) << "a refused merge wrote " << out;
    ++checked;
  }
  EXPECT_EQ(checked, 6);
}

TEST(Cluster, BadBasinShardOptionsAreRefused) {
  Dir dir;
  const std::string out = dir.File("x.csv");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"--shard 3/3", "--shard = 3/3 is invalid: expected K/N with N >= 1 shards and 0 <= K < N"},
      {"--shard 1/x", "--shard 1/x is invalid: expected K/N"},
      {"--shard 0/49", "--shard = 0/49 is invalid: the map has only 48 starts"},
      {"--shard 0/2 --plot " + dir.File("x.png"), "--plot is invalid with --shard"}};
  int checked = 0;
  for (const auto& [args, message] : cases) {
    const CommandResult r = RunCli(std::string(kBasins) + " " + args + " -o " + out + " 2>&1");
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_NE(r.out.find(message), std::string::npos) << r.out;
    EXPECT_FALSE(std::filesystem::exists(out));
    ++checked;
  }
  EXPECT_EQ(checked, 4);
}

std::vector<std::string> AttractorShards(const Dir& dir, const std::string& name = "attr") {
  std::vector<std::string> files;
  for (int k = 0; k < 3; ++k) {
    files.push_back(dir.File(name + std::to_string(k) + ".csv"));
    const CommandResult r = RunCli(std::string(kAttractors) + " --shard " + std::to_string(k) +
                                   "/3 -o " + files.back());
    EXPECT_EQ(r.status, 0) << r.out;
  }
  return files;
}

TEST(Cluster, AttractorsThreadedAndInShardsMergedIsTheSameFile) {
  Dir dir;
  const CommandResult one =
      RunCli(std::string(kAttractors) + " --threads 2 -o " + dir.File("one.csv"));
  ASSERT_EQ(one.status, 0) << one.out;
  EXPECT_NE(one.out.find("the motion of every start written to"), std::string::npos) << one.out;
  const std::string bytes = ReadFile(dir.File("one.csv"));
  ASSERT_GT(bytes.size(), 1000u);
  ASSERT_EQ(bytes.rfind("# capsubot ", 0), 0u) << "no provenance line";
  // The from-rest grid of `attractors` is the x0-psi map of `basins`: the same table, under
  // the provenance of each command.
  ASSERT_EQ(RunCli(std::string(kBasins) + " --threads 2 -o " + dir.File("map.csv")).status, 0);
  const CsvLines map = ReadCsv(dir.File("map.csv")), attractors = SplitCsv(bytes);
  EXPECT_EQ(map.header, attractors.header);
  EXPECT_TRUE(map.rows == attractors.rows);
  ASSERT_EQ(map.comments.size(), 1u);
  EXPECT_NE(map.comments[0].find(" basins --A 0.05 "), std::string::npos) << map.comments[0];

  const std::vector<std::string> shards = AttractorShards(dir);
  EXPECT_NE(ReadFile(shards[1]).find("\n# shard 1/3 of 48 starts\nx0,psi,attractor,"),
            std::string::npos);
  int orders = 0;
  for (const std::vector<std::string>& order :
       {shards, std::vector<std::string>{shards[2], shards[0], shards[1]}}) {
    const std::string out = dir.File("merged" + std::to_string(orders) + ".csv");
    const CommandResult merged = Merge(out, order);
    ASSERT_EQ(merged.status, 0) << merged.out;
    EXPECT_TRUE(ReadFile(out) == bytes) << "order " << orders;
    ++orders;
  }
  EXPECT_EQ(orders, 2);
}

TEST(Cluster, AttractorShardMergeErrorsAndBadOptionsWriteNothing) {
  Dir dir;
  const std::vector<std::string> s = AttractorShards(dir);
  const std::string basin = BasinShards(dir)[1];
  const std::string cut_row = dir.File("cut_row.csv");
  {
    std::string text = ReadFile(s[1]);
    text.erase(text.rfind('\n', text.size() - 2) + 1);  // drop the last row
    std::ofstream(cut_row, std::ios::binary) << text;
  }
  const std::string out = dir.File("merged.csv");
  const std::vector<std::pair<std::vector<std::string>, std::string>> merges = {
      {{s[0], basin, s[2]},
       "capsubot merge: error: shard files " + s[0] + " and " + basin +
           " are of different basin maps: expected the same comment lines, header, shard count "
           "N and start count T\n"},
      {{s[1], s[2]},
       "capsubot merge: error: shard files: shard 0/3 missing: expected all 3 shards\n"},
      {{s[0], s[1], s[2], s[2]},
       "capsubot merge: error: shard files " + s[2] + " and " + s[2] + " are both shard 2/3\n"},
      {{s[0], cut_row, s[2]},
       "capsubot merge: error: shard file " + cut_row +
           " is truncated: it ends after 15 of its 16 starts\n"}};
  int checked = 0;
  for (const auto& [files, message] : merges) {
    const CommandResult r = Merge(out, files);
    EXPECT_EQ(r.status, 2) << r.out;
    EXPECT_EQ(r.out, message);
    EXPECT_FALSE(std::filesystem::exists(out)) << "a refused merge wrote " << out;
    ++checked;
  }
  const std::vector<std::pair<std::string, std::string>> options = {
      {"--shard 0/3", "--shard is invalid without -o: expected the shard file to write"},
      {"--shard 0/3 --json -o " + out, "--json is invalid with --shard"},
      {"--shard 0/49 -o " + out, "--shard = 0/49 is invalid: the map has only 48 starts"},
      {"--resume -o " + out, "--resume is invalid without --shard"}};
  for (const auto& [args, message] : options) {
    const CommandResult r = RunCli(std::string(kAttractors) + " " + args + " 2>&1");
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_NE(r.out.find("capsubot attractors: error: " + message), std::string::npos) << r.out;
    EXPECT_FALSE(std::filesystem::exists(out));
    ++checked;
  }
  EXPECT_EQ(checked, 8);
}

// A basin shard slow enough to be killed mid-way (100 starts of about 10 ms each on one
// thread), checkpointed after every block of starts.
std::string SlowBasinShard(const std::string& shard, const std::string& out) {
  return "basins --A 0.05 --c 0.02 --phi0 -2.842 --T0 0.1 --e 0.5 --alpha 0.2792869076315278 "
         "--starts 20x15 --transient 6000 --record 40 --checkpoint-seconds 0 --shard " +
         shard + " -o " + out;
}

TEST(Cluster, KilledBasinShardResumesToTheBytesOfAnUninterruptedOne) {
  Dir dir;
  const std::string reference = dir.File("reference.csv"), killed = dir.File("killed.csv");
  ASSERT_EQ(RunCli(SlowBasinShard("1/3", reference) + " --threads 2").status, 0);
  // Started in the background, killed (SIGKILL) once a checkpoint records some starts (the
  // shell waits at most 60 s).
  const CommandResult kill = Shell(
      std::string(CAPSUBOT_CLI) + " " + SlowBasinShard("1/3", killed) +
      " --threads 1 > /dev/null & pid=$!; for i in $(seq 6000); do grep -qs '^points [1-9]' " +
      killed + ".checkpoint && break; sleep 0.01; done; kill -9 $pid; wait $pid; echo status $?");
  ASSERT_NE(kill.out.find("status 137"), std::string::npos)
      << "the shard ended before it could be killed: " << kill.out;
  EXPECT_FALSE(std::filesystem::exists(killed));
  ASSERT_TRUE(std::filesystem::exists(killed + ".partial"));
  ASSERT_TRUE(std::filesystem::exists(killed + ".checkpoint"));

  // The checkpoint of shard 1 does not resume shard 2, nor another map.
  for (const std::string& other : {SlowBasinShard("2/3", killed) + " --resume",
                                   SlowBasinShard("1/3", killed) + " --resume --max-period 7"}) {
    const CommandResult r = RunCli(other + " 2>&1");
    EXPECT_EQ(r.status, 2) << r.out;
    EXPECT_NE(
        r.out.find(
            ".checkpoint is invalid for this shard: it was written by a shard with other options"),
        std::string::npos)
        << r.out;
    EXPECT_FALSE(std::filesystem::exists(killed));
  }
  const CommandResult resumed = RunCli(SlowBasinShard("1/3", killed) + " --resume --threads 2");
  ASSERT_EQ(resumed.status, 0) << resumed.out;
  EXPECT_NE(resumed.out.find("resumed from the checkpoint"), std::string::npos) << resumed.out;
  EXPECT_TRUE(ReadFile(killed) == ReadFile(reference)) << "resumed shard differs";
  EXPECT_FALSE(std::filesystem::exists(killed + ".partial"));
  EXPECT_FALSE(std::filesystem::exists(killed + ".checkpoint"));
}

// A two-parameter bifurcation study: T0 stepped up and down at 3 values of e (6
// continuations, 9 parts with the analytic orbits).
constexpr const char* kBifurcation =
    "bifurcation --A 0.05 --c 0.02 --phi0 -2.842 --e 0.5 --alpha 0.2792869076315278 --param T0 "
    "--from 0.08 --to 0.12 --steps 4 --transient 40 --record 20 --over e=0.4:0.6:3";

// The 3 shards of kBifurcation (`extra` options): their impacts and summary files.
std::pair<std::vector<std::string>, std::vector<std::string>> BifurcationShards(
    const Dir& dir, const std::string& name = "bif", const std::string& extra = "") {
  std::vector<std::string> impacts, summaries;
  for (int k = 0; k < 3; ++k) {
    impacts.push_back(dir.File(name + "_i" + std::to_string(k) + ".csv"));
    summaries.push_back(dir.File(name + "_s" + std::to_string(k) + ".csv"));
    const CommandResult r =
        RunCli(std::string(kBifurcation) + extra + " --shard " + std::to_string(k) + "/3 -o " +
               impacts.back() + " --summary " + summaries.back());
    EXPECT_EQ(r.status, 0) << r.out;
  }
  return {impacts, summaries};
}

TEST(Cluster, BifurcationStudyThreadedAndInShardsMergedIsTheSameFiles) {
  Dir dir;
  const CommandResult one =
      RunCli(std::string(kBifurcation) + " --threads 2 -o " + dir.File("impacts.csv") +
             " --summary " + dir.File("summary.csv"));
  ASSERT_EQ(one.status, 0) << one.out;
  EXPECT_NE(one.out.find("(4 values, both) for 3 values of e: "), std::string::npos) << one.out;
  const std::string impacts = ReadFile(dir.File("impacts.csv"));
  const std::string summary = ReadFile(dir.File("summary.csv"));
  // The provenance line of the study in both files, then 3 values of e x 4 of T0 x (up, down)
  // rows, plus the analytic orbits.
  const CsvLines summary_csv = SplitCsv(summary), impacts_csv = SplitCsv(impacts);
  ASSERT_EQ(summary_csv.comments.size(), 1u) << summary;
  EXPECT_EQ(summary_csv.comments[0].rfind("# capsubot ", 0), 0u) << summary;
  EXPECT_TRUE(impacts_csv.comments == summary_csv.comments);
  ASSERT_EQ(summary_csv.header.rfind("e,param,direction,period,", 0), 0u) << summary;
  EXPECT_NE(summary.find("\n0.6,0.12,analytic,1,1,0,"), std::string::npos) << summary;
  ASSERT_GT(impacts.size(), 1000u);

  const auto [i, s] = BifurcationShards(dir);
  EXPECT_NE(ReadFile(s[1]).find("\n# shard 1/3 of 6 continuations\ne,param,direction,"),
            std::string::npos);
  int checked = 0;
  for (const auto& [files, bytes] :
       {std::pair{std::vector<std::string>{i[2], i[0], i[1]}, impacts},
        std::pair{std::vector<std::string>{s[1], s[2], s[0]}, summary}, std::pair{s, summary}}) {
    const std::string out = dir.File("merged" + std::to_string(checked) + ".csv");
    const CommandResult merged = Merge(out, files);
    ASSERT_EQ(merged.status, 0) << merged.out;
    EXPECT_TRUE(ReadFile(out) == bytes) << "merge " << checked;
    ++checked;
  }
  EXPECT_EQ(checked, 3);
}

TEST(Cluster, BifurcationShardMergeErrorsAndBadShardsWriteNothing) {
  Dir dir;
  const auto [i, s] = BifurcationShards(dir);
  const std::string other = BifurcationShards(dir, "other", " --max-period 7").second[1];
  const std::string cut = dir.File("cut.csv");
  {
    std::string text = ReadFile(s[1]);
    text.erase(text.rfind('\n', text.size() - 2) + 1);  // drop the last row
    std::ofstream(cut, std::ios::binary) << text;
  }
  const std::string out = dir.File("merged.csv");
  const std::vector<std::pair<std::vector<std::string>, std::string>> merges = {
      {{s[0], other, s[2]},
       "shard files " + s[0] + " and " + other +
           " are of different bifurcation studies: expected the same comment lines, header, "
           "shard count N and continuation count T"},
      {{s[0], i[1], s[2]}, "shard files " + s[0] + " and " + i[1] + " are of different"},
      {{s[0], s[2]}, "shard files: shard 1/3 missing: expected all 3 shards"},
      {{s[0], s[1], s[1], s[2]}, "shard files " + s[1] + " and " + s[1] + " are both shard 1/3"},
      {{s[0], cut, s[2]},
       "shard file " + cut + " is truncated: part 8 ends after 7 of its 8 rows"}};
  int checked = 0;
  for (const auto& [files, message] : merges) {
    const CommandResult r = Merge(out, files);
    EXPECT_EQ(r.status, 2) << r.out;
    EXPECT_NE(r.out.find("capsubot merge: error: " + message), std::string::npos) << r.out;
    EXPECT_FALSE(std::filesystem::exists(out)) << "a refused merge wrote " << out;
    ++checked;
  }
  const std::vector<std::pair<std::string, std::string>> shards = {
      {" --shard 0/7",
       "shard count N = 7 is invalid: the study has 6 continuations (3 values of the second "
       "parameter x 2 directions): expected 1 <= N <= 6"},
      {" --direction up --shard 0/4",
       "shard count N = 4 is invalid: the study has 3 continuations"},
      {" --shard 3/3", "--shard = 3/3 is invalid: expected K/N with N >= 1 shards and 0 <= K < N"},
      {" --shard 0/3 --summary " + out, "--summary = " + out +
                                            " is invalid: it is the file of -o = " + out +
                                            ": expected another file"}};
  for (const auto& [args, message] : shards) {
    const CommandResult r = RunCli(std::string(kBifurcation) + args + " -o " + out + " 2>&1");
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_NE(r.out.find("capsubot bifurcation: error: " + message), std::string::npos) << r.out;
    EXPECT_FALSE(std::filesystem::exists(out));
    EXPECT_FALSE(std::filesystem::exists(out + ".partial"));
    ++checked;
  }
  EXPECT_EQ(checked, 9);
}

TEST(Cluster, BifurcationShardZeroOfOneIsTheWholeStudy) {
  Dir dir;
  ASSERT_EQ(RunCli(std::string(kBifurcation) + " -o " + dir.File("i.csv") + " --summary " +
                   dir.File("s.csv"))
                .status,
            0);
  const CommandResult r = RunCli(std::string(kBifurcation) + " --shard 0/1 -o " +
                                 dir.File("i1.csv") + " --summary " + dir.File("s1.csv"));
  ASSERT_EQ(r.status, 0) << r.out;
  EXPECT_GT(ReadFile(dir.File("i.csv")).size(), 1000u);
  EXPECT_TRUE(ReadFile(dir.File("i1.csv")) == ReadFile(dir.File("i.csv")));
  EXPECT_TRUE(ReadFile(dir.File("s1.csv")) == ReadFile(dir.File("s.csv")));
}

// Part numbers beyond an int (a 32-bit parse wraps 4294967305 to 9, 4294967297 to 1) are
// refused with the line as written.
TEST(Cluster, BifurcationMergeRefusesPartNumbersBeyondRange) {
  Dir dir;
  const auto [i, s] = BifurcationShards(dir);
  const std::string text = ReadFile(s[1]);
  const std::size_t part = text.find("# part 1 of ");
  ASSERT_NE(part, std::string::npos) << text;
  const std::size_t end = text.find('\n', part);
  const std::string line = text.substr(part, end - part);  // "# part 1 of Q: R rows"
  const std::string rows = line.substr(line.find(':'));
  const std::string out = dir.File("merged.csv");
  int checked = 0;
  for (const std::string& forged :
       {"# part 1 of 4294967305" + rows, "# part 4294967297 of 9" + rows,
        "# part 1 of 99999999999" + rows}) {
    std::string bad = text;
    bad.replace(part, line.size(), forged);
    const std::string file = dir.File("forged.csv");
    std::ofstream(file, std::ios::binary) << bad;
    const CommandResult r = Merge(out, {s[0], file, s[2]});
    EXPECT_EQ(r.status, 2) << r.out;
    EXPECT_NE(r.out.find("capsubot merge: error: shard file " + file + " line '" + forged +
                         "' is invalid: expected '# part P of Q: R rows' with 0 <= P < Q <= "
                         "2147483647, R >= 0"),
              std::string::npos)
        << r.out;
    EXPECT_FALSE(std::filesystem::exists(out));
    ++checked;
  }
  EXPECT_EQ(checked, 3);
}

TEST(Cluster, BifurcationUnderMpirunIsTheThreadedRun) {
  if (!kMpi) GTEST_SKIP() << "capsubot built without MPI (CAPSUBOT_MPI=OFF)";
  // The 9 parts of kBifurcation (3 values of e x up, down, analytic) computed on the ranks:
  // the same printed summary (once, by rank 0) and the same bytes of both files as the
  // threaded run; one shard too. The same paths in every run: the summary names them.
  Dir dir;
  const std::string impacts = dir.File("impacts.csv"), summary = dir.File("summary.csv");
  const std::string files = " -o " + impacts + " --summary " + summary;
  int runs = 0;
  for (const std::string& shard : {std::string(), std::string(" --shard 1/3")}) {
    const CommandResult one =
        RunCli(std::string(kBifurcation) + shard + " --threads 2" + files + " 2>&1");
    ASSERT_EQ(one.status, 0) << one.out;
    EXPECT_NE(one.out.find("(4 values, both) for 3 values of e"), std::string::npos) << one.out;
    const std::string impact_bytes = ReadFile(impacts), summary_bytes = ReadFile(summary);
    ASSERT_GT(impact_bytes.size(), 1000u);
    ASSERT_GT(summary_bytes.size(), 500u);
    for (const char* ranks_threads : {"2 1", "3 2"}) {
      int ranks = 0, threads = 0;
      std::sscanf(ranks_threads, "%d %d", &ranks, &threads);
      std::filesystem::remove(impacts);
      std::filesystem::remove(summary);
      const CommandResult r = Mpirun(ranks, std::string(kBifurcation) + shard + " --threads " +
                                                std::to_string(threads) + files);
      ASSERT_EQ(r.status, 0) << r.out;
      EXPECT_EQ(r.out, one.out) << ranks << " ranks" << shard;  // printed once, by rank 0
      EXPECT_TRUE(ReadFile(impacts) == impact_bytes) << ranks << " ranks" << shard;
      EXPECT_TRUE(ReadFile(summary) == summary_bytes) << ranks << " ranks" << shard;
      EXPECT_FALSE(std::filesystem::exists(impacts + ".partial"));
      ++runs;
    }
  }
  EXPECT_EQ(runs, 4);
}

// Shard 1/3 of the study of kBifurcation with a long transient, slow enough to be killed
// mid-way: parts 1 (e = 0.4 down), 6 (e = 0.6 up) and 8 (its analytic orbits), every period
// simulated, a sweep part about 1.3 s on one thread; checkpointed after every part. `extra`:
// more options.
std::string SlowBifurcationShard(const std::string& shard, const std::string& out,
                                 const std::string& extra = "") {
  return "bifurcation --A 0.05 --c 0.02 --phi0 -2.842 --e 0.5 --alpha 0.2792869076315278 "
         "--param T0 --from 0.08 --to 0.12 --steps 4 --transient 300000 --record 20 "
         "--converged-tolerance 0 --over e=0.4:0.6:3 --checkpoint-seconds 0 --shard " +
         shard + " -o " + out + " --summary " + out + ".summary" + extra;
}

TEST(Cluster, KilledBifurcationShardResumesToTheBytesOfAnUninterruptedOne) {
  Dir dir;
  const std::string reference = dir.File("reference.csv"), killed = dir.File("killed.csv");
  const std::string summary = killed + ".summary";
  ASSERT_EQ(RunCli(SlowBifurcationShard("1/3", reference, " --threads 2")).status, 0);
  // Started in the background, killed (SIGKILL) once the checkpoints of both files record a
  // part (-o's is written first; the shell waits at most 60 s).
  const CommandResult kill =
      Shell(std::string(CAPSUBOT_CLI) + " " + SlowBifurcationShard("1/3", killed, " --threads 1") +
            " > /dev/null & pid=$!; for i in $(seq 6000); do grep -qs '^points [1-9]' " + killed +
            ".checkpoint && grep -qs '^points [1-9]' " + summary +
            ".checkpoint && break; sleep 0.01; done; kill -9 $pid; wait $pid; echo status $?");
  ASSERT_NE(kill.out.find("status 137"), std::string::npos)
      << "the shard ended before it could be killed: " << kill.out;
  for (const std::string& file : {killed, summary}) {
    EXPECT_FALSE(std::filesystem::exists(file)) << file;
    ASSERT_TRUE(std::filesystem::exists(file + ".partial")) << file;
    ASSERT_TRUE(std::filesystem::exists(file + ".checkpoint")) << file;
  }
  const std::string partial = ReadFile(killed + ".partial");
  EXPECT_NE(partial.find("\n# part 1 of 9: "), std::string::npos) << partial;

  // The checkpoint of shard 1 does not resume shard 2, nor another study; resume and
  // checkpoints are for shards only. Each refusal leaves the files as they were.
  const std::string checkpoint = ReadFile(killed + ".checkpoint");
  const std::vector<std::pair<std::string, std::string>> refused = {
      {SlowBifurcationShard("2/3", killed, " --resume"),
       "resume: checkpoint " + killed +
           ".checkpoint is invalid for this shard: it was written by a shard with other "
           "options"},
      {SlowBifurcationShard("1/3", killed, " --resume --max-period 7"),
       "resume: checkpoint " + killed + ".checkpoint is invalid for this shard"},
      {std::string(kBifurcation) + " --resume -o " + killed,
       "--resume is invalid without --shard K/N, N >= 2: expected it only for a shard of the study "
       "(a "
       "whole study is not checkpointed)"},
      {std::string(kBifurcation) + " --checkpoint-seconds 1 -o " + killed,
       "--checkpoint-seconds is invalid without --shard"}};
  int checked = 0;
  for (const auto& [args, message] : refused) {
    const CommandResult r = RunCli(args + " 2>&1");
    EXPECT_EQ(r.status, 2) << args;
    EXPECT_NE(r.out.find("capsubot bifurcation: error: " + message), std::string::npos) << r.out;
    EXPECT_FALSE(std::filesystem::exists(killed));
    EXPECT_TRUE(ReadFile(killed + ".partial") == partial) << args;
    EXPECT_TRUE(ReadFile(killed + ".checkpoint") == checkpoint) << args;
    ++checked;
  }
  // A damaged checkpoint of --summary is refused before either file is touched.
  const std::string summary_checkpoint = ReadFile(summary + ".checkpoint");
  {
    std::string damaged = summary_checkpoint;
    damaged[damaged.find("points ") + 7] ^= 1;
    std::ofstream(summary + ".checkpoint", std::ios::binary) << damaged;
  }
  const CommandResult r = RunCli(SlowBifurcationShard("1/3", killed, " --resume") + " 2>&1");
  EXPECT_EQ(r.status, 2);
  EXPECT_NE(r.out.find("capsubot bifurcation: error: resume: checkpoint " + summary +
                       ".checkpoint is not a valid capsubot sweep checkpoint (checksum mismatch)"),
            std::string::npos)
      << r.out;
  EXPECT_TRUE(ReadFile(killed + ".partial") == partial);
  EXPECT_TRUE(ReadFile(killed + ".checkpoint") == checkpoint);
  std::ofstream(summary + ".checkpoint", std::ios::binary) << summary_checkpoint;
  ++checked;
  // A checkpoint whose partial file is gone: named, no empty partial file made.
  std::filesystem::rename(summary + ".partial", summary + ".kept");
  const CommandResult lost = RunCli(SlowBifurcationShard("1/3", killed, " --resume") + " 2>&1");
  EXPECT_EQ(lost.status, 2);
  EXPECT_NE(lost.out.find("capsubot bifurcation: error: resume: " + summary +
                          ".partial is missing, but its checkpoint " + summary +
                          ".checkpoint says it holds "),
            std::string::npos)
      << lost.out;
  EXPECT_FALSE(std::filesystem::exists(summary + ".partial"));
  EXPECT_TRUE(ReadFile(killed + ".partial") == partial);
  std::filesystem::rename(summary + ".kept", summary + ".partial");
  ++checked;
  EXPECT_EQ(checked, 6);
  const CommandResult resumed =
      RunCli(SlowBifurcationShard("1/3", killed, " --resume --threads 2"));
  ASSERT_EQ(resumed.status, 0) << resumed.out;
  EXPECT_NE(resumed.out.find(" resumed from the checkpoint)"), std::string::npos) << resumed.out;
  // The line counts the rows of the whole files, those of the resumed parts too.
  const auto rows = [](const std::string& text) {
    std::istringstream in(text);
    long count = -1;  // the header
    for (std::string line; std::getline(in, line);) count += line.rfind('#', 0) == 0 ? 0 : 1;
    return std::to_string(count);
  };
  EXPECT_NE(resumed.out.find(": " + rows(ReadFile(reference)) + " impacts written to " + killed +
                             ", " + rows(ReadFile(reference + ".summary")) + " summary rows to "),
            std::string::npos)
      << resumed.out;
  EXPECT_TRUE(ReadFile(killed) == ReadFile(reference)) << "resumed impacts differ";
  EXPECT_TRUE(ReadFile(summary) == ReadFile(reference + ".summary")) << "resumed summary differs";
  for (const std::string& file : {killed, summary}) {
    EXPECT_FALSE(std::filesystem::exists(file + ".partial")) << file;
    EXPECT_FALSE(std::filesystem::exists(file + ".checkpoint")) << file;
  }
}

TEST(Cluster, CommandsThatRunOnOneProcessRefuseMpirun) {
  if (!kMpi) GTEST_SKIP() << "capsubot built without MPI (CAPSUBOT_MPI=OFF)";
  // Run P times over, these commands would print P times and write one file P times: each is
  // refused before any work, said once (by rank 0), no file written.
  Dir dir;
  const std::string out = dir.File("out.csv");
  const std::string robot = " --A 0.05 --c 0.02 --phi0 -2.842 --T0 0.1 --e 0.5";
  const std::vector<std::pair<std::string, std::string>> commands = {
      {"solve", "solve" + robot},
      {"simulate", "simulate" + robot + " --from-orbit --periods 4 --events " + out},
      {"design",  // one design (of a point of kDesignGrid): not a grid
       "design --m1 0.2 --L 0.02 --mu 0.3 --force-bias 0.1 --frequency 20 --margin 0 "
       "--margin-stroke 0 --stick-margin 0 --rho-max 1 --e 0.7 --force-amplitude 0.5"}};
  int checked = 0;
  for (const auto& [name, args] : commands) {
    const CommandResult r = Mpirun(2, args);
    EXPECT_NE(r.status, 0) << r.out;
    const std::string message = "capsubot " + name + ": error: mpirun -n 2 is invalid for " + name +
                                ": it runs on one process; expected mpirun only for sweep, "
                                "basins, attractors, bifurcation and design --grid "
                                "(docs/cluster.md)\n";
    const std::size_t at = r.out.find(message);
    EXPECT_NE(at, std::string::npos) << r.out;
    EXPECT_EQ(r.out.find("capsubot " + name + ": error:", at + 1), std::string::npos)
        << "said more than once: " << r.out;
    EXPECT_FALSE(std::filesystem::exists(out)) << name;
    ++checked;
  }
  EXPECT_EQ(checked, 3);
  // Alone (one process), the same command runs.
  const CommandResult alone =
      Mpirun(1, "simulate" + robot + " --from-orbit --periods 4 --events " + out);
  EXPECT_EQ(alone.status, 0) << alone.out;
  EXPECT_TRUE(std::filesystem::exists(out));
}

// mpirun copies rank 0's standard output to its own and ignores a write that fails there: the
// run writes mpirun's standard output itself, and a full one fails it (exit 1), as alone.
TEST(Cluster, FullStandardOutputUnderMpirunFails) {
  if (!kMpi) GTEST_SKIP() << "capsubot built without MPI (CAPSUBOT_MPI=OFF)";
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT", "1", 1);
  ::setenv("OMPI_ALLOW_RUN_AS_ROOT_CONFIRM", "1", 1);
  const std::string sweep = std::string(kMpiexec) + " --oversubscribe -n 2 " + CAPSUBOT_CLI +
                            " sweep --grid A=0:1:3 --c 0.5 --phi0 0 -o -";
  const CommandResult full = Shell("sh -c '" + sweep + " > /dev/full'");
  EXPECT_EQ(full.status, 1) << full.out;
  EXPECT_NE(full.out.find("capsubot sweep: error: --output -: cannot write standard output: No "
                          "space left on device"),
            std::string::npos)
      << full.out;
  // Written through a pipe, the header and the 3 rows arrive whole.
  const CommandResult piped = Shell(sweep + " | grep -c ,");
  EXPECT_EQ(piped.status, 0) << piped.out;
  EXPECT_EQ(piped.out, "4\n");
}

TEST(Cluster, BadInputUnderMpirunFailsOnceAndWritesNoFile) {
  if (!kMpi) GTEST_SKIP() << "capsubot built without MPI (CAPSUBOT_MPI=OFF)";
  Dir dir;
  const std::string out = dir.File("bad.csv");
  // Every process parses the same command line: bad input is said once, by rank 0, whether
  // it is found by the parser (an unknown option, a bad --grid) or by the run (rank 0 finds
  // the bad value; the workers are told to stop).
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"sweep --grid phi0=-pi:pi:100 --A 0.5 --c 0.5 --e 1.3 -o " + out,
       "capsubot sweep: error: restitution e = 1.3 is invalid"},
      {"sweep --grid phi0=-pi:pi:100 --A 0.5 --c 0.5 --no-such-option -o " + out,
       "capsubot sweep: error: "},
      {"bifurcation --A 0.05 --c 0.02 --phi0 -2.842 --e 0.5 --alpha 0.3 --param T0 --from 0.08 "
       "--to 0.12 --steps 4 --over e=0.4:0.6:0 -o " +
           out,
       "capsubot bifurcation: error: "}};
  int checked = 0;
  for (const auto& [args, message] : cases) {
    const CommandResult r = Mpirun(2, args);
    EXPECT_EQ(r.status, 2) << r.out;
    const std::size_t at = r.out.find(message);
    EXPECT_NE(at, std::string::npos) << r.out;
    EXPECT_EQ(r.out.find(message, at + 1), std::string::npos) << "said more than once: " << r.out;
    EXPECT_FALSE(std::filesystem::exists(out)) << args;
    EXPECT_FALSE(std::filesystem::exists(out + ".partial")) << args;
    ++checked;
  }
  EXPECT_EQ(checked, 3);
}

}  // namespace
}  // namespace capsubot::testing
