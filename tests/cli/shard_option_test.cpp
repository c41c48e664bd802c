// --shard K/N and the options only a shard takes (capsubot/cli/shard_option.hpp).

#include "capsubot/cli/shard_option.hpp"

#include <gtest/gtest.h>

#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace capsubot::cli {
namespace {

TEST(ShardOption, ReadsShardKOfN) {
  EXPECT_EQ(ParseShard("0/4"), std::make_pair(0, 4));
  EXPECT_EQ(ParseShard("3/4"), std::make_pair(3, 4));
  EXPECT_EQ(ParseShard("0/1"), std::make_pair(0, 1));
  EXPECT_EQ(ParseShard("2147483646/2147483647"), std::make_pair(2147483646, 2147483647));
}

TEST(ShardOption, RefusesAnythingElseNamingTheRule) {
  for (const char* text : {"4/4", "5/4", "-1/4", "+1/4", "1/-4", "0/0", "a/b", "1", "1/", "/4",
                           "1/4/2", " 1/4", "1/4 ", "0x1/4", "2147483648/2147483649", ""}) {
    try {
      ParseShard(text);
      ADD_FAILURE() << "--shard " << text << " was read";
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find("--shard"), std::string::npos) << e.what();
      EXPECT_NE(std::string(e.what()).find("0 <= K < N"), std::string::npos) << e.what();
    }
  }
}

TEST(ShardOption, OnlyTwoShardsOrMoreSplitTheRun) {
  EXPECT_FALSE(SplitsRun(""));
  EXPECT_FALSE(SplitsRun("0/1"));
  EXPECT_TRUE(SplitsRun("0/2"));
  EXPECT_TRUE(SplitsRun("1/2"));
  EXPECT_THROW(SplitsRun("2/2"), std::invalid_argument);
}

TEST(ShardOption, ResumeAndCheckpointsNeedAShard) {
  for (const char* flag : {"--resume", "--checkpoint-seconds"}) {
    CLI::App app{"test"};
    bool resume = false;
    double seconds = 0.5;
    app.add_flag("--resume", resume);
    app.add_option("--checkpoint-seconds", seconds);
    std::vector<std::string> args = {flag};
    if (std::string(flag) == "--checkpoint-seconds") args = {"2", flag};  // last first
    app.parse(args);
    EXPECT_NO_THROW(RequireShardForResume(app, true, "map"));
    try {
      RequireShardForResume(app, false, "map");
      ADD_FAILURE() << flag << " without a shard was accepted";
    } catch (const std::invalid_argument& e) {
      EXPECT_EQ(std::string(e.what()).rfind(std::string(flag) + " is invalid without --shard", 0),
                0u)
          << e.what();
    }
  }
  CLI::App bare{"test"};  // neither given: nothing to refuse
  bool resume = false;
  double seconds = 0.5;
  bare.add_flag("--resume", resume);
  bare.add_option("--checkpoint-seconds", seconds);
  bare.parse(std::vector<std::string>{});
  EXPECT_NO_THROW(RequireShardForResume(bare, false, "map"));
}

}  // namespace
}  // namespace capsubot::cli
