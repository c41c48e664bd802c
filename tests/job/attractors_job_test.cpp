// The attractors job (capsubot/job/attractors_job.hpp): one call gives what the library calls it
// makes give (ClassifyStarts over the grid from rest, WriteStartMap, WriteStartShard), and its
// options are checked before any work, the message naming the parameter.

#include "capsubot/job/attractors_job.hpp"

#include <gtest/gtest.h>

#include <filesystem>
#include <fstream>
#include <sstream>
#include <string>
#include <variant>
#include <vector>

#include "attract_job_cases.hpp"
#include "test_utils.hpp"

namespace capsubot {
namespace {

using testing::InvalidArgumentMessage;
using testing::SameAttractors;

// The job of the stable optimum on a small grid from rest.
AttractorsJobOptions SmallMap() {
  const RobotModel robot = testing::StableOptimum();
  AttractorsJobOptions o;
  o.robot = robot;
  o.starts = {2, 3};
  o.attractor.threads = 2;
  return o;
}

std::string ReadText(const std::filesystem::path& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream text;
  text << in.rdbuf();
  return text.str();
}

TEST(AttractorsJob, IsTheClassificationOfTheGridFromRest) {
  const AttractorsJobOptions o = SmallMap();
  const AttractorsJobResult r = RunAttractorsJob(o);
  const Attractors direct = ClassifyStarts(o.robot, GridStarts(2, 3), o.attractor);
  EXPECT_TRUE(SameAttractors(r.attractors, direct));
  FromRestOptions from_rest;
  from_rest.n_x = 2;
  from_rest.n_psi = 3;
  from_rest.attractor = o.attractor;
  EXPECT_TRUE(SameAttractors(r.attractors, FindAttractors(o.robot, from_rest)));
  // The robot's known motion from rest (tests/attract/attractors_test.cpp): 3 right + 1 left.
  ASSERT_EQ(r.attractors.attractors.size(), 1U);
  EXPECT_EQ(r.attractors.attractors[0].motion.impacts_right, 3);
  EXPECT_EQ(r.options.starts.Starts(), 6);
}

TEST(AttractorsJob, WritesTheMapOfTheLibraryAndTellsTheStartsDone) {
  AttractorsJobOptions o = SmallMap();
  const std::filesystem::path path = testing::TempPath("attractors_job_map.csv");
  o.run = WholeStartMap{path.string(), "# the run\n"};
  std::vector<std::string> stages;
  o.on_stage = [&stages](const std::string& stage) { stages.push_back(stage); };
  std::int64_t told = 0;
  o.progress = [&told](std::int64_t done, std::int64_t total) {
    EXPECT_EQ(total, 6);
    told = done;
  };
  const AttractorsJobResult r = RunAttractorsJob(o);
  EXPECT_EQ(told, 6);
  EXPECT_EQ(stages, (std::vector<std::string>{"attractors: 6 starts", ""}));
  EXPECT_FALSE(r.options.progress);  // the result holds no callback of the caller
  EXPECT_FALSE(r.options.on_stage);
  const std::filesystem::path expected = testing::TempPath("attractors_job_expected.csv");
  WriteStartMap(expected.string(), GridStarts(2, 3), r.attractors, false, "# the run\n");
  EXPECT_EQ(ReadText(path), ReadText(expected));
  EXPECT_EQ(testing::ReadCsv(path).rows.size(), 6U);
}

TEST(AttractorsJob, ShardWritesItsStartsOnlyAndItsWorkIsThem) {
  AttractorsJobOptions o = SmallMap();
  const std::filesystem::path path = testing::TempPath("attractors_job_shard.csv");
  StartMapShard shard;
  shard.file.shard = 1;
  shard.file.shards = 4;
  shard.file.output = path.string();
  o.run = shard;
  const AttractorsJobResult r = RunAttractorsJob(o);
  EXPECT_EQ(r.shard.starts, 2);  // starts 1 and 5 of 6
  EXPECT_TRUE(r.attractors.attractors.empty());
  const testing::CsvLines csv = testing::ReadCsv(path);
  ASSERT_EQ(csv.rows.size(), 2U);
  EXPECT_EQ(csv.comments.back(), "# shard 1/4 of 6 starts");
  const StartMapWork work = AttractorsJobWork(o);
  ASSERT_EQ(work.starts.size(), 2U);
  EXPECT_EQ(work.starts[1].psi, GridStarts(2, 3)[5].psi);
}

TEST(AttractorsJob, BadOptionsAreRefusedNamingTheParameter) {
  struct Case {
    const char* name;
    void (*change)(AttractorsJobOptions&);
    const char* message;
  };
  const Case cases[] = {
      {"grid", [](AttractorsJobOptions& o) { o.starts.n_x = 0; }, "n_x = 0 is invalid"},
      {"starts",
       [](AttractorsJobOptions& o) {
         o.starts = {3000, 3000};
       },
       "starts = 3000x3000 is invalid: expected n_x * n_psi <= 4194304 starts"},
      {"params", [](AttractorsJobOptions& o) { o.robot.params.e = 1.3; }, "restitution e = 1.3"},
      {"record", [](AttractorsJobOptions& o) { o.attractor.motion.record = 3; },
       "record = 3 is invalid"},
      {"alpha", [](AttractorsJobOptions& o) { o.robot.alpha = 1.5; },
       "mass ratio alpha = 1.5 is invalid"},
      {"shard",
       [](AttractorsJobOptions& o) {
         StartMapShard s;
         s.file.shard = 0;
         s.file.shards = 7;
         s.file.output = "never-written.csv";
         o.run = s;
       },
       "shard = 0/7 is invalid: the map has only 6 starts"},
  };
  for (const Case& c : cases) {
    AttractorsJobOptions o = SmallMap();
    c.change(o);
    const std::string message = InvalidArgumentMessage([&] { RunAttractorsJob(o); });
    EXPECT_EQ(message.rfind(c.message, 0), 0U) << c.name << ": " << message;
  }
  EXPECT_FALSE(std::filesystem::exists("never-written.csv"));
}

}  // namespace
}  // namespace capsubot
