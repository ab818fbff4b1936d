// The batch steppers on the direct system: every lane is the trajectory
// integrated alone by the scalar stepper, bit for bit, whatever the lane
// count, the neighbours (finishing or failing at other times) and the
// instruction set; the invariants as an independent check of the motion.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <functional>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "ensemble_reference.hpp"
#include "physics/direct_rhs_batch.hpp"
#include "physics/helpers.hpp"
#include "physics/invariants.hpp"
#include "support/simd_env.hpp"

namespace epviz::sim {
using physics::Body;
using physics::Case;
using physics::DirectBatchSystem;
using physics::DirectSystem;
using physics::InitialState;
using physics::Invariants;
using physics::Vector3d;
namespace {

using numerics::SimdPath;
using test::identical;

// A generic (chaotic) top: neighbouring trajectories part, so a lane that
// borrowed anything from another would show.
Body generic_body() {
  Body b;
  b.inertia = {1.0, 1.6, 2.1};
  b.com = {0.3, -0.2, 0.5};
  b.weight = 2.0;
  return b;
}

// n trajectories with t_end from 1.5 to 9 in no order and a few output times
// each, so that lanes finish at different times and are refilled.
std::vector<DirectBatchTask> mixed_tasks(int n) {
  std::vector<DirectBatchTask> tasks;
  for (int i = 0; i < n; ++i) {
    InitialState s;
    s.omega = {0.4 + 0.07 * i, -0.8 + 0.05 * (i % 5), 1.1 - 0.03 * i};
    s.gamma = Vector3d(0.2 * std::sin(i), 0.3, 1.0).normalized();
    const double t_end = 1.5 + double((i * 7) % 11) * 0.75;
    tasks.push_back(direct_batch_task(s, t_end, {0.0, t_end / 3, t_end / 2, t_end / 2}));
  }
  return tasks;
}

numerics::AdaptiveOptions tolerance(double tol) {
  numerics::AdaptiveOptions o;
  o.rtol = o.atol = tol;
  return o;
}

std::vector<SimdPath> paths_of_this_cpu() {
  std::vector<SimdPath> paths;
  for (SimdPath p : numerics::kSimdPaths)
    if (numerics::cpu_supports(p)) paths.push_back(p);
  return paths;
}

void expect_each_lane_alone(const Body& body, const std::vector<DirectBatchTask>& tasks,
                            DirectBatchSettings settings) {
  std::vector<DirectBatchResult> alone;
  for (const auto& task : tasks)
    alone.push_back(settings.method == BatchMethod::rk4
                        ? test::rk4_alone(body, task, settings.rk4)
                        : test::dop853_alone(body, task, settings.adaptive));
  for (SimdPath path : paths_of_this_cpu()) {
    for (int width : {1, 2, 4, 8}) {
      settings.path = path;
      settings.width = width;
      const auto batch = integrate_direct_batch(body, tasks, settings);
      ASSERT_EQ(batch.size(), tasks.size());
      for (std::size_t i = 0; i < tasks.size(); ++i)
        EXPECT_TRUE(identical(batch[i], alone[i]))
            << "trajectory " << i << ", path " << numerics::name(path) << ", " << width << " lanes";
    }
  }
}

TEST(DirectBatch, RhsIsDirectSystemsBitwise) {
  const Body body = generic_body();
  const DirectSystem scalar(body);
  const DirectBatchSystem batch = DirectBatchSystem::of(body);
  physics::test::Random rnd;
  for (int trial = 0; trial < 8; ++trial) {
    DirectSystem::State xs, d;
    xs << rnd.vec(), rnd.unit();
    double x[6], dx[6];
    for (int i = 0; i < 6; ++i) x[i] = xs[i];
    batch.rhs(0.0, x, dx);
    scalar.rhs(0.0, xs, d);
    for (int i = 0; i < 6; ++i) EXPECT_EQ(test::bits(dx[i]), test::bits(d[i]));
  }
}

// W = 1 reproduces the scalar DOP853 bit for bit (not merely to 1e-13): the
// batch performs its operations in its order, down to the summation order of
// Eigen's sum() in the error norm and the initial step (eigen_order_sum), and
// neither is compiled with fused multiply-adds.
TEST(DirectBatch, Dop853LanesAreTheScalarStepperAloneBitwise) {
  DirectBatchSettings settings;
  settings.adaptive = tolerance(1e-9);
  expect_each_lane_alone(generic_body(), mixed_tasks(19), settings);
}

// Hairer's initial step guess has branches for a vanishing derivative and a
// vanishing second derivative. Bodies at rest with gamma along r (no torque),
// and nearly at rest, among moving ones, start as alone: the generic body,
// whose derivative there is round-off (about 1e-17), and one with r on the
// third axis, whose derivative is exactly zero.
TEST(DirectBatch, StatesAtRestAndNearItStartAsAlone) {
  Body on_axis = generic_body();
  on_axis.com = {0.0, 0.0, 0.5};
  for (const Body& body : {generic_body(), on_axis}) {
    auto tasks = mixed_tasks(6);
    for (double spin : {0.0, 1e-13, 1e-7}) {
      InitialState s;
      s.omega = {spin, -spin, 0.5 * spin};
      s.gamma = body.com.normalized();
      tasks.push_back(direct_batch_task(s, 3.0, {1.0, 2.0}));
    }
    DirectBatchSettings settings;
    settings.adaptive = tolerance(1e-9);
    expect_each_lane_alone(body, tasks, settings);
  }
}

TEST(DirectBatch, Dop853WithGivenInitialStepAndPiControl) {
  DirectBatchSettings settings;
  settings.adaptive = tolerance(1e-7);
  settings.adaptive.h_init = 0.3;  // rejected at first
  settings.adaptive.beta = 0.04;
  settings.adaptive.h_max = 0.5;
  expect_each_lane_alone(generic_body(), mixed_tasks(9), settings);
}

TEST(DirectBatch, Rk4LanesAreTheScalarStepperAloneBitwise) {
  DirectBatchSettings settings;
  settings.method = BatchMethod::rk4;
  settings.rk4.h = 0.013;
  expect_each_lane_alone(generic_body(), mixed_tasks(11), settings);
}

TEST(DirectBatch, AFailingLaneFailsAloneAndTheOthersFinishAsAlone) {
  auto tasks = mixed_tasks(13);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  tasks[2].x0[4] = nan;                                      // fails at its start
  tasks[7].x0[0] = std::numeric_limits<double>::infinity();  // likewise
  for (BatchMethod method : {BatchMethod::dop853, BatchMethod::rk4}) {
    DirectBatchSettings settings;
    settings.method = method;
    settings.adaptive = tolerance(1e-9);
    const auto batch = integrate_direct_batch(generic_body(), tasks, settings);
    for (std::size_t i : {2u, 7u}) {
      ASSERT_TRUE(batch[i].failure) << i;
      EXPECT_EQ(batch[i].failure->kind, numerics::FailureKind::non_finite);
    }
    int failed = 0;
    for (const auto& r : batch) failed += r.failure.has_value();
    EXPECT_EQ(failed, 2);
    expect_each_lane_alone(generic_body(), tasks, settings);
  }
}

numerics::Failure output_refused(double t) {
  return numerics::Failure{t, "dop853", numerics::FailureKind::lost_motion, "refused"};
}

// An output check that refuses the outputs `refused` names.
numerics::BatchOutputCheck<6> refusing(std::function<bool(long id, double t)> refused) {
  return [refused](long id, double t,
                   const std::array<double, 6>&) -> std::optional<numerics::Failure> {
    if (refused(id, t)) return output_refused(t);
    return std::nullopt;
  };
}

// The task alone with its output k refused: the outputs before it, and the
// work done up to making it (as a consumer of the scalar run that refuses the
// sample there).
DirectBatchResult refused_alone(const DirectBatchTask& task, const numerics::AdaptiveOptions& o,
                                std::size_t k) {
  numerics::Dop853<DirectSystem> s(DirectSystem(generic_body()), o);
  s.init(task.t0, test::to_state(task.x0));
  DirectBatchResult r;
  for (std::size_t j = 0; j <= k; ++j) {
    while (s.t() < task.out_times[j]) s.step();
    const auto x = test::to_array(s.dense(task.out_times[j]));
    if (j < k) r.outputs.push_back(x);
  }
  r.t = s.t();
  r.x = test::to_array(s.state());
  r.steps = s.stats().steps;
  r.rejected_steps = s.stats().rejected_steps;
  r.rhs_evals = s.stats().rhs_evals;
  r.failure = output_refused(task.out_times[k]);
  return r;
}

// An output check ends its trajectory at the output it refuses, without that
// output, with the work done to make it; the other lanes go on as alone.
TEST(DirectBatch, AnOutputCheckFailsItsLaneAlone) {
  auto tasks = mixed_tasks(13);
  for (std::size_t i = 0; i < tasks.size(); ++i) tasks[i].id = long(i);
  const double refused = tasks[5].out_times[2];
  DirectBatchSettings settings;
  settings.adaptive = tolerance(1e-9);
  settings.check = refusing([&](long id, double t) {
    return (id == 5 && t == refused) || (id == 9 && t == tasks[9].t0);
  });
  std::vector<DirectBatchResult> expected;
  for (const auto& task : tasks)
    expected.push_back(test::dop853_alone(generic_body(), task, settings.adaptive));
  expected[5] = refused_alone(tasks[5], settings.adaptive, 2);
  expected[9] = DirectBatchResult{};  // refused at its first output, t0, before any work
  expected[9].t = tasks[9].t0;
  expected[9].x = tasks[9].x0;
  expected[9].failure = output_refused(tasks[9].t0);
  for (SimdPath path : paths_of_this_cpu()) {
    for (int width : {1, 2, 4, 8}) {
      settings.path = path;
      settings.width = width;
      const auto batch = integrate_direct_batch(generic_body(), tasks, settings);
      for (std::size_t i = 0; i < tasks.size(); ++i)
        EXPECT_TRUE(identical(batch[i], expected[i]))
            << "trajectory " << i << ", path " << numerics::name(path) << ", " << width << " lanes";
    }
  }
  settings.method = BatchMethod::rk4;  // which has no output check
  EXPECT_THROW(integrate_direct_batch(generic_body(), tasks, settings), std::invalid_argument);
}

// The step budget is per trajectory: the long ones fail in the middle of the
// batch (step_budget), the short ones finish, each as alone.
// Trajectories whose last step holds their only output: the steps that end
// trajectories wait for their dense output to be computed several at a time
// while their lanes go on with new ones. Each still ends as alone, once, its
// result complete when it is told ended; a check that refuses the output in
// that last step fails it there.
TEST(DirectBatch, TrajectoriesEndingInTheirLastStepEndAsAlone) {
  auto tasks = mixed_tasks(29);
  for (std::size_t i = 0; i < tasks.size(); ++i) {
    tasks[i].id = long(i);
    tasks[i].out_times = {tasks[i].t_end * (1.0 - 1e-9)};
  }
  const auto refused = [](long id) { return id % 4 == 1; };
  DirectBatchSettings settings;
  settings.adaptive = tolerance(1e-9);
  settings.check = refusing([&](long id, double) { return refused(id); });
  std::vector<DirectBatchResult> expected;
  for (const auto& task : tasks) {
    expected.push_back(refused(task.id)
                           ? refused_alone(task, settings.adaptive, 0)
                           : test::dop853_alone(generic_body(), task, settings.adaptive));
    // The output lies in the last step: the step that reaches it passes t_end.
    numerics::Dop853<DirectSystem> s(DirectSystem(generic_body()), settings.adaptive);
    s.init(task.t0, test::to_state(task.x0));
    while (s.t() < task.out_times[0]) s.step();
    ASSERT_GE(s.t(), task.t_end) << "trajectory " << task.id;
  }
  for (SimdPath path : paths_of_this_cpu()) {
    for (int width : {1, 2, 4, 8}) {
      settings.path = path;
      settings.width = width;
      std::vector<int> ended(tasks.size(), 0);
      std::vector<DirectBatchResult> told(tasks.size());
      settings.events.ended = [&](long id, const DirectBatchResult& r) {
        ++ended[std::size_t(id)];
        told[std::size_t(id)] = r;
      };
      const auto batch = integrate_direct_batch(generic_body(), tasks, settings);
      for (std::size_t i = 0; i < tasks.size(); ++i) {
        std::string where = "trajectory ";
        where += std::to_string(i);
        where += ", path ";
        where += numerics::name(path);
        where += ", ";
        where += std::to_string(width);
        where += " lanes";
        EXPECT_TRUE(identical(batch[i], expected[i])) << where;
        EXPECT_EQ(ended[i], 1) << where;
        EXPECT_TRUE(identical(told[i], expected[i])) << where;
      }
    }
  }
}

TEST(DirectBatch, StepBudgetStopsTheLongTrajectoriesOnly) {
  DirectBatchSettings settings;
  settings.adaptive = tolerance(1e-10);
  const auto tasks = mixed_tasks(12);
  // The budget: the median of the attempts the trajectories need.
  std::vector<long> attempts;
  for (const auto& r : integrate_direct_batch(generic_body(), tasks, settings))
    attempts.push_back(r.steps + r.rejected_steps);
  std::sort(attempts.begin(), attempts.end());
  settings.adaptive.max_steps = attempts[attempts.size() / 2];
  const auto batch = integrate_direct_batch(generic_body(), tasks, settings);
  int failed = 0, finished = 0;
  for (const auto& r : batch) {
    if (r.failure) {
      EXPECT_EQ(r.failure->kind, numerics::FailureKind::step_budget);
    }
    (r.failure ? failed : finished)++;
  }
  EXPECT_GT(failed, 0);
  EXPECT_GT(finished, 0);
  expect_each_lane_alone(generic_body(), tasks, settings);
}

// An absolute tolerance far below round-off: the step size underflows.
TEST(DirectBatch, UnreachableToleranceUnderflowsLikeAlone) {
  DirectBatchSettings settings;
  settings.adaptive.rtol = 0;
  settings.adaptive.atol = 1e-300;
  auto tasks = mixed_tasks(5);
  const auto batch = integrate_direct_batch(generic_body(), tasks, settings);
  for (const auto& r : batch) {
    ASSERT_TRUE(r.failure);
    EXPECT_NE(r.failure->kind, numerics::FailureKind::non_finite) << r.failure->message();
  }
  expect_each_lane_alone(generic_body(), tasks, settings);
}

using epviz::test::ScopedSimdEnv;

TEST(DirectBatch, ForcedPathsGiveTheScalarPathsResultsBitwise) {
  const auto tasks = mixed_tasks(10);
  DirectBatchSettings settings;
  settings.path = SimdPath::scalar;
  const auto scalar = integrate_direct_batch(generic_body(), tasks, settings);
  for (SimdPath path : paths_of_this_cpu()) {
    ScopedSimdEnv env(std::string(numerics::name(path)).c_str());
    EXPECT_EQ(numerics::chosen_simd_path(), path);
    const auto forced = integrate_direct_batch(generic_body(), tasks);  // path from EPVIZ_SIMD
    for (std::size_t i = 0; i < tasks.size(); ++i)
      EXPECT_TRUE(identical(forced[i], scalar[i])) << numerics::name(path) << " " << i;
  }
}

std::string refusal(const char* value) {
  ScopedSimdEnv env(value);
  try {
    integrate_direct_batch(generic_body(), mixed_tasks(1));
  } catch (const std::invalid_argument& e) {
    return e.what();
  }
  return "(accepted)";
}

TEST(DirectBatch, SimdVariableIsCheckedBeforeWork) {
  EXPECT_EQ(refusal("avx3"), "EPVIZ_SIMD=avx3: unknown; allowed: scalar, sse2, avx2, avx512");
  for (SimdPath path : numerics::kSimdPaths) {
    if (numerics::cpu_supports(path)) continue;
    const std::string what = refusal(std::string(numerics::name(path)).c_str());
    EXPECT_NE(what.find("this CPU lacks that instruction set"), std::string::npos) << what;
  }
  {
    ScopedSimdEnv empty("");
    EXPECT_EQ(numerics::chosen_simd_path(), numerics::widest_simd_path());
  }
  EXPECT_TRUE(numerics::cpu_supports(SimdPath::scalar));
}

TEST(DirectBatch, BadTasksAndWidthsAreRefused) {
  auto tasks = mixed_tasks(3);
  tasks[1].out_times = {1.0, 0.5};
  EXPECT_THROW(integrate_direct_batch(generic_body(), tasks), std::invalid_argument);
  tasks = mixed_tasks(3);
  tasks[2].t_end = -1.0;
  EXPECT_THROW(integrate_direct_batch(generic_body(), tasks), std::invalid_argument);
  DirectBatchSettings settings;
  settings.width = 3;
  EXPECT_THROW(integrate_direct_batch(generic_body(), mixed_tasks(3), settings),
               std::invalid_argument);
}

// Energy, |gamma|^2 and the area integral, which the steppers know nothing
// of, stay within the tolerance's reach over every trajectory of a batch.
TEST(DirectBatch, InvariantsAreConserved) {
  const Body body = generic_body();
  DirectBatchSettings settings;
  settings.adaptive = tolerance(1e-11);
  auto tasks = mixed_tasks(16);
  const auto batch = integrate_direct_batch(body, tasks, settings);
  for (std::size_t i = 0; i < tasks.size(); ++i) {
    const auto& x0 = tasks[i].x0;
    const auto& x1 = batch[i].x;
    ASSERT_FALSE(batch[i].failure);
    const Vector3d w0(x0[0], x0[1], x0[2]), g0(x0[3], x0[4], x0[5]);
    const Vector3d w1(x1[0], x1[1], x1[2]), g1(x1[3], x1[4], x1[5]);
    const Invariants a = invariants(body, Case::generic, w0, g0);
    const Invariants b = invariants(body, Case::generic, w1, g1);
    const Invariants scale = invariant_scales(body, Case::generic, w0, g0);
    EXPECT_LT(std::abs(b.energy - a.energy) / scale.energy, 1e-8) << i;
    EXPECT_LT(std::abs(b.area - a.area) / scale.area, 1e-8) << i;
    EXPECT_LT(std::abs(b.gamma_norm2 - a.gamma_norm2) / scale.gamma_norm2, 1e-8) << i;
    EXPECT_GT(batch[i].steps, 10);
  }
}

// What a step hook saw of one trajectory: every step's ends, and the dense
// output at the middle of the steps it looked into.
struct HookLog {
  std::vector<std::array<double, 6>> ends;  // x_prev, x of each step
  std::vector<double> times;                // t_prev, t of each step
  std::vector<std::array<double, 6>> middles;
  bool operator==(const HookLog&) const = default;
};

constexpr int kLookEvery = 3;  // the hook asks for the dense output of every third step
constexpr long kStopped = 4, kStopAt = 9, kFailed = 8, kFailAt = 6;

numerics::Failure hook_failure(double t) {
  return numerics::Failure{t, "dop853", numerics::FailureKind::lost_motion, "hook"};
}

// The hook's trajectories driven by the scalar DOP853 alone: step after step
// until t_end, the dense output of every third step read at its middle,
// trajectory kStopped stopped and kFailed failed at their kStopAt-th and
// kFailAt-th steps.
DirectBatchResult hooked_alone(const DirectBatchTask& task, const numerics::AdaptiveOptions& opts,
                               HookLog& log) {
  numerics::Dop853<DirectSystem> s(DirectSystem(generic_body()), opts);
  s.init(task.t0, test::to_state(task.x0));
  DirectBatchResult r;
  for (long n = 1; s.t() < task.t_end; ++n) {
    log.times.push_back(s.t());
    log.ends.push_back(test::to_array(s.state()));
    s.step();
    log.times.push_back(s.t());
    log.ends.push_back(test::to_array(s.state()));
    if (n % kLookEvery != 0) continue;
    log.middles.push_back(test::to_array(s.dense(0.5 * (s.t_prev() + s.t()))));
    if ((task.id == kStopped && n == kStopAt) || (task.id == kFailed && n == kFailAt)) {
      r.stopped = task.id == kStopped;
      if (task.id == kFailed) r.failure = hook_failure(s.t());
      break;
    }
  }
  r.t = r.stopped || r.failure ? s.t() : task.t_end;
  r.x = test::to_array(r.stopped || r.failure ? s.state() : s.dense(task.t_end));
  r.steps = s.stats().steps;
  r.rejected_steps = s.stats().rejected_steps;
  r.rhs_evals = s.stats().rhs_evals;
  return r;
}

// A step hook sees every step of every lane, bitwise the scalar stepper's,
// reads the dense output of the steps it asks for as the scalar stepper's
// dense(t) (whole, or a component at a time), and ends a trajectory (stopped or failed) alone; the work counted
// is the scalar run's, dense stages included where they were used.
TEST(DirectBatch, AStepHookSeesEachLanesStepsAndDenseOutputAsAlone) {
  auto tasks = mixed_tasks(13);
  for (std::size_t i = 0; i < tasks.size(); ++i) {
    tasks[i].id = long(i);
    tasks[i].out_times.clear();
  }
  DirectBatchSettings settings;
  settings.adaptive = tolerance(1e-9);
  std::vector<HookLog> expected_logs(tasks.size()), logs;
  std::vector<DirectBatchResult> expected;
  for (std::size_t i = 0; i < tasks.size(); ++i)
    expected.push_back(hooked_alone(tasks[i], settings.adaptive, expected_logs[i]));
  ASSERT_TRUE(expected[kStopped].stopped);
  ASSERT_TRUE(expected[kFailed].failure);
  std::vector<long> seen;
  settings.step_hook.wants_dense = [&](const numerics::BatchStep<6>& step) {
    HookLog& log = logs[std::size_t(step.id)];
    log.times.insert(log.times.end(), {step.t_prev, step.t});
    log.ends.insert(log.ends.end(), {step.x_prev, step.x});
    return ++seen[std::size_t(step.id)] % kLookEvery == 0;
  };
  settings.step_hook.look = [&](const numerics::BatchStep<6>& step,
                                const numerics::BatchDense<6>& dense) {
    const double middle = 0.5 * (step.t_prev + step.t);
    const auto x = dense(middle);
    logs[std::size_t(step.id)].middles.push_back(x);
    for (int i = 0; i < 6; ++i)  // one component alone is the state's
      EXPECT_EQ(test::bits(dense.component(i, middle)), test::bits(x[std::size_t(i)]));
    numerics::BatchStepVerdict verdict;
    const long n = seen[std::size_t(step.id)];
    verdict.stop = step.id == kStopped && n == kStopAt;
    if (step.id == kFailed && n == kFailAt) verdict.failure = hook_failure(step.t);
    return verdict;
  };
  for (SimdPath path : paths_of_this_cpu()) {
    for (int width : {1, 2, 4, 8}) {
      settings.path = path;
      settings.width = width;
      logs.assign(tasks.size(), {});
      seen.assign(tasks.size(), 0);
      const auto batch = integrate_direct_batch(generic_body(), tasks, settings);
      for (std::size_t i = 0; i < tasks.size(); ++i) {
        EXPECT_TRUE(identical(batch[i], expected[i]))
            << "trajectory " << i << ", path " << numerics::name(path) << ", " << width << " lanes";
        EXPECT_EQ(batch[i].stopped, expected[i].stopped) << i;
        EXPECT_TRUE(logs[i] == expected_logs[i])
            << "what the hook saw of trajectory " << i << ", path " << numerics::name(path) << ", "
            << width << " lanes";
      }
    }
  }
  settings.method = BatchMethod::rk4;  // which has no step hook
  EXPECT_THROW(integrate_direct_batch(generic_body(), tasks, settings), std::invalid_argument);
}

// Two threads of W lanes each, taking chunks in turn: the same results, bit
// for bit, as one batch (and so as each trajectory alone).
TEST(DirectBatch, ParallelOverThreadsGivesTheSameResults) {
  const auto tasks = mixed_tasks(300);
  DirectBatchSettings settings;
  settings.adaptive = tolerance(1e-8);
  const auto serial = integrate_direct_batch(generic_body(), tasks, settings);
  for (int threads : {1, 2, 3}) {
    const auto parallel = integrate_direct_batch_parallel(generic_body(), tasks, settings, threads);
    ASSERT_EQ(parallel.size(), tasks.size());
    for (std::size_t i = 0; i < tasks.size(); ++i)
      EXPECT_TRUE(identical(parallel[i], serial[i])) << threads << " threads, trajectory " << i;
  }
  EXPECT_THROW(integrate_direct_batch_parallel(generic_body(), tasks, settings, 0),
               std::invalid_argument);
  settings.width = 5;
  EXPECT_THROW(integrate_direct_batch_parallel(generic_body(), tasks, settings),
               std::invalid_argument);
}

}  // namespace
}  // namespace epviz::sim
