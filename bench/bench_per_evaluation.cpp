// Cost per right-hand-side evaluation of a whole adaptive integration, ours
// against Boost.Odeint's Dormand–Prince 5(4) on the same system, tolerance and
// interval (Kovalevskaya top, direct formulation, T = 100, tol 1e-10):
//
//   build/bench/epviz_bench --benchmark_filter=per_evaluation
//
// The counter ns/eval divides the time of the whole integration by its
// evaluations, so step control, error norms and stage sums count as overhead
// of the evaluation they surround; Odeint's controlled stepper checks the
// error in the max norm, ours in Hairer's RMS norm, so the two take slightly
// different numbers of steps for the same tolerance.
#include <benchmark/benchmark.h>

#include <array>
#include <boost/numeric/odeint.hpp>

#include "numerics/embedded_rk.hpp"
#include "physics/cases.hpp"
#include "physics/direct.hpp"

namespace {

using namespace epviz;
using physics::DirectSystem;

constexpr double kTol = 1e-10;
constexpr double kEnd = 100.0;

const physics::CasePreset& kovalevskaya() { return physics::preset(physics::Case::kovalevskaya); }

void report(benchmark::State& state, long evals_per_run) {
  state.counters["evals"] = double(evals_per_run);
  state.counters["ns/eval"] =
      benchmark::Counter(double(evals_per_run) * double(state.iterations()),
                         benchmark::Counter::kIsRate | benchmark::Counter::kInvert);
}

template <class Stepper>
void ours(benchmark::State& state) {
  const DirectSystem sys(kovalevskaya().body);
  numerics::AdaptiveOptions opts;
  opts.rtol = opts.atol = kTol;
  long evals = 0;
  for (auto _ : state) {
    Stepper stepper(sys, opts);
    stepper.init(0.0, sys.pack(kovalevskaya().initial));
    while (stepper.t() < kEnd) stepper.step();
    benchmark::DoNotOptimize(stepper.state());
    evals = stepper.stats().rhs_evals;
  }
  report(state, evals);
}

// Odeint's System concept, over the very same right-hand side (inlined).
struct OdeintDirect {
  DirectSystem sys;
  long* evals;
  void operator()(const std::array<double, 6>& x, std::array<double, 6>& dxdt, double t) const {
    const Eigen::Map<const DirectSystem::State> in(x.data());
    DirectSystem::State out;
    sys.rhs(t, in, out);
    Eigen::Map<DirectSystem::State>(dxdt.data()) = out;
    ++*evals;
  }
};

void odeint_dopri5(benchmark::State& state) {
  namespace odeint = boost::numeric::odeint;
  using OdeState = std::array<double, 6>;
  const DirectSystem sys(kovalevskaya().body);
  long evals = 0;
  for (auto _ : state) {
    evals = 0;
    OdeState x;
    const DirectSystem::State x0 = sys.pack(kovalevskaya().initial);
    std::copy(x0.data(), x0.data() + 6, x.begin());
    auto stepper = odeint::make_controlled(kTol, kTol, odeint::runge_kutta_dopri5<OdeState>());
    odeint::integrate_adaptive(stepper, OdeintDirect{sys, &evals}, x, 0.0, kEnd, 1e-3);
    benchmark::DoNotOptimize(x);
  }
  report(state, evals);
}

BENCHMARK(ours<numerics::Dopri5<DirectSystem>>)->Name("per_evaluation/epviz/dopri5");
BENCHMARK(ours<numerics::Dop853<DirectSystem>>)->Name("per_evaluation/epviz/dop853");
BENCHMARK(odeint_dopri5)->Name("per_evaluation/odeint/dopri5");

}  // namespace
