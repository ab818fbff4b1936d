#include <algorithm>
#include <atomic>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <string>
#include <thread>

#include "sim/ensemble.hpp"

namespace epviz::sim {

std::vector<DirectBatchResult> integrate_direct_batch_parallel(
    const physics::Body& body, const std::vector<DirectBatchTask>& tasks,
    const DirectBatchSettings& settings, int threads) {
  if (threads < 1)
    throw std::invalid_argument("threads " + std::to_string(threads) + ": must be at least 1");
  // Everything that can be refused is refused here, before a thread starts:
  // the tasks, EPVIZ_SIMD and the width (by integrating none of the tasks).
  numerics::check_batch_tasks(tasks);
  DirectBatchSettings fixed = settings;
  if (!fixed.path) fixed.path = numerics::chosen_simd_path();
  integrate_direct_batch(body, {}, fixed);

  // Chunks small enough to balance the threads, large enough that each batch
  // keeps its lanes busy most of the time; with few tasks (a section's
  // orbits), an equal share for each thread, so that every thread has some.
  const std::size_t share = (tasks.size() + std::size_t(threads) - 1) / std::size_t(threads);
  const std::size_t chunk = std::max<std::size_t>(
      {1, std::min<std::size_t>(64, share), tasks.size() / (8 * std::size_t(threads))});
  std::vector<DirectBatchResult> results(tasks.size());
  std::atomic<std::size_t> next{0};
  std::exception_ptr error;
  std::mutex error_mutex;
  const auto work = [&] {
    try {
      for (;;) {
        const std::size_t begin = next.fetch_add(chunk);
        if (begin >= tasks.size()) return;
        const std::size_t end = std::min(tasks.size(), begin + chunk);
        const std::vector<DirectBatchTask> part(tasks.begin() + long(begin),
                                                tasks.begin() + long(end));
        auto done = integrate_direct_batch(body, part, fixed);
        std::move(done.begin(), done.end(), results.begin() + long(begin));
      }
    } catch (...) {
      const std::lock_guard<std::mutex> lock(error_mutex);
      if (!error) error = std::current_exception();
    }
  };
  std::vector<std::thread> pool;
  for (int i = 1; i < threads; ++i) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
  return results;
}

}  // namespace epviz::sim
