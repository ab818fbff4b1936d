#pragma once
// What a batch lane must reproduce: the scalar steppers (numerics/embedded_rk.hpp,
// numerics/rk4.hpp) on one trajectory of the direct system alone, driven the
// way the batch drives its lanes, and an exact comparison of results.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <string>

#include "numerics/embedded_rk.hpp"
#include "numerics/rk4.hpp"
#include "physics/direct.hpp"
#include "sim/ensemble.hpp"
#include "sim/steppers.hpp"

namespace epviz::sim::test {
using physics::Body;
using physics::DirectSystem;

inline std::array<double, 6> to_array(const DirectSystem::State& x) {
  std::array<double, 6> a;
  for (int i = 0; i < 6; ++i) a[std::size_t(i)] = x[i];
  return a;
}

inline DirectSystem::State to_state(const std::array<double, 6>& a) {
  DirectSystem::State x;
  for (int i = 0; i < 6; ++i) x[i] = a[std::size_t(i)];
  return x;
}

// DOP853 alone: `while (s.t() < t_out) s.step(); s.dense(t_out)` for each
// output time, then for t_end.
inline DirectBatchResult dop853_alone(const Body& body, const DirectBatchTask& task,
                                      const numerics::AdaptiveOptions& opts) {
  numerics::Dop853<DirectSystem> s(DirectSystem(body), opts);
  s.init(task.t0, to_state(task.x0));
  DirectBatchResult r;
  try {
    for (double t : task.out_times) {
      while (s.t() < t) s.step();
      r.outputs.push_back(to_array(s.dense(t)));
    }
    while (s.t() < task.t_end) s.step();
    r.x = to_array(s.dense(task.t_end));
    r.t = task.t_end;
  } catch (const numerics::IntegrationError& e) {
    r.failure = e.failure();
    r.x = to_array(s.state());
    r.t = s.t();
  }
  r.steps = s.stats().steps;
  r.rejected_steps = s.stats().rejected_steps;
  r.rhs_evals = s.stats().rhs_evals;
  return r;
}

// RK4 alone, landing on each output time by numerics::rk4_step_towards.
inline DirectBatchResult rk4_alone(const Body& body, const DirectBatchTask& task,
                                   const numerics::BatchRk4Options& opts) {
  numerics::Rk4<DirectSystem> s{DirectSystem(body)};
  DirectSystem::State x = to_state(task.x0);
  double t = task.t0;
  DirectBatchResult r;
  std::vector<double> targets = task.out_times;
  targets.push_back(task.t_end);
  try {
    for (std::size_t i = 0; i < targets.size(); ++i) {
      while (t < targets[i]) {
        const numerics::Rk4Step step = numerics::rk4_step_towards(t, targets[i], opts.h);
        s.step(x, t, step.h);
        t = step.lands ? targets[i] : t + step.h;
      }
      if (i + 1 < targets.size()) r.outputs.push_back(to_array(x));
    }
    r.t = task.t_end;
  } catch (const numerics::IntegrationError& e) {
    r.failure = e.failure();
    r.t = t;
  }
  r.x = to_array(x);
  r.steps = s.stats().steps;
  r.rhs_evals = s.stats().rhs_evals;
  return r;
}

inline std::uint64_t bits(double v) { return std::bit_cast<std::uint64_t>(v); }

inline ::testing::AssertionResult same_bits(const std::array<double, 6>& a,
                                            const std::array<double, 6>& b) {
  for (std::size_t i = 0; i < 6; ++i)
    if (bits(a[i]) != bits(b[i]))
      return ::testing::AssertionFailure()
             << "component " << i << ": " << std::hexfloat << a[i] << " vs " << b[i];
  return ::testing::AssertionSuccess();
}

// Every number of the two results equal bit for bit, the failures alike.
inline ::testing::AssertionResult identical(const DirectBatchResult& a,
                                            const DirectBatchResult& b) {
  if (a.steps != b.steps || a.rejected_steps != b.rejected_steps)
    return ::testing::AssertionFailure() << "steps " << a.steps << "/" << a.rejected_steps << " vs "
                                         << b.steps << "/" << b.rejected_steps;
  if (a.rhs_evals != b.rhs_evals)
    return ::testing::AssertionFailure() << "rhs_evals " << a.rhs_evals << " vs " << b.rhs_evals;
  if (bits(a.t) != bits(b.t)) return ::testing::AssertionFailure() << "t " << a.t << " vs " << b.t;
  if (a.failure.has_value() != b.failure.has_value())
    return ::testing::AssertionFailure() << "one failed, the other did not";
  if (a.failure &&
      (a.failure->kind != b.failure->kind || bits(a.failure->t) != bits(b.failure->t) ||
       a.failure->detail != b.failure->detail || a.failure->method != b.failure->method))
    return ::testing::AssertionFailure()
           << "failures differ: " << a.failure->message() << " vs " << b.failure->message();
  if (a.outputs.size() != b.outputs.size())
    return ::testing::AssertionFailure()
           << a.outputs.size() << " vs " << b.outputs.size() << " outputs";
  for (std::size_t i = 0; i < a.outputs.size(); ++i)
    if (auto same = same_bits(a.outputs[i], b.outputs[i]); !same)
      return same << " (output " << i << ")";
  if (auto same = same_bits(a.x, b.x); !same) return same << " (final state)";
  return ::testing::AssertionSuccess();
}

}  // namespace epviz::sim::test
