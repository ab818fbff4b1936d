#include "sim/simulate.hpp"

#include <ctime>

#include "sim/trajectory.hpp"

namespace epviz::sim {
namespace {

// The calling thread's CPU time: a run integrates on one thread, and in a
// sweep other threads run other points meanwhile (the process's CPU time
// would count theirs too, and costs a walk over all threads to read).
double cpu_now() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

void finish(RunResult& r, const Trajectory& trajectory) {
  r.stats = trajectory.stats();
  r.effective_step = trajectory.effective_step();
  r.chart_switches = trajectory.chart_switches();
}

}  // namespace

RunResult simulate(const RunSpec& spec) {
  RunResult r;
  r.samples.reserve(std::size_t(spec.samples) + 1);
  // Only the integration is timed: sampling into the reserved vector is part of
  // it, the caller's I/O and invariant bookkeeping are not.
  const double start = cpu_now();
  auto trajectory = Trajectory::start(spec);
  r.samples.push_back(trajectory->initial());
  try {
    for (int k = 1; k <= spec.samples; ++k) r.samples.push_back(trajectory->next());
  } catch (const numerics::IntegrationError& e) {
    r.failure = e.failure();
  }
  r.cpu_seconds = cpu_now() - start;
  r.samples_written = long(r.samples.size());
  finish(r, *trajectory);
  return r;
}

RunResult simulate(const RunSpec& spec, const SampleSink& sink) {
  RunResult r;
  double start = cpu_now();
  auto trajectory = Trajectory::start(spec);
  Sample s = trajectory->initial();
  r.cpu_seconds += cpu_now() - start;
  sink(s);
  ++r.samples_written;
  for (int k = 1; k <= spec.samples; ++k) {
    start = cpu_now();
    try {
      s = trajectory->next();
    } catch (const numerics::IntegrationError& e) {
      r.failure = e.failure();
    }
    r.cpu_seconds += cpu_now() - start;
    if (r.failure) break;
    sink(s);
    ++r.samples_written;
  }
  finish(r, *trajectory);
  return r;
}

}  // namespace epviz::sim
