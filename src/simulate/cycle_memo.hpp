#pragma once
// The results of a pure function of the simulator's state (the event search of a segment),
// kept along a run so that a run which comes back, bit for bit, to a state it had earlier
// takes them from here instead of computing them again (docs/simulate.md, "Repeated cycles").
// A motion that has settled on a periodic attractor does so within a few tens of periods:
// rounding then maps the state onto itself exactly, and from there the run repeats the
// same events forever. Each stored result is used only when its key equals the present one
// in every bit, so a run with the memo is the run without it, bit for bit.
//
// Cost: the state is looked up among the first keys of the last kMaxTurns periods once per
// period; along a detected cycle each use compares one key. The trace holds at most
// kMaxEntries results (it starts afresh when full).

#include <array>
#include <cstddef>
#include <cstdint>
#include <vector>

namespace capsubot::detail {

template <class Key, class Value>
class CycleMemo {
 public:
  /// Longest cycle looked for, in periods.
  static constexpr int kMaxTurns = 64;
  /// Most results kept.
  static constexpr std::size_t kMaxEntries = 4096;

  /// The stored result for `key` in period `turn`: the next one of a cycle the run follows,
  /// or, at the first look-up of a period, the one stored for the same key at the start of
  /// one of the last kMaxTurns periods (the run has entered a cycle); nullptr otherwise.
  const Value* Find(const Key& key, std::int64_t turn) {
    const bool first = turn != turn_;
    turn_ = turn;
    if (cursor_ != kNone) {
      if (cursor_ == cycle_end_) cursor_ = cycle_begin_;
      if (trace_[cursor_].key == key) return &trace_[cursor_++].value;
      cursor_ = kNone;  // the run has left the cycle (the end of the run changes a step)
    }
    if (!first) return nullptr;
    for (int i = 0; i < n_starts_; ++i) {
      const std::size_t begin = starts_[static_cast<std::size_t>(i)];
      if (trace_[begin].key == key) {
        cycle_begin_ = begin;
        cycle_end_ = trace_.size();
        cursor_ = begin + 1;
        return &trace_[begin].value;
      }
    }
    new_turn_ = true;
    return nullptr;
  }

  /// Stores the result computed for `key` (after a Find that returned nullptr).
  void Add(const Key& key, const Value& value) {
    if (trace_.size() == kMaxEntries) {
      trace_.clear();
      n_starts_ = 0;
      next_start_ = 0;
    }
    if (new_turn_) {
      starts_[next_start_] = trace_.size();
      next_start_ = (next_start_ + 1) % starts_.size();
      if (n_starts_ < kMaxTurns) ++n_starts_;
      new_turn_ = false;
    }
    trace_.push_back({key, value});
  }

 private:
  struct Entry {
    Key key;
    Value value;
  };
  static constexpr std::size_t kNone = static_cast<std::size_t>(-1);

  std::vector<Entry> trace_;
  // Index of the first entry of each of the last kMaxTurns periods (a ring).
  std::array<std::size_t, kMaxTurns> starts_{};
  int n_starts_ = 0;
  std::size_t next_start_ = 0;
  bool new_turn_ = false;
  std::int64_t turn_ = -1;
  // The cycle being followed: entries [cycle_begin_, cycle_end_) (those stored since its first
  // key; each used only while its key matches), next one at cursor_.
  std::size_t cursor_ = kNone, cycle_begin_ = 0, cycle_end_ = 0;
};

}  // namespace capsubot::detail
