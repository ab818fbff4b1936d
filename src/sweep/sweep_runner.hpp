#pragma once
// Runs the points of a sweep on a pool of threads in this process (no process
// per point: a short run costs microseconds, a process start milliseconds),
// appending each row as it finishes.
#include <functional>
#include <vector>

#include "sim/run_spec.hpp"
#include "sweep/point_run.hpp"
#include "sweep/rows_file.hpp"

namespace epviz::sweep {

struct SweepTotals {
  long points = 0;
  long failures = 0;  // points whose run failed (a result, not an error)
};

// Runs `points` with `threads` threads (at least 1), appending a row each to
// `rows` and calling `on_row` (from the worker, under a lock) after each.
// The first exception a worker meets stops the others and is rethrown.
SweepTotals run_points(const SweepSpec& spec, const std::vector<PreparedPoint>& points, int threads,
                       RowAppender& rows, const std::function<void()>& on_row = {});

}  // namespace epviz::sweep
