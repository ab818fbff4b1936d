#pragma once
// Runs the points of a sweep on a pool of threads in this process (no process
// per point: a short run costs microseconds, a process start milliseconds),
// appending each row as it finishes.
#include <functional>
#include <string>
#include <vector>

#include "shard/shard_spec.hpp"
#include "sim/run_spec.hpp"
#include "sweep/point_run.hpp"
#include "sweep/rows_file.hpp"

namespace epviz::sweep {

struct SweepTotals {
  long points = 0;
  long failures = 0;  // points whose run failed (a result, not an error)
};

// The points of `range` that `done` (the rows already written, resume_rows)
// lacks, each resolved. Every value of every axis is read and checked first,
// through one point per value, so that a bad value anywhere stops every shard
// alike; then only `range`'s points are resolved in full (where a value meets
// the others: an energy the state cannot reach, a step budget) and kept, so
// that a shard costs time and memory in proportion to its own range, however
// large the sweep. Throws io::BadInput for a bad value.
std::vector<PreparedPoint> pending_points(const SweepSpec& spec, shard::ItemRange range,
                                          const ExistingRows& done);

// How the points the batch integrator can take (batch_points.hpp,
// runs_batched) are run: side by side in batches, or one by one as the
// others. The rows are the same; `scalar` is for comparisons.
enum class PointPath { batch, scalar };

// Runs `points` with `threads` threads (at least 1), appending a row each to
// `rows` and calling `on_row` (from the worker, under a lock) after each.
// The threads take work in turn: a batch of points that share a body,
// tolerance and step budget (its rows appended when the batch ends), or one
// point that the batch cannot take. The first exception a worker meets stops
// the others and is rethrown.
SweepTotals run_points(const SweepSpec& spec, const std::vector<PreparedPoint>& points, int threads,
                       RowAppender& rows, const std::function<void()>& on_row = {},
                       PointPath path = PointPath::batch);

}  // namespace epviz::sweep
