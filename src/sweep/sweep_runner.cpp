#include "sweep/sweep_runner.hpp"

#include <algorithm>
#include <atomic>
#include <exception>
#include <map>
#include <mutex>
#include <stdexcept>
#include <thread>

#include "io/bad_input.hpp"
#include "job/resolve.hpp"
#include "sweep/batch_points.hpp"
#include "sweep/level_point.hpp"

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

namespace {

// What one thread takes at a time: points run as one batch, or one point on
// the scalar path.
struct Work {
  std::vector<const PreparedPoint*> points;
  bool batched = false;
};

// A batch keeps every sample of its points until it ends (the scalar path one
// point's): at most this many, about 40 MB, unless one point has more.
constexpr long kBatchSamples = 1L << 18;

// Batches of one batch_key each, large enough that the lanes seldom idle at
// a batch's end, small enough that the threads share the work evenly and
// rows reach the file as the sweep goes; the scalar points after them.
std::vector<Work> work_list(const std::vector<PreparedPoint>& points, int threads, PointPath path) {
  std::vector<std::string> keys;
  std::map<std::string, std::vector<const PreparedPoint*>> groups;
  std::vector<Work> scalar;
  for (const auto& p : points) {
    if (path == PointPath::batch && !p.level && runs_batched(p.run)) {
      auto [it, fresh] = groups.try_emplace(batch_key(p.run));
      if (fresh) keys.push_back(it->first);
      it->second.push_back(&p);
    } else {
      scalar.push_back({{&p}, false});
    }
  }
  std::vector<Work> list;
  for (const auto& key : keys) {
    const auto& group = groups[key];
    const std::size_t chunk =
        std::clamp<std::size_t>(group.size() / (4 * std::size_t(threads)), 16, 64);
    long samples = 0;
    for (std::size_t i = 0; i < group.size(); ++i) {
      const PreparedPoint* p = group[i];
      const long mine = long(p->run.samples) + 1;
      if (i == 0 || list.back().points.size() >= chunk || samples + mine > kBatchSamples) {
        list.push_back({{}, true});
        samples = 0;
      }
      list.back().points.push_back(p);
      samples += mine;
    }
  }
  list.insert(list.end(), scalar.begin(), scalar.end());
  return list;
}

}  // namespace

SweepTotals run_points(const SweepSpec& spec, const std::vector<PreparedPoint>& points, int threads,
                       RowAppender& rows, const std::function<void()>& on_row, PointPath path) {
  const std::vector<Work> work_items = work_list(points, std::max(1, threads), path);
  std::atomic<std::size_t> next{0};
  std::atomic<bool> stop{false};
  std::atomic<long> failures{0};
  std::exception_ptr error;
  std::mutex lock;
  ReferenceCache references;
  auto work = [&] {
    for (;;) {
      const std::size_t i = next.fetch_add(1);
      if (i >= work_items.size() || stop) return;
      try {
        const Work& w = work_items[i];
        const auto put = [&](const PointRow& row) {
          if (row.failed) ++failures;
          rows.append(row.line);
          if (on_row) {
            std::lock_guard g(lock);
            on_row();
          }
        };
        const PreparedPoint& first = *w.points.front();
        if (w.batched)
          run_batched(w.points, spec.hash, spec.reference, spec.ftle, &references, put);
        else if (first.level)
          put(level_row(first, spec.hash,
                        level_metrics(first.run, *first.level, spec.level_orbits, *spec.ftle)));
        else
          put(run_point(*w.points.front(), spec.hash, spec.reference, spec.ftle, &references));
      } catch (...) {
        std::lock_guard g(lock);
        if (!error) error = std::current_exception();
        stop = true;
        return;
      }
    }
  };
  const int n = std::max(1, std::min<int>(threads, int(work_items.size())));
  std::vector<std::thread> pool;
  for (int t = 1; t < n; ++t) pool.emplace_back(work);
  work();
  for (auto& t : pool) t.join();
  if (error) std::rethrow_exception(error);
  return {long(points.size()), failures.load()};
}

}  // namespace epviz::sweep
