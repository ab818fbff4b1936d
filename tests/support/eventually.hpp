#pragma once
// Waiting on a condition with no event to wait on (a file that grows, a
// process's state): looked at again and again up to a deadline, never for a
// fixed time, so that a passing test waits no longer than the condition takes.
#include <chrono>
#include <functional>
#include <thread>

namespace epviz::test {

// Whether `condition` holds within `timeout`; it is looked at every 5 ms.
inline bool eventually(const std::function<bool()>& condition, std::chrono::milliseconds timeout) {
  const auto deadline = std::chrono::steady_clock::now() + timeout;
  while (!condition()) {
    if (std::chrono::steady_clock::now() > deadline) return false;
    std::this_thread::sleep_for(std::chrono::milliseconds(5));
  }
  return true;
}

}  // namespace epviz::test
