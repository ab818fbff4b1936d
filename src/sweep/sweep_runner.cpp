#include "sweep/sweep_runner.hpp"

#include <atomic>
#include <exception>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "io/bad_input.hpp"
#include "job/resolve.hpp"

namespace epviz::sweep {

std::vector<PreparedPoint> pending_points(const SweepSpec& spec, shard::ItemRange range,
                                          const ExistingRows& done) {
  PointReader read_point(spec);
  for (long i : spec.value_probes()) (void)read_point(i);
  std::vector<PreparedPoint> pending;
  pending.reserve(std::size_t(range.size()));
  for (long i = range.first; i < range.end; ++i) {
    try {
      auto p = read_point(i);
      auto run = resolve_point(p, [](const job::SimulationFields& f) { return job::resolve(f); });
      if (!done.indices.count(i)) pending.push_back(prepared_point(p, std::move(run)));
    } catch (const std::invalid_argument& e) {  // an energy no state of the body reaches
      throw io::BadInput(e.what());
    }
  }
  return pending;
}

SweepTotals run_points(const SweepSpec& spec, const std::vector<PreparedPoint>& points, int threads,
                       RowAppender& rows, const std::function<void()>& on_row) {
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::atomic<long> failures{0};
  std::exception_ptr error;
  std::mutex lock;
  ReferenceCache references;
  auto work = [&] {
    for (;;) {
      const std::size_t i = next.fetch_add(1);
      if (i >= points.size() || stop) return;
      try {
        const auto& p = points[i];
        const auto row = run_point(p, spec.hash, spec.reference, spec.ftle, &references);
        if (row.failed) ++failures;
        rows.append(row.line);
        if (on_row) {
          std::lock_guard g(lock);
          on_row();
        }
      } catch (...) {
        std::lock_guard g(lock);
        if (!error) error = std::current_exception();
        stop = true;
        return;
      }
    }
  };
  const int n = std::max(1, std::min<int>(threads, int(points.size())));
  std::vector<std::thread> pool;
  for (int t = 1; t < n; ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
  return {long(points.size()), failures.load()};
}

}  // namespace epviz::sweep
