// The registry of temporary files removed on SIGINT/SIGTERM. The signal handler may run at
// any instruction of any thread: it only reads lock-free atomics and calls unlink(2) and
// raise(3), which are async-signal-safe.

#include <signal.h>
#include <unistd.h>

#include <atomic>
#include <cstring>

#include "capsubot/io/io.hpp"

namespace capsubot {
namespace {

enum SlotState : int { kFree = 0, kFilling = 1, kReady = 2 };

struct Slot {
  std::atomic<int> state{kFree};
  char path[kMaxTempPathBytes] = {};
};

Slot g_slots[kMaxTempFiles];
static_assert(std::atomic<int>::is_always_lock_free, "the signal handler needs lock-free atomics");

extern "C" void RemoveTempFilesAndReraise(int signal_number) {
  for (Slot& slot : g_slots) {
    if (slot.state.load(std::memory_order_acquire) == kReady) ::unlink(slot.path);
  }
  // SA_RESETHAND restored the default action; the signal is blocked until we return, then
  // it ends the process as if no handler had been installed.
  ::raise(signal_number);
}

}  // namespace

int RegisterTempFile(const std::string& path) {
  if (path.size() >= static_cast<std::size_t>(kMaxTempPathBytes)) return -1;
  for (int i = 0; i < kMaxTempFiles; ++i) {
    int expected = kFree;
    if (!g_slots[i].state.compare_exchange_strong(expected, kFilling, std::memory_order_acquire)) {
      continue;
    }
    std::memcpy(g_slots[i].path, path.c_str(), path.size() + 1);
    g_slots[i].state.store(kReady, std::memory_order_release);
    return i;
  }
  return -1;
}

void UnregisterTempFile(int slot) {
  if (slot >= 0 && slot < kMaxTempFiles) {
    g_slots[slot].state.store(kFree, std::memory_order_release);
  }
}

void InstallTempFileCleanup() {
  for (int signal_number : {SIGINT, SIGTERM}) {
    struct sigaction current {};
    ::sigaction(signal_number, nullptr, &current);
    if (current.sa_handler == SIG_IGN) continue;  // started ignoring it (nohup): keep that
    struct sigaction action {};
    action.sa_handler = RemoveTempFilesAndReraise;
    sigemptyset(&action.sa_mask);
    action.sa_flags = SA_RESETHAND;
    ::sigaction(signal_number, &action, nullptr);
  }
}

}  // namespace capsubot
