// Ensembles: ns per trajectory-step of 4,096 trajectories of the direct
// system by DOP853 at one tolerance, the scalar stepper one trajectory at a
// time against the batch stepper on each instruction set of this CPU and lane
// count (docs/ensembles.md has the figures). And the step attempt's arithmetic
// alone (ensemble_attempt_only): what the batch would cost per step if its
// control, output and queue were free, the ceiling of its speed-up.
//
//   build/bench/epviz_bench --benchmark_filter=ensemble
#include <benchmark/benchmark.h>

#include <cmath>
#include <memory>
#include <string>
#include <vector>

#include "numerics/embedded_rk.hpp"
#include "physics/direct.hpp"
#include "sim/ensemble.hpp"
#include "sim/ensemble_isa.hpp"

namespace {

using namespace epviz;

constexpr int kTrajectories = 4096;
constexpr double kTolerance = 1e-10;

physics::Body ensemble_body() {
  physics::Body b;
  b.inertia = {1.0, 1.6, 2.1};
  b.com = {0.3, -0.2, 0.5};
  b.weight = 2.0;
  return b;
}

// Initial states spread over a box of angular velocities, t_end from 2 to 4.
const std::vector<sim::DirectBatchTask>& ensemble() {
  static const std::vector<sim::DirectBatchTask> tasks = [] {
    std::vector<sim::DirectBatchTask> t;
    for (int i = 0; i < kTrajectories; ++i) {
      physics::InitialState s;
      s.omega = {-1.0 + 2.0 * (i % 16) / 15.0, -1.0 + 2.0 * ((i / 16) % 16) / 15.0,
                 0.5 + (i / 256) / 16.0};
      s.gamma = physics::Vector3d(0.1 * std::sin(i), 0.2, 1.0).normalized();
      t.push_back(sim::direct_batch_task(s, 2.0 + 2.0 * (i % 7) / 6.0));
    }
    return t;
  }();
  return tasks;
}

numerics::AdaptiveOptions options() {
  numerics::AdaptiveOptions o;
  o.rtol = o.atol = kTolerance;
  return o;
}

void ensemble_scalar_dop853(benchmark::State& state) {
  const physics::DirectSystem sys(ensemble_body());
  long steps = 0;
  for (auto _ : state) {
    for (const auto& task : ensemble()) {
      numerics::Dop853<physics::DirectSystem> s(sys, options());
      physics::DirectSystem::State x;
      for (int i = 0; i < 6; ++i) x[i] = task.x0[std::size_t(i)];
      s.init(task.t0, x);
      while (s.t() < task.t_end) s.step();
      benchmark::DoNotOptimize(s.dense(task.t_end));
      steps += s.stats().steps + s.stats().rejected_steps;
    }
  }
  state.counters["per_step"] =
      benchmark::Counter(double(steps), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}
BENCHMARK(ensemble_scalar_dop853)->Unit(benchmark::kMillisecond);

void ensemble_batch_dop853(benchmark::State& state, numerics::SimdPath path, int width) {
  sim::DirectBatchSettings settings;
  settings.adaptive = options();
  settings.path = path;
  settings.width = width;
  long steps = 0;
  for (auto _ : state) {
    const auto results = sim::integrate_direct_batch(ensemble_body(), ensemble(), settings);
    for (const auto& r : results) steps += r.steps + r.rejected_steps;
    benchmark::DoNotOptimize(results.data());
  }
  state.counters["per_step"] =
      benchmark::Counter(double(steps), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// The attempt kernel over and over on W lanes of the ensemble's first states
// with a step of 0.05 (each attempt from the same state: no control at all).
template <int W>
void ensemble_attempt_only(benchmark::State& state, numerics::SimdPath path) {
  const auto& kernels = [&]() -> const auto& {
    const auto& k = sim::batch_isa::kernels_for(path);
    if constexpr (W == 1) return k.w1.dop853;
    if constexpr (W == 2) return k.w2.dop853;
    if constexpr (W == 4) return k.w4.dop853;
    if constexpr (W == 8) return k.w8.dop853;
  }
  ();
  const auto sys = physics::DirectBatchSystem::of(ensemble_body());
  auto lanes = std::make_unique<numerics::EmbeddedLanes<6, W, numerics::Dop853Tableau>>();
  lanes->atol = lanes->rtol = kTolerance;
  for (int l = 0; l < W; ++l) {
    double x[6], k0[6];
    for (int i = 0; i < 6; ++i)
      x[i] = lanes->x[i][l] = ensemble()[std::size_t(l)].x0[std::size_t(i)];
    sys.rhs(0.0, x, k0);
    for (int i = 0; i < 6; ++i) lanes->k[0][i][l] = k0[i];
    lanes->t[l] = 0.0;
    lanes->h[l] = 0.05;
  }
  long attempts = 0;
  for (auto _ : state) {
    kernels.attempt(*lanes, sys);
    benchmark::DoNotOptimize(lanes->err[0]);
    attempts += W;
  }
  state.counters["per_step"] = benchmark::Counter(
      double(attempts), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

// One benchmark per path this CPU has and lane count.
const bool registered = [] {
  for (numerics::SimdPath path : numerics::kSimdPaths) {
    if (!numerics::cpu_supports(path)) continue;
    for (int width : {1, 2, 4, 8}) {
      const std::string name = "ensemble_batch_dop853/" + std::string(numerics::name(path)) + "/W" +
                               std::to_string(width);
      benchmark::RegisterBenchmark(name.c_str(), ensemble_batch_dop853, path, width)
          ->Unit(benchmark::kMillisecond);
    }
    const std::string only = "ensemble_attempt_only/" + std::string(numerics::name(path)) + "/W";
    const int lanes = sim::default_batch_width(path);
    const auto add = [&](auto fn) {
      benchmark::RegisterBenchmark((only + std::to_string(lanes)).c_str(), fn, path);
    };
    switch (lanes) {
      case 1: add(ensemble_attempt_only<1>); break;
      case 2: add(ensemble_attempt_only<2>); break;
      case 4: add(ensemble_attempt_only<4>); break;
      default: add(ensemble_attempt_only<8>); break;
    }
  }
  return true;
}();

}  // namespace
