// sim::simulate with a sink and a step observer: the events are those of the
// trajectory itself, in its order, however many steps lie between two
// samples; the sink's and the observer's time is not the integration's.
#include <gtest/gtest.h>

#include <ctime>
#include <vector>

#include "physics/cases.hpp"
#include "sim/simulate.hpp"
#include "sim/trajectory.hpp"

namespace epviz {
namespace {

struct Event {
  double t;
  bool output;
  double gamma1;
};

// The trajectory driven by hand (Trajectory::observe_steps and next()): the
// order every consumer must see.
std::vector<Event> driven_by_hand(const sim::RunSpec& spec) {
  std::vector<Event> events;
  auto trajectory = sim::Trajectory::start(spec);
  trajectory->observe_steps([&](const sim::Sample& s) {
    events.push_back({s.t, false, s.gamma[0]});
  });
  const sim::Sample first = trajectory->initial();
  events.push_back({first.t, true, first.gamma[0]});
  for (int k = 1; k <= spec.samples; ++k) {
    const sim::Sample s = trajectory->next();
    events.push_back({s.t, true, s.gamma[0]});
  }
  return events;
}

std::vector<Event> streamed(const sim::RunSpec& spec, sim::RunResult* result = nullptr) {
  std::vector<Event> events;
  auto r = sim::simulate(
      spec,
      [&](const sim::Sample& s) {
        events.push_back({s.t, true, s.gamma[0]});
      },
      [&](const sim::Sample& s) {
        events.push_back({s.t, false, s.gamma[0]});
      });
  if (result) *result = r;
  return events;
}

void expect_same(const std::vector<Event>& a, const std::vector<Event>& b) {
  ASSERT_EQ(a.size(), b.size());
  for (std::size_t i = 0; i < a.size(); ++i) {
    EXPECT_EQ(a[i].t, b[i].t) << "event " << i;
    EXPECT_EQ(a[i].output, b[i].output) << "event " << i;
    EXPECT_EQ(a[i].gamma1, b[i].gamma1) << "event " << i;
  }
}

sim::RunSpec kovalevskaya(sim::Method m, double t_end, int samples) {
  return sim::preset_run(physics::Case::kovalevskaya, m, sim::Formulation::direct, t_end, samples);
}

TEST(StreamedRun, HandsOnEveryStepAndSampleInTheTrajectorysOrder) {
  // Many samples and few steps between them, and the other way round: tens
  // of thousands of steps before the only sample, more than any buffer holds.
  for (auto [method, samples] :
       {std::pair{sim::Method::dop853, 2000}, std::pair{sim::Method::dop853, 1},
        std::pair{sim::Method::rk4, 3}}) {
    auto spec = kovalevskaya(method, 300.0, samples);
    spec.step = 1e-3;
    sim::RunResult result;
    const auto events = streamed(spec, &result);
    expect_same(events, driven_by_hand(spec));
    long steps = 0;
    for (const auto& e : events) steps += e.output ? 0 : 1;
    EXPECT_EQ(steps, result.stats.steps) << sim::name(method) << " " << samples;
    EXPECT_EQ(result.samples_written, long(samples) + 1);
  }
}

TEST(StreamedRun, HandsOnTheStepsBeforeAFailureAndNotTheFailedSample) {
  // A step budget that ends the run between two samples.
  auto spec = kovalevskaya(sim::Method::dop853, 300.0, 10);
  spec.max_steps = 500;
  sim::RunResult result;
  const auto events = streamed(spec, &result);
  ASSERT_TRUE(result.failure);
  ASSERT_FALSE(events.empty());
  long steps = 0, outputs = 0;
  for (const auto& e : events) (e.output ? outputs : steps) += 1;
  EXPECT_EQ(outputs, result.samples_written);
  EXPECT_LT(outputs, 11);
  EXPECT_EQ(steps, result.stats.steps);
  EXPECT_FALSE(events.back().output) << "the steps up to the failure come after the last sample";
}

double process_cpu_seconds() {
  timespec ts{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// Burns `seconds` of this thread's CPU time.
void burn(double seconds) {
  const double until = process_cpu_seconds() + seconds;
  volatile double x = 1.0;
  while (process_cpu_seconds() < until) x = x * 1.0000001;
}

TEST(StreamedRun, CpuSecondsCountTheIntegrationNotTheConsumers) {
  const auto spec = kovalevskaya(sim::Method::dop853, 1.0, 20);
  const double bare = sim::simulate(spec).cpu_seconds;
  const double start = process_cpu_seconds();
  const auto r = sim::simulate(
      spec, [](const sim::Sample&) { burn(0.005); }, [](const sim::Sample&) { burn(0.0005); });
  const double total = process_cpu_seconds() - start;
  ASSERT_GT(total, 0.1);  // 21 samples and dozens of steps burnt
  EXPECT_LT(r.cpu_seconds, 0.02) << "bare " << bare << " s, all " << total << " s";
  EXPECT_GT(r.cpu_seconds, 0.0);
}

}  // namespace
}  // namespace epviz
