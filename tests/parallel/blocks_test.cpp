// Blocks of work computed by threads reach the sink in order with the bytes a sequential loop
// gives; an error of a computer or of the sink stops the run and comes back to the caller.

#include "capsubot/parallel/blocks.hpp"

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace capsubot {
namespace {

// Unit i's bytes: its number and a line break (depend only on i).
BlockComputeFactory NumberLines() {
  return [] {
    return [](std::int64_t begin, std::int64_t end, std::string& out) {
      for (std::int64_t i = begin; i < end; ++i) out += std::to_string(i) + '\n';
      return end - begin;
    };
  };
}

std::string SequentialLines(std::int64_t first, std::int64_t end) {
  std::string s;
  for (std::int64_t i = first; i < end; ++i) s += std::to_string(i) + '\n';
  return s;
}

TEST(LocalBlocks, DeliversEveryBlockInOrderWithTheSequentialBytes) {
  int plans = 0;
  for (int threads : {1, 2, 5}) {
    for (std::int64_t block : {1, 7, 1000}) {
      BlockPlan plan;
      plan.first = 13;
      plan.end = 1013;
      plan.block = block;
      plan.threads = threads;
      std::string bytes;
      std::int64_t count = 0, next = plan.first;
      LocalBlocks().Run(plan, NumberLines(),
                        [&](std::int64_t b, std::int64_t e, const std::string& s, std::int64_t c) {
                          EXPECT_EQ(b, next);
                          EXPECT_EQ(e, std::min(plan.end, b + block));
                          next = e;
                          bytes += s;
                          count += c;
                        });
      EXPECT_EQ(next, plan.end);
      EXPECT_EQ(count, 1000);
      EXPECT_TRUE(bytes == SequentialLines(13, 1013)) << threads << " threads, block " << block;
      ++plans;
    }
  }
  EXPECT_EQ(plans, 9);
}

TEST(LocalBlocks, AnEmptyPlanCallsNoSink) {
  BlockPlan plan;
  plan.first = plan.end = 5;
  plan.threads = 3;
  int calls = 0;
  LocalBlocks().Run(plan, NumberLines(),
                    [&](std::int64_t, std::int64_t, const std::string&, std::int64_t) { ++calls; });
  EXPECT_EQ(calls, 0);
}

TEST(LocalBlocks, AComputerErrorStopsTheRunAndIsRethrown) {
  BlockPlan plan;
  plan.end = 10000;
  plan.block = 3;
  plan.threads = 4;
  const BlockComputeFactory failing = [] {
    return [](std::int64_t begin, std::int64_t end, std::string&) -> std::int64_t {
      if (begin <= 4242 && 4242 < end) throw std::runtime_error("unit 4242 cannot be computed");
      return end - begin;
    };
  };
  std::int64_t last = 0;
  try {
    LocalBlocks().Run(
        plan, failing,
        [&](std::int64_t, std::int64_t e, const std::string&, std::int64_t) { last = e; });
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "unit 4242 cannot be computed");
  }
  EXPECT_LE(last, 4242);  // nothing after the failed block reached the sink
}

TEST(LocalBlocks, ASinkErrorStopsTheRunAndIsRethrown) {
  BlockPlan plan;
  plan.end = 1000;
  plan.threads = 2;
  int calls = 0;
  try {
    LocalBlocks().Run(plan, NumberLines(),
                      [&](std::int64_t, std::int64_t, const std::string&, std::int64_t) {
                        if (++calls == 10) throw std::runtime_error("disk full");
                      });
    ADD_FAILURE() << "no exception";
  } catch (const std::runtime_error& e) {
    EXPECT_STREQ(e.what(), "disk full");
  }
  EXPECT_EQ(calls, 10);
}

TEST(BlockPlan, ValidateNamesTheBadField) {
  BlockPlan plan;
  plan.end = 10;
  plan.block = 0;
  try {
    plan.Validate();
    ADD_FAILURE() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_STREQ(e.what(), "block = 0 is invalid: expected >= 1 unit");
  }
}

TEST(BalancedBlock, GivesEveryThreadAboutEightBlocksUpToTheMost) {
  EXPECT_EQ(BalancedBlock(1000000, 2, 2048), 2048);  // capped
  EXPECT_EQ(BalancedBlock(1600, 2, 2048), 100);      // 1600 / (8 * 2)
  EXPECT_EQ(BalancedBlock(3, 4, 2048), 1);           // at least one unit
}

TEST(WorkerThreads, GivesTheThreadsAskedOrOnePerCoreAtMostOnePerUnit) {
  const int cores = static_cast<int>(std::max(1U, std::thread::hardware_concurrency()));
  EXPECT_EQ(WorkerThreads(3), 3);
  EXPECT_EQ(WorkerThreads(0), cores);
  EXPECT_EQ(WorkerThreads(8, 2), 2);  // one per unit
  EXPECT_EQ(WorkerThreads(0, 1), 1);
  EXPECT_EQ(WorkerThreads(5, 0), 1);  // at least one
  EXPECT_EQ(WorkerThreads(3, 1000), 3);
}

TEST(ComputeThreads, ComputeEveryBlockOfAQueueTakenInOrderByTheCaller) {
  BlockPlan plan;
  plan.end = 1000;
  plan.block = 7;
  plan.threads = 3;
  BlockQueue queue(plan, 4);
  std::string all;
  const BlockComputeFactory make = NumberLines();
  ComputeThreads workers(queue, make, plan.threads);
  int deliveries = 0;
  for (int i = 0; i < 1000 && !queue.done(); ++i) {  // each wait ends with a block or 1 s
    if (queue.DeliverNext([&](std::int64_t, std::int64_t, const std::string& bytes,
                              std::int64_t) { all += bytes; },
                          std::chrono::seconds(1))) {
      ++deliveries;
    }
  }
  workers.Join();
  EXPECT_EQ(deliveries, 143);  // ceil(1000 / 7)
  EXPECT_EQ(all, SequentialLines(0, 1000));
}

}  // namespace
}  // namespace capsubot
