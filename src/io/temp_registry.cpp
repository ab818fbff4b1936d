#include "io/temp_registry.hpp"

#include <limits.h>
#include <signal.h>
#include <unistd.h>

#include <array>
#include <atomic>
#include <cerrno>
#include <cstring>
#include <mutex>
#include <string>

namespace epviz::io {
namespace {

constexpr std::size_t kSlots = 64;

struct Slot {
  // 0 free, 1 being filled or emptied (the handler skips it), 2 registered.
  std::atomic<int> state{0};
  pid_t child = -1;
  char path[PATH_MAX] = {};
};

std::array<Slot, kSlots> slots;
std::once_flag installed;
static_assert(std::atomic<int>::is_always_lock_free, "the handler reads the slots' state");

extern "C" void remove_temporaries_and_reraise(int sig) {
  const int saved_errno = errno;
  for (auto& slot : slots) {
    if (slot.state.load(std::memory_order_acquire) != 2) continue;
    if (slot.child > 0) ::kill(slot.child, SIGKILL);
    ::unlink(slot.path);
  }
  errno = saved_errno;
  ::signal(sig, SIG_DFL);
  ::raise(sig);
}

void install_for(int sig) {
  struct sigaction old {};
  if (::sigaction(sig, nullptr, &old) == 0 && old.sa_handler == SIG_IGN) return;
  struct sigaction action {};
  action.sa_handler = remove_temporaries_and_reraise;
  sigemptyset(&action.sa_mask);
  // Both signals are blocked while the handler runs, so a second one waits
  // for the first to finish removing files.
  sigaddset(&action.sa_mask, SIGINT);
  sigaddset(&action.sa_mask, SIGTERM);
  action.sa_flags = SA_RESETHAND;
  ::sigaction(sig, &action, nullptr);
}

}  // namespace

void install_temporary_cleanup() {
  std::call_once(installed, [] {
    install_for(SIGINT);
    install_for(SIGTERM);
  });
}

int register_temporary(const std::filesystem::path& path, pid_t child) {
  const std::string text = std::filesystem::absolute(path).string();
  if (text.size() >= PATH_MAX) return -1;
  for (std::size_t i = 0; i < kSlots; ++i) {
    int expected = 0;
    if (!slots[i].state.compare_exchange_strong(expected, 1, std::memory_order_acq_rel)) continue;
    std::memcpy(slots[i].path, text.c_str(), text.size() + 1);
    slots[i].child = child;
    slots[i].state.store(2, std::memory_order_release);
    return int(i);
  }
  return -1;
}

void unregister_temporary(int slot) noexcept {
  if (slot < 0 || std::size_t(slot) >= kSlots) return;
  slots[std::size_t(slot)].state.store(1, std::memory_order_release);
  slots[std::size_t(slot)].child = -1;
  slots[std::size_t(slot)].state.store(0, std::memory_order_release);
}

void forget_child(int slot) noexcept {
  if (slot < 0 || std::size_t(slot) >= kSlots) return;
  auto& s = slots[std::size_t(slot)];
  int expected = 2;
  if (!s.state.compare_exchange_strong(expected, 1, std::memory_order_acq_rel)) return;
  s.child = -1;
  s.state.store(2, std::memory_order_release);
}

std::size_t registered_temporaries() {
  std::size_t n = 0;
  for (const auto& slot : slots) n += slot.state.load() == 2;
  return n;
}

}  // namespace epviz::io
