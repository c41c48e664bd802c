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

TEST(CycleMemo, FollowsACycleOnceThePeriodsFirstKeyRepeats) {
  Memo memo;
  // Two periods of transient, then a cycle of two periods (keys 5 6 7 | 8 9) repeated 3 times.
  const std::vector<std::vector<int>> turns = {{1, 2},    {3, 4}, {5, 6, 7}, {8, 9},
                                               {5, 6, 7}, {8, 9}, {5, 6, 7}, {8, 9}};
  // Found at the start of the fifth period: everything from there on (4 periods, 10 keys).
  EXPECT_EQ(Feed(memo, turns), 10);
}

TEST(CycleMemo, AOnePeriodCycleWithOneKeyWrapsAroundItself) {
  Memo memo;
  EXPECT_EQ(Feed(memo, {{4}, {4}, {4}, {4}, {4}}), 4);
}

TEST(CycleMemo, LeavesTheCycleAtTheFirstDifferentKeyAndFindsItAgain) {
  Memo memo;
  // The cycle (1 2) is followed from period 2; in period 4 the second key differs (3): that
  // one and the rest of the period are computed; period 5 starts like period 1 again.
  const std::vector<std::vector<int>> turns = {{1, 2}, {1, 2}, {1, 2}, {1, 3}, {1, 2}, {1, 2}};
  // Reused: periods 2 and 3 (4 keys), the 1 of period 4, periods 5 and 6 (4 keys).
  EXPECT_EQ(Feed(memo, turns), 9);
}

TEST(CycleMemo, KeysAreLookedUpOnlyAtThePeriodsFirstSearch) {
  Memo memo;
  // Key 2 comes back in the middle of a period: not looked up there (the look-up costs a scan
  // of the last periods' first keys, paid once per period).
  EXPECT_EQ(Feed(memo, {{1, 2}, {3, 2, 4}}), 0);
}

TEST(CycleMemo, ACycleLongerThanItsPeriodBoundIsNotFound) {
  Memo memo;
  std::vector<std::vector<int>> turns;
  const int n = Memo::kMaxTurns + 1;  // distinct first keys, then the same again
  for (int pass = 0; pass < 2; ++pass) {
    for (int k = 0; k < n; ++k) turns.push_back({k});
  }
  EXPECT_EQ(Feed(memo, turns), 0);
  // One period shorter is found: the second pass reuses all of its keys.
  Memo shorter;
  turns.clear();
  for (int pass = 0; pass < 2; ++pass) {
    for (int k = 0; k < n - 1; ++k) turns.push_back({k});
  }
  EXPECT_EQ(Feed(shorter, turns), n - 1);
}

TEST(CycleMemo, AFullTraceStartsAfreshAndStillFindsLaterCycles) {
  Memo memo;
  // More distinct keys than the trace holds, spread over periods, then a repeated period.
  std::vector<std::vector<int>> turns;
  const int keys = static_cast<int>(Memo::kMaxEntries) + 100;
  for (int k = 0; k < keys; k += 10) {
    std::vector<int> period;
    for (int j = k; j < k + 10; ++j) period.push_back(j);
    turns.push_back(period);
  }
  turns.push_back({-1, -2});
  turns.push_back({-1, -2});
  EXPECT_EQ(Feed(memo, turns), 2);
}

}  // namespace
}  // namespace capsubot::detail
