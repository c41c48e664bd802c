// The memo of results along repeated cycles (src/simulate/cycle_memo.hpp): it returns a stored
// result only for a key equal to the one it was stored for, follows a cycle once the first key
// of a period repeats, and leaves it at the first key that differs.

#include "simulate/cycle_memo.hpp"

#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

namespace capsubot::detail {
namespace {

using Memo = CycleMemo<int, int>;

// Feeds the keys of `turns` (one list per period) to the memo as the simulator does: Find,
// and on a miss the result (here 10 times the key) is computed and added. Returns how many
// results came from the memo; every one of them must be the result of its key.
int Feed(Memo& memo, const std::vector<std::vector<int>>& turns, std::int64_t first_turn = 0) {
  int reused = 0;
  std::int64_t turn = first_turn;
  for (const std::vector<int>& keys : turns) {
    for (const int key : keys) {
      if (const int* known = memo.Find(key, turn)) {
        EXPECT_EQ(*known, 10 * key);
        ++reused;
      } else {
        memo.Add(key, 10 * key);
      }
    }
    ++turn;
  }
  return reused;
}

TEST(CycleMemo, RecordsTheCycleAfterAFirstKeyRepeatsAndReplaysItOnceItCloses) {
  Memo memo;
  // Two periods of transient, then a cycle of two periods (keys 5 6 7 | 8 9) four times: the
  // third period's first key comes back in the fifth, which starts the record; it closes in
  // the seventh, from which on everything is replayed (2 periods, 5 keys).
  const std::vector<std::vector<int>> turns = {{1, 2},    {3, 4}, {5, 6, 7}, {8, 9},
                                               {5, 6, 7}, {8, 9}, {5, 6, 7}, {8, 9}};
  EXPECT_EQ(Feed(memo, turns), 5);
  // Two more cycles: all replayed.
  EXPECT_EQ(Feed(memo, {{5, 6, 7}, {8, 9}, {5, 6, 7}, {8, 9}}, 8), 10);
}

TEST(CycleMemo, AOnePeriodCycleWithOneKeyWrapsAroundItself) {
  Memo memo;
  // Remembered in period 0, seen again and recorded in 1, closed in 2: replayed from there.
  EXPECT_EQ(Feed(memo, {{4}, {4}, {4}, {4}, {4}}), 3);
}

TEST(CycleMemo, LeavesTheCycleAtTheFirstDifferentKeyAndFindsItAgain) {
  Memo memo;
  // The cycle (1 2) is recorded in period 1 and replayed from period 2; in period 3 the
  // second key differs (3): the memo leaves the cycle, records it again in period 4 (its
  // first key was seen) and replays it from period 5.
  const std::vector<std::vector<int>> turns = {{1, 2}, {1, 2}, {1, 2}, {1, 3}, {1, 2}, {1, 2}};
  // Replayed: period 2 (2 keys), the 1 of period 3, period 5 (2 keys).
  EXPECT_EQ(Feed(memo, turns), 5);
}

TEST(CycleMemo, KeysAreLookedUpOnlyAtThePeriodsFirstSearch) {
  Memo memo;
  // Key 2 comes back in the middle of a period, and again as a first key: only the latter
  // starts a record (a look-up scans the last periods' first keys, paid once per period).
  EXPECT_EQ(Feed(memo, {{1, 2}, {3, 2, 4}, {2}, {2}, {2}}), 1);
}

TEST(CycleMemo, ACycleLongerThanItsPeriodBoundIsNotFound) {
  // Distinct first keys for kMaxTurns + 1 periods, repeated three times: the first key of a
  // pass has left the ring when it comes back.
  const auto passes = [](int n) {
    std::vector<std::vector<int>> turns;
    for (int pass = 0; pass < 3; ++pass) {
      for (int k = 0; k < n; ++k) turns.push_back({k});
    }
    return turns;
  };
  Memo longer;
  EXPECT_EQ(Feed(longer, passes(Memo::kMaxTurns + 1)), 0);
  // kMaxTurns periods: seen in the second pass, recorded there, replayed in the third.
  Memo bound;
  EXPECT_EQ(Feed(bound, passes(Memo::kMaxTurns)), Memo::kMaxTurns);
}

TEST(CycleMemo, ACycleOfMoreResultsThanTheTraceHoldsIsNotRecorded) {
  // Two periods of n keys each, repeated: a cycle of 2n results.
  const auto cycle = [](int n, int cycles) {
    std::vector<std::vector<int>> turns;
    for (int c = 0; c < cycles; ++c) {
      for (int half = 0; half < 2; ++half) {
        std::vector<int> period;
        for (int k = 0; k < n; ++k) period.push_back(half * n + k);
        turns.push_back(period);
      }
    }
    return turns;
  };
  const int fits = static_cast<int>(Memo::kMaxEntries) / 2;  // 2n = kMaxEntries
  Memo small, large;
  // Recorded in the second cycle, replayed in the third and fourth.
  EXPECT_EQ(Feed(small, cycle(fits, 4)), 4 * fits);
  EXPECT_EQ(Feed(large, cycle(fits + 1, 4)), 0);
}

}  // namespace
}  // namespace capsubot::detail
