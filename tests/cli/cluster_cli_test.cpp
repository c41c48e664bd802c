// Runs split over processes give the bytes of the run on one machine (docs/cluster.md): a
// sweep threaded, in 3 shards merged and under `mpirun -n 2` (and 3 ranks, oversubscribed);
// a basin map threaded, in 3 shards merged and under mpirun; bad input under mpirun fails with
// no file written. The merge errors of basin shards (another run, missing, duplicated,
// truncated) are tested here, those of sweep shards in sweep_cli_test.cpp. The mpirun tests are
// skipped only when capsubot is built without MPI.

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

#ifdef CAPSUBOT_MPIEXEC
constexpr bool kMpi = true;
constexpr const char* kMpiexec = CAPSUBOT_MPIEXEC;
#else
constexpr bool kMpi = false;
constexpr const char* kMpiexec = "";
#endif

std::string ReadFile(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream s;
  s << in.rdbuf();
  return s.str();
}

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

TEST(Cluster, SweepThreadedShardedAndUnderMpirunIsTheSameFile) {
  Dir dir;
  const std::string whole = dir.File("whole.csv");
  ASSERT_EQ(RunCli(std::string(kSweep) + " --threads 2 -o " + whole).status, 0);
  const std::string bytes = ReadFile(whole);
  ASSERT_GT(bytes.size(), 10000u);

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

TEST(Cluster, BadInputUnderMpirunFailsAndWritesNoFile) {
  if (!kMpi) GTEST_SKIP() << "capsubot built without MPI (CAPSUBOT_MPI=OFF)";
  Dir dir;
  const std::string out = dir.File("bad.csv");
  // Rank 0 finds the bad value; the workers are told to stop.
  const CommandResult r =
      Mpirun(2, "sweep --grid phi0=-pi:pi:100 --A 0.5 --c 0.5 --e 1.3 -o " + out);
  EXPECT_NE(r.status, 0) << r.out;
  EXPECT_NE(r.out.find("capsubot sweep: error: restitution e = 1.3 is invalid"), std::string::npos)
      << r.out;
  EXPECT_FALSE(std::filesystem::exists(out));
  EXPECT_FALSE(std::filesystem::exists(out + ".partial"));
}

}  // namespace
}  // namespace capsubot::testing
