#include "sim/simulate.hpp"

#include <chrono>
#include <ctime>

#include "sim/trajectory.hpp"

namespace epviz::sim {
namespace {

void finish(RunResult& r, const Trajectory& trajectory) {
  r.stats = trajectory.stats();
  r.effective_step = trajectory.effective_step();
  r.chart_switches = trajectory.chart_switches();
}

// What a streamed run hands on, in the order it happened: the accepted steps
// (when the caller observes them) and the output samples. They wait in a
// buffer of fixed size and are handed on in bursts, with the clock stopped:
// - the thread's CPU clock is a system call (about a microsecond here, the
//   cost of several steps), so it is read once a burst, not around each sample;
// - memory does not grow with the steps between two samples (it did when the
//   steps waited for their sample: 210 bytes a step);
// - a burst also ends at a sample when kMaxDelay has passed since the last,
//   so that the caller's progress line and output keep up with a slow run.
class Relay {
 public:
  Relay(const SampleSink& sink, const SampleSink& on_step, RunResult& result)
      : sink_(sink), on_step_(on_step), result_(result) {
    events_.reserve(kCapacity);
  }

  void start_clock() {
    started_ = thread_cpu_seconds();
    due_ = std::chrono::steady_clock::now() + kMaxDelay;
  }
  void stop_clock() { result_.cpu_seconds += thread_cpu_seconds() - started_; }

  void step(const Sample& s) {
    events_.push_back({s, false});
    if (events_.size() == kCapacity) burst();
  }
  void sample(const Sample& s) {
    events_.push_back({s, true});
    if (events_.size() == kCapacity || std::chrono::steady_clock::now() >= due_) burst();
  }
  // Hands on what waits; the clock is stopped meanwhile.
  void burst() {
    stop_clock();
    hand_on();
    start_clock();
  }
  void hand_on() {
    for (const Event& e : events_) {
      if (e.output) {
        sink_(e.sample);
        ++result_.samples_written;
      } else {
        on_step_(e.sample);
      }
    }
    events_.clear();
  }

 private:
  struct Event {
    Sample sample;
    bool output;
  };
  static constexpr std::size_t kCapacity = 2048;
  static constexpr std::chrono::milliseconds kMaxDelay{100};

  const SampleSink& sink_;
  const SampleSink& on_step_;
  RunResult& result_;
  std::vector<Event> events_;
  double started_ = 0.0;
  std::chrono::steady_clock::time_point due_;
};

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
  Relay relay(sink, on_step, r);
  relay.start_clock();
  auto trajectory = Trajectory::start(spec);
  if (on_step) trajectory->observe_steps([&relay](const Sample& s) { relay.step(s); });
  relay.sample(trajectory->initial());
  try {
    for (int k = 1; k <= spec.samples; ++k) relay.sample(trajectory->next());
  } catch (const numerics::IntegrationError& e) {
    // The steps before the failure are handed on; the sample that failed is not.
    r.failure = e.failure();
  }
  relay.stop_clock();
  relay.hand_on();
  finish(r, *trajectory);
  return r;
}

}  // namespace epviz::sim
