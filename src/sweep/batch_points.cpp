#include "sweep/batch_points.hpp"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <stdexcept>

#include "sim/drift.hpp"
#include "sim/ensemble.hpp"
#include "sim/run_options.hpp"

namespace epviz::sweep {
namespace {

// The task of sim::simulate's run: output times k * (t_end / samples) for
// k = 1 .. samples, and no stepping past the last (AdaptiveTrajectory steps
// while t < the output time, then reads the dense output).
sim::DirectBatchTask task_of(const sim::RunSpec& run, long id) {
  const double spacing = run.t_end / run.samples;
  std::vector<double> out;
  out.reserve(std::size_t(run.samples));
  for (int k = 1; k <= run.samples; ++k) out.push_back(double(k) * spacing);
  const double t_end = out.back();
  sim::DirectBatchTask task = sim::direct_batch_task(run.initial, t_end, std::move(out));
  task.id = id;
  return task;
}

sim::Sample sample_of(double t, const std::array<double, 6>& x) {
  sim::Sample s;
  s.t = t;
  s.omega = {x[0], x[1], x[2]};
  s.gamma = {x[3], x[4], x[5]};
  return s;
}

// Runs `tasks` (ids 0, 1, ... into `runs`) with every output passing the
// motion check of its run, as sim::Trajectory's outputs do.
std::vector<sim::DirectBatchResult> integrate(const std::vector<sim::RunSpec>& runs,
                                              const std::vector<sim::DirectBatchTask>& tasks,
                                              numerics::BatchEvents<6> events = {}) {
  std::vector<sim::MotionCheck> checks;
  checks.reserve(runs.size());
  for (const auto& run : runs) checks.emplace_back(run.body, run.initial, run.max_drift);
  const std::string method(sim::name(sim::Method::dop853));
  sim::DirectBatchSettings settings = sim::dop853_batch_settings(runs.front());
  settings.check = [&](long id, double t, const std::array<double, 6>& x) {
    return checks[std::size_t(id)].failure(sample_of(t, x), method);
  };
  settings.events = std::move(events);
  return sim::integrate_direct_batch(runs.front().body, tasks, settings);
}

// sim::simulate's result of the run whose batch result is `r`.
sim::RunResult run_result(const sim::DirectBatchTask& task, sim::DirectBatchResult r) {
  sim::RunResult out;
  out.samples.reserve(r.outputs.size() + 1);
  out.samples.push_back(sample_of(0.0, task.x0));
  for (std::size_t k = 0; k < r.outputs.size(); ++k)
    out.samples.push_back(sample_of(task.out_times[k], r.outputs[k]));
  out.samples_written = long(out.samples.size());
  out.stats.steps = r.steps;
  out.stats.rejected_steps = r.rejected_steps;
  out.stats.rhs_evals = r.rhs_evals;
  out.failure = std::move(r.failure);
  return out;
}

// The exponents of every point: round after round, the base and neighbour
// states of the points still going advance one window, all in one batch.
std::vector<FtleResult> exponents(const std::vector<const PreparedPoint*>& points,
                                  const FtleSettings& settings) {
  std::vector<FtleWindows> windows;
  windows.reserve(points.size());
  for (const auto* p : points) windows.emplace_back(p->run, settings);
  std::vector<sim::RunSpec> runs;
  std::vector<sim::DirectBatchTask> tasks;
  std::vector<std::size_t> owner;
  for (;;) {
    runs.clear();
    tasks.clear();
    owner.clear();
    for (std::size_t j = 0; j < windows.size(); ++j) {
      const FtleWindows& w = windows[j];
      if (w.done()) continue;
      for (const FtleState* x : {&w.base(), &w.neighbour()}) {
        runs.push_back(window_run(points[j]->run, *x, w.window()));
        tasks.push_back(task_of(runs.back(), long(tasks.size())));
      }
      owner.push_back(j);
    }
    if (owner.empty()) break;
    const auto results = integrate(runs, tasks);
    const auto state = [&](std::size_t i) -> std::optional<FtleState> {
      if (results[i].failure) return std::nullopt;
      const auto& x = results[i].outputs.back();
      FtleState s;
      for (int c = 0; c < 6; ++c) s[c] = x[std::size_t(c)];
      return s;
    };
    for (std::size_t k = 0; k < owner.size(); ++k)
      windows[owner[k]].absorb(state(2 * k), state(2 * k + 1));
  }
  std::vector<FtleResult> values;
  values.reserve(windows.size());
  for (const auto& w : windows) values.push_back(w.result());
  return values;
}

}  // namespace

bool runs_batched(const sim::RunSpec& run) {
  // The checks sim::Trajectory::start makes are left to it: a run it would
  // refuse takes the scalar path and is refused there, as before.
  return sim::batchable(run) && run.t_end > 0.0 && std::isfinite(run.t_end) && run.samples >= 1 &&
         run.samples <= kKeptSamples && run.max_drift > 0.0;
}

std::string batch_key(const sim::RunSpec& run) {
  std::string key;
  char buf[40];
  const auto put = [&](double x) {
    std::snprintf(buf, sizeof buf, "%.17g,", x);
    key += buf;
  };
  for (int i = 0; i < 3; ++i) {
    put(run.body.inertia[i]);
    put(run.body.com[i]);
  }
  put(run.body.weight);
  put(sim::adaptive_tol(run));
  put(double(run.max_steps));
  return key;
}

void run_batched(const std::vector<const PreparedPoint*>& points, const std::string& sweep_hash,
                 bool reference, const std::optional<FtleSettings>& ftle, ReferenceCache* cache,
                 const std::function<void(const PointRow&)>& emit) {
  if (points.empty()) return;
  for (const auto* p : points)
    if (!runs_batched(p->run) || !sim::share_a_batch(p->run, points.front()->run))
      throw std::logic_error("run_batched: a point the batch cannot take, or of another batch");
  std::vector<sim::RunSpec> runs;
  std::vector<sim::DirectBatchTask> tasks;
  runs.reserve(points.size());
  tasks.reserve(points.size());
  for (const auto* p : points) {
    runs.push_back(p->run);
    tasks.push_back(task_of(p->run, long(tasks.size())));
  }
  const auto row = [&](std::size_t i, sim::DirectBatchResult r, double cpu,
                       const std::optional<FtleResult>& exponent) {
    sim::RunResult result = run_result(tasks[i], std::move(r));
    result.cpu_seconds = cpu;
    const PointOutcome outcome = outcome_of(runs[i], std::move(result), reference);
    return point_row(*points[i], sweep_hash, outcome, reference, cache, exponent);
  };

  // A run's CPU time: the thread's from its start to its end, shared with
  // the lanes beside it.
  const double lanes = double(std::min<std::size_t>(
      points.size(), std::size_t(sim::default_batch_width(numerics::chosen_simd_path()))));
  std::vector<double> started(points.size()), cpu(points.size());
  std::vector<sim::DirectBatchResult> waiting;  // for their exponents
  numerics::BatchEvents<6> events;
  events.started = [&](long id) { started[std::size_t(id)] = sim::thread_cpu_seconds(); };
  events.ended = [&](long id, const sim::DirectBatchResult& r) {
    const auto i = std::size_t(id);
    cpu[i] = (sim::thread_cpu_seconds() - started[i]) / lanes;
    if (!ftle) emit(row(i, r, cpu[i], std::nullopt));  // its row now, as the scalar path's
  };
  auto results = integrate(runs, tasks, std::move(events));
  if (!ftle) return;
  const auto values = exponents(points, *ftle);
  for (std::size_t i = 0; i < points.size(); ++i)
    emit(row(i, std::move(results[i]), cpu[i], values[i]));
}

}  // namespace epviz::sweep
