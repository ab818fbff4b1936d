// Cost of one right-hand side evaluation and of one step of each method in each
// formulation, on the Kovalevskaya top (a bounded, smooth motion).
//
//   build/bench/epviz_bench --benchmark_filter=direct
#include <benchmark/benchmark.h>

#include <chrono>
#include <cmath>

#include "numerics/composition.hpp"
#include "numerics/embedded_rk.hpp"
#include "numerics/gauss_legendre.hpp"
#include "numerics/rk4.hpp"
#include "numerics/splitting.hpp"
#include "physics/cases.hpp"
#include "physics/direct.hpp"
#include "physics/free_rigid_body_flow.hpp"
#include "physics/riccati.hpp"
#include "physics/spinor.hpp"

namespace {

using namespace epviz;

const physics::CasePreset& bench_case() { return physics::preset(physics::Case::kovalevskaya); }

template <class Sys>
void rhs(benchmark::State& state) {
  const Sys sys(bench_case().body);
  auto x = sys.pack(bench_case().initial);
  typename Sys::State dx;
  for (auto _ : state) {
    sys.rhs(0.0, x, dx);
    benchmark::DoNotOptimize(dx);
    benchmark::ClobberMemory();
  }
}

template <class Stepper>
void fixed_step(benchmark::State& state) {
  using Sys = std::decay_t<decltype(std::declval<Stepper&>().system())>;
  Stepper stepper{Sys(bench_case().body)};
  auto x = stepper.system().pack(bench_case().initial);
  const double h = 0.01;
  double t = 0.0;
  for (auto _ : state) {
    stepper.step(x, t, h);
    t += h;
    benchmark::DoNotOptimize(x);
  }
  state.counters["rhs/step"] = double(stepper.stats().rhs_evals) / double(stepper.stats().steps);
  state.counters["per_t"] =
      benchmark::Counter(t, benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

template <class Stepper>
void adaptive_step(benchmark::State& state) {
  using Sys = std::decay_t<decltype(std::declval<Stepper&>().system())>;
  numerics::AdaptiveOptions opts;
  opts.rtol = opts.atol = 1e-10;
  Stepper stepper(Sys(bench_case().body), opts);
  stepper.init(0.0, stepper.system().pack(bench_case().initial));
  for (auto _ : state) {
    stepper.step();
    benchmark::DoNotOptimize(stepper.state());
  }
  const numerics::Stats& st = stepper.stats();
  state.counters["rhs/step"] = double(st.rhs_evals) / double(st.steps);
  state.counters["rej/step"] = double(st.rejected_steps) / double(st.steps);
  state.counters["h"] = stepper.t() / double(st.steps);  // mean accepted step
  // Cost per unit of simulated time (shown as time per 1 time unit): what a
  // cheaper step that needs more steps would not improve.
  state.counters["per_t"] =
      benchmark::Counter(stepper.t(), benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

using physics::DirectSystem;
using physics::RiccatiSystem;
using physics::SpinorSystem;

BENCHMARK(rhs<DirectSystem>)->Name("rhs/direct");
BENCHMARK(rhs<RiccatiSystem>)->Name("rhs/riccati");
BENCHMARK(rhs<SpinorSystem>)->Name("rhs/spinor");

#define EPVIZ_FIXED(Method, Sys, label) \
  BENCHMARK(fixed_step<numerics::Method<Sys>>)->Name("step/" label);
#define EPVIZ_ADAPTIVE(Method, Sys, label) \
  BENCHMARK(adaptive_step<numerics::Method<Sys>>)->Name("step/" label);

EPVIZ_FIXED(Rk4, DirectSystem, "direct/rk4")
EPVIZ_ADAPTIVE(Dopri5, DirectSystem, "direct/dopri5")
EPVIZ_ADAPTIVE(Dop853, DirectSystem, "direct/dop853")
EPVIZ_FIXED(ImplicitMidpoint, DirectSystem, "direct/midpoint")
EPVIZ_FIXED(Gauss4, DirectSystem, "direct/gauss4")
EPVIZ_FIXED(Gauss6, DirectSystem, "direct/gauss6")
EPVIZ_FIXED(StrangSplitting, DirectSystem, "direct/splitting")
EPVIZ_FIXED(Composition2, physics::ExactSplitSystem, "direct/exact-split2")
EPVIZ_FIXED(Composition4, physics::ExactSplitSystem, "direct/exact-split4")

EPVIZ_FIXED(Rk4, RiccatiSystem, "riccati/rk4")
EPVIZ_ADAPTIVE(Dopri5, RiccatiSystem, "riccati/dopri5")
EPVIZ_ADAPTIVE(Dop853, RiccatiSystem, "riccati/dop853")
EPVIZ_FIXED(ImplicitMidpoint, RiccatiSystem, "riccati/midpoint")
EPVIZ_FIXED(Gauss4, RiccatiSystem, "riccati/gauss4")
EPVIZ_FIXED(Gauss6, RiccatiSystem, "riccati/gauss6")

EPVIZ_FIXED(Rk4, SpinorSystem, "spinor/rk4")
EPVIZ_ADAPTIVE(Dopri5, SpinorSystem, "spinor/dopri5")
EPVIZ_ADAPTIVE(Dop853, SpinorSystem, "spinor/dop853")
EPVIZ_FIXED(ImplicitMidpoint, SpinorSystem, "spinor/midpoint")
EPVIZ_FIXED(Gauss4, SpinorSystem, "spinor/gauss4")
EPVIZ_FIXED(Gauss6, SpinorSystem, "spinor/gauss6")

// One exact free rigid body flow: the Kovalevskaya body (I1 = I2: the
// closed-form precession) and the generic body (distinct moments: Jacobi
// elliptic functions and the elliptic integrals of the first and third kinds).
template <physics::Case C>
void free_flow(benchmark::State& state) {
  const auto& p = physics::preset(C);
  const physics::FreeRigidBodyFlow f(p.body.inertia);
  Eigen::Vector3d w = p.initial.omega, g = p.initial.gamma;
  for (auto _ : state) {
    f.advance(0.01, w, g);
    benchmark::DoNotOptimize(w);
    benchmark::DoNotOptimize(g);
  }
}
BENCHMARK(free_flow<physics::Case::kovalevskaya>)->Name("flow/free-rigid-body/kovalevskaya");
BENCHMARK(free_flow<physics::Case::generic>)->Name("flow/free-rigid-body/generic");

// Work-precision at equal final-time error on the Kovalevskaya top (t = 10):
// the fewest steps (geometric sweep) with which the axis-by-axis splitting and
// exact-split4 reach the error given as the argument's exponent, then the
// wall-clock time of both runs. Counters: steps of each and
// ratio = time(splitting) / time(exact-split4) (> 1: exact-split4 is cheaper).
using Vec6 = Eigen::Matrix<double, 6, 1>;
constexpr double kWpT = 10.0;

template <class Stepper>
Vec6 run_steps(Stepper s, long n) {
  auto x = s.system().pack(bench_case().initial);
  const double h = kWpT / double(n);
  for (long i = 0; i < n; ++i) s.step(x, double(i) * h, h);
  return x;
}

const Vec6& wp_reference() {
  static const Vec6 ref = [] {
    numerics::AdaptiveOptions o;
    o.rtol = o.atol = 1e-14;
    numerics::Dop853<DirectSystem> s(DirectSystem(bench_case().body), o);
    s.init(0.0, s.system().pack(bench_case().initial));
    while (s.t() < kWpT) s.step();
    return Vec6(s.dense(kWpT));
  }();
  return ref;
}

template <class Make>
long steps_for(Make make, double target) {
  for (long n = 16; n <= (1L << 24); n = long(std::ceil(double(n) * 1.1)))
    if ((run_steps(make(), n) - wp_reference()).norm() <= target) return n;
  return -1;
}

void work_precision_ratio(benchmark::State& state) {
  const double target = std::pow(10.0, -double(state.range(0)));
  const auto& body = bench_case().body;
  auto axis = [&] { return numerics::StrangSplitting<DirectSystem>(DirectSystem(body)); };
  auto exact = [&] {
    return numerics::Composition4<physics::ExactSplitSystem>(physics::ExactSplitSystem(body));
  };
  const long ns = steps_for(axis, target), n4 = steps_for(exact, target);
  if (ns < 0 || n4 < 0) {
    state.SkipWithError("target error not reached");
    return;
  }
  double t_axis = 0.0, t_exact = 0.0;
  using clock = std::chrono::steady_clock;
  for (auto _ : state) {
    const auto t0 = clock::now();
    benchmark::DoNotOptimize(run_steps(axis(), ns));
    const auto t1 = clock::now();
    benchmark::DoNotOptimize(run_steps(exact(), n4));
    const auto t2 = clock::now();
    t_axis += std::chrono::duration<double>(t1 - t0).count();
    t_exact += std::chrono::duration<double>(t2 - t1).count();
    state.SetIterationTime(std::chrono::duration<double>(t2 - t1).count());
  }
  state.counters["steps_splitting"] = double(ns);
  state.counters["steps_exact4"] = double(n4);
  state.counters["ratio"] = t_axis / t_exact;
}
BENCHMARK(work_precision_ratio)
    ->Name("wp/kovalevskaya/splitting-vs-exact-split4")
    ->Arg(6)
    ->Arg(8)
    ->Arg(10)
    ->UseManualTime()
    ->Unit(benchmark::kMillisecond);

}  // namespace
