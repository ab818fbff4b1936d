// Cost of one right-hand side evaluation and of one step of each method in each
// formulation, on the Kovalevskaya top (a bounded, smooth motion).
//
//   build/bench/epviz_bench --benchmark_filter=direct
#include <benchmark/benchmark.h>

#include "numerics/embedded_rk.hpp"
#include "numerics/gauss_legendre.hpp"
#include "numerics/rk4.hpp"
#include "numerics/splitting.hpp"
#include "physics/cases.hpp"
#include "physics/direct.hpp"
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

}  // namespace
