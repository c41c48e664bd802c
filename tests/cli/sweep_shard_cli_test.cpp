// `capsubot sweep --shard K/N` and `capsubot merge`: N shards computed apart and merged give
// the bytes of the single run (plain, robot mode with several rows a point, an optimisation);
// merge refuses shards of another run, a missing, duplicated or truncated shard, extra rows.

#include <gtest/gtest.h>
#include <sys/wait.h>
#include <unistd.h>

#include <cstdlib>
#include <fstream>
#include <sstream>
#include <string>
#include <vector>

namespace {

const std::string kCli = CAPSUBOT_CLI;

class TempDir {
 public:
  TempDir() {
    char pattern[] = "/tmp/capsubot_shard_cli_test_XXXXXX";
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

struct Outcome {
  int status = -1;
  std::string output;  // stdout and stderr
};

Outcome RunCli(const std::string& args, const TempDir& dir) {
  const std::string log = dir.File("log");
  const int raw = std::system((kCli + " " + args + " > '" + log + "' 2>&1").c_str());
  return {WIFEXITED(raw) ? WEXITSTATUS(raw) : -1, ReadFile(log)};
}

// Runs `sweep` whole and in `n` shards, merges them; returns the shard paths.
std::vector<std::string> RunShards(const std::string& sweep, int n, const TempDir& dir) {
  EXPECT_EQ(RunCli(sweep + " -o " + dir.File("whole.csv"), dir).status, 0);
  std::vector<std::string> shards;
  for (int k = 0; k < n; ++k) {
    shards.push_back(dir.File("shard" + std::to_string(k) + ".csv"));
    const Outcome r = RunCli(
        sweep + " --shard " + std::to_string(k) + "/" + std::to_string(n) + " -o " + shards.back(),
        dir);
    EXPECT_EQ(r.status, 0) << r.output;
  }
  return shards;
}

std::string Merge(const std::string& out, const std::vector<std::string>& shards,
                  const TempDir& dir, int* status = nullptr) {
  std::string args = "merge " + out;
  for (const std::string& s : shards) args += " " + s;
  const Outcome r = RunCli(args, dir);
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
  ASSERT_EQ(RunCli(sweep + " --T0 0.9 --shard 1/3 -o " + other, dir).status, 0);
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

TEST(SweepShard, BadShardSpecsAreRefused) {
  TempDir dir;
  const std::string sweep = "sweep --grid phi0=-pi:pi:5 --A 0.5 --c 0.5 -o " + dir.File("x.csv");
  const std::vector<std::pair<std::string, std::string>> cases = {
      {"3/3", "--shard = 3/3 is invalid: expected K/N with N >= 1 shards and 0 <= K < N"},
      {"-1/3", "--shard -1/3 is invalid: expected K/N"},
      {"1/2/3", "--shard 1/2/3 is invalid: expected K/N"},
      {"1/6", "--shard = 1/6 is invalid: the grid has only 5 points"}};
  for (const auto& [spec, message] : cases) {
    const Outcome r = RunCli(sweep + " --shard " + spec, dir);
    EXPECT_EQ(r.status, 2) << spec;
    EXPECT_NE(r.output.find(message), std::string::npos) << r.output;
  }
}

}  // namespace
