#pragma once
// The results of a pure function of the simulator's state (the event search of a segment),
// kept along a cycle of the run so that, once the run comes back to a state it had, bit for
// bit, they are taken from here instead of computed again (docs/simulate.md, "Repeated
// cycles"). A motion that has settled on a periodic attractor does so within a few tens of
// periods: rounding then maps the state onto itself exactly, and from there the run repeats
// the same events forever. Each stored result is used only when its key equals the present
// one in every bit, so a run with the memo is the run without it, bit for bit.
//
// Three phases. Watching: the key of the first look-up of each period is compared with those
// of the last kMaxTurns periods. Once one repeats, the run has entered a cycle, and the
// results of the next cycle are recorded (at most kMaxEntries, over at most kMaxTurns
// periods, else the memo goes back to watching). When the first key of a period equals the
// first recorded one, the cycle has closed: its results are replayed in order, each checked
// against its key, until a key differs (the end of the run changes a step). A run that never
// repeats pays the key of each event and kMaxTurns key comparisons per period.

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
  /// Most results recorded (the trace stays below the size the allocator would map and
  /// unmap for every run).
  static constexpr std::size_t kMaxEntries = 1024;

  /// The stored result for `key`, looked up in period `turn`: the next one of the cycle being
  /// replayed, or the first recorded one when the first look-up of a period closes the cycle;
  /// nullptr otherwise (compute it and give it to Add).
  const Value* Find(const Key& key, std::int64_t turn) {
    const bool first = turn != turn_;
    turn_ = turn;
    if (replaying_) {
      if (cursor_ == trace_.size()) cursor_ = 0;
      if (trace_[cursor_].key == key) return &trace_[cursor_++].value;
      Restart();  // the run has left the cycle
    }
    if (!first) return nullptr;
    if (recording_) {
      if (trace_.front().key == key) {
        recording_ = false;
        replaying_ = true;
        cursor_ = 1;
        return &trace_.front().value;
      }
      if (++recorded_turns_ > kMaxTurns) Restart();
    }
    if (!recording_ && Seen(key)) {
      recording_ = true;
      recorded_turns_ = 0;
    }
    Remember(key);
    return nullptr;
  }

  /// The result computed for `key` after Find returned nullptr (kept while recording).
  void Add(const Key& key, const Value& value) {
    if (!recording_) return;
    if (trace_.size() == kMaxEntries) {
      Restart();
      return;
    }
    trace_.push_back({key, value});
  }

 private:
  struct Entry {
    Key key;
    Value value;
  };

  bool Seen(const Key& key) const {
    for (int i = 0; i < n_firsts_; ++i) {
      if (firsts_[static_cast<std::size_t>(i)] == key) return true;
    }
    return false;
  }
  void Remember(const Key& key) {
    firsts_[next_first_] = key;
    next_first_ = (next_first_ + 1) % firsts_.size();
    if (n_firsts_ < kMaxTurns) ++n_firsts_;
  }
  void Restart() {
    trace_.clear();
    recording_ = replaying_ = false;
    cursor_ = 0;
  }

  // Keys of the first look-ups of the last kMaxTurns periods (a ring).
  std::array<Key, kMaxTurns> firsts_{};
  int n_firsts_ = 0;
  std::size_t next_first_ = 0;
  std::int64_t turn_ = -1;
  // The recorded cycle: results in order from the first look-up of a period.
  std::vector<Entry> trace_;
  bool recording_ = false, replaying_ = false;
  int recorded_turns_ = 0;
  std::size_t cursor_ = 0;  // next entry to replay
};

}  // namespace capsubot::detail
