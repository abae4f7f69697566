#include "detail/temporary_registry.h"

#include <unistd.h>

#include <array>
#include <atomic>
#include <csignal>
#include <cstring>
#include <mutex>

namespace octaclay::core::detail {
namespace {

enum SlotState : int { kFree = 0, kFilling = 1, kLive = 2 };

struct Slot {
  std::atomic<int> state{kFree};
  std::array<char, 4096> path{};
};
constexpr std::size_t kPathBytes = 4096;

std::array<Slot, 128> slots;

void removeTemporariesAndDie(int signal) {
  // Only async-signal-safe calls here: unlink, signal, raise.
  for (Slot& slot : slots)
    if (slot.state.load(std::memory_order_acquire) == kLive) ::unlink(slot.path.data());
  ::signal(signal, SIG_DFL);
  ::raise(signal);
}

void installHandlers() {
  // Every signal whose default action ends the process, a user or a tool may send during a save.
  for (const int signal : {SIGINT, SIGTERM, SIGHUP, SIGQUIT, SIGUSR1, SIGUSR2, SIGALRM, SIGPIPE}) {
    struct sigaction previous {};
    if (::sigaction(signal, nullptr, &previous) != 0 || previous.sa_handler != SIG_DFL) continue;
    struct sigaction action {};
    action.sa_handler = removeTemporariesAndDie;
    sigemptyset(&action.sa_mask);
    ::sigaction(signal, &action, nullptr);
  }
  struct sigaction previous {};
  if (::sigaction(SIGXFSZ, nullptr, &previous) == 0 && previous.sa_handler == SIG_DFL)
    ::signal(SIGXFSZ, SIG_IGN);
}

} // namespace

int registerTemporary(const std::filesystem::path& path) {
  static std::once_flag installed;
  std::call_once(installed, installHandlers);
  std::error_code ec;
  const std::string absolute = std::filesystem::absolute(path, ec).string();
  if (ec || absolute.size() >= kPathBytes) return -1;
  for (std::size_t k = 0; k < slots.size(); ++k) {
    int expected = kFree;
    if (!slots[k].state.compare_exchange_strong(expected, kFilling)) continue;
    std::memcpy(slots[k].path.data(), absolute.c_str(), absolute.size() + 1);
    slots[k].state.store(kLive, std::memory_order_release);
    return static_cast<int>(k);
  }
  return -1;
}

void unregisterTemporary(int slot) {
  if (slot >= 0 && slot < static_cast<int>(slots.size()))
    slots[static_cast<std::size_t>(slot)].state.store(kFree, std::memory_order_release);
}

} // namespace octaclay::core::detail
