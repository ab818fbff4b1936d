#include "sim/simulate.hpp"

#include <ctime>

#include "sim/trajectory.hpp"

namespace epviz::sim {
namespace {

void finish(RunResult& r, const Trajectory& trajectory) {
  r.stats = trajectory.stats();
  r.effective_step = trajectory.effective_step();
  r.chart_switches = trajectory.chart_switches();
}

}  // namespace

double thread_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

RunResult simulate(const RunSpec& spec) {
  RunResult r;
  r.samples.reserve(std::size_t(spec.samples) + 1);
  // Only the integration is timed: sampling into the reserved vector is part of
  // it, the caller's I/O and invariant bookkeeping are not.
  const double start = thread_cpu_seconds();
  auto trajectory = Trajectory::start(spec);
  r.samples.push_back(trajectory->initial());
  try {
    for (int k = 1; k <= spec.samples; ++k) r.samples.push_back(trajectory->next());
  } catch (const numerics::IntegrationError& e) {
    r.failure = e.failure();
  }
  r.cpu_seconds = thread_cpu_seconds() - start;
  r.samples_written = long(r.samples.size());
  finish(r, *trajectory);
  return r;
}

RunResult simulate(const RunSpec& spec, const SampleSink& sink, const SampleSink& on_step) {
  RunResult r;
  double start = thread_cpu_seconds();
  auto trajectory = Trajectory::start(spec);
  // The steps are kept while the clock runs and handed on after it stops:
  // a copy per step costs nothing next to a step.
  std::vector<Sample> steps;
  if (on_step) trajectory->observe_steps([&steps](const Sample& s) { steps.push_back(s); });
  auto hand_on_steps = [&] {
    for (const auto& s : steps) on_step(s);
    steps.clear();
  };
  Sample s = trajectory->initial();
  r.cpu_seconds += thread_cpu_seconds() - start;
  sink(s);
  ++r.samples_written;
  for (int k = 1; k <= spec.samples; ++k) {
    start = thread_cpu_seconds();
    try {
      s = trajectory->next();
    } catch (const numerics::IntegrationError& e) {
      r.failure = e.failure();
    }
    r.cpu_seconds += thread_cpu_seconds() - start;
    hand_on_steps();
    if (r.failure) break;
    sink(s);
    ++r.samples_written;
  }
  finish(r, *trajectory);
  return r;
}

}  // namespace epviz::sim
