#include "sim/simulate.hpp"

#include <cmath>
#include <ctime>
#include <stdexcept>

#include "numerics/embedded_rk.hpp"
#include "numerics/gauss_legendre.hpp"
#include "numerics/rk4.hpp"
#include "numerics/splitting.hpp"
#include "physics/direct.hpp"
#include "physics/riccati.hpp"
#include "physics/spinor.hpp"

namespace epviz::sim {
namespace {

double cpu_now() {
  timespec ts{};
  clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &ts);
  return double(ts.tv_sec) + 1e-9 * double(ts.tv_nsec);
}

// Measures only the integration: sampling into a preallocated vector is part of
// it, everything else (I/O, invariants) happens after.
class CpuTimer {
 public:
  CpuTimer() : start_(cpu_now()) {}
  double seconds() const { return cpu_now() - start_; }

 private:
  double start_;
};

template <class Sys>
Sample make_sample(const Sys& sys, double t, const typename Sys::State& x) {
  Sample s;
  s.t = t;
  s.omega = sys.omega(x);
  s.gamma = sys.gamma(x);
  if constexpr (requires { sys.attitude(x); }) s.attitude = sys.attitude(x);
  return s;
}

template <class Sys>
long chart_switches_of(const Sys& sys) {
  if constexpr (requires { sys.chart_switches(); })
    return sys.chart_switches();
  else
    return 0;
}

template <class Stepper>
RunResult run_fixed(Stepper stepper, const RunSpec& spec) {
  RunResult r;
  const auto times = output_times(spec.t_end, spec.samples);
  const double spacing = spec.t_end / spec.samples;
  const long substeps = std::max(1L, long(std::ceil(spacing / spec.step * (1.0 - 1e-12))));
  const double h = spacing / double(substeps);
  r.effective_step = h;
  r.samples.reserve(times.size());

  auto x = stepper.system().pack(spec.initial);
  CpuTimer timer;
  r.samples.push_back(make_sample(stepper.system(), 0.0, x));
  try {
    for (std::size_t k = 1; k < times.size(); ++k) {
      const double t0 = times[k - 1];
      for (long j = 0; j < substeps; ++j) stepper.step(x, t0 + double(j) * h, h);
      r.samples.push_back(make_sample(stepper.system(), times[k], x));
    }
  } catch (const numerics::IntegrationError& e) {
    r.failure = e.failure();
  }
  r.cpu_seconds = timer.seconds();
  r.stats = stepper.stats();
  r.chart_switches = chart_switches_of(stepper.system());
  return r;
}

template <class Stepper>
RunResult run_adaptive(Stepper stepper, const RunSpec& spec) {
  RunResult r;
  const auto times = output_times(spec.t_end, spec.samples);
  r.samples.reserve(times.size());

  CpuTimer timer;
  stepper.init(0.0, stepper.system().pack(spec.initial));
  r.samples.push_back(make_sample(stepper.system(), 0.0, stepper.state()));
  try {
    for (std::size_t k = 1; k < times.size(); ++k) {
      while (stepper.t() < times[k]) stepper.step();
      // The system's chart is the one the last step ran in, so the dense
      // state and the chart agree.
      r.samples.push_back(make_sample(stepper.system(), times[k], stepper.dense(times[k])));
    }
  } catch (const numerics::IntegrationError& e) {
    r.failure = e.failure();
  }
  r.cpu_seconds = timer.seconds();
  r.stats = stepper.stats();
  r.chart_switches = chart_switches_of(stepper.system());
  return r;
}

template <class Sys>
RunResult run_with(Sys sys, const RunSpec& spec) {
  numerics::AdaptiveOptions opts;
  opts.rtol = spec.tol;
  opts.atol = spec.tol;
  switch (spec.method) {
    case Method::rk4: return run_fixed(numerics::Rk4<Sys>(sys), spec);
    case Method::dopri5: return run_adaptive(numerics::Dopri5<Sys>(sys, opts), spec);
    case Method::dop853: return run_adaptive(numerics::Dop853<Sys>(sys, opts), spec);
    case Method::midpoint: return run_fixed(numerics::ImplicitMidpoint<Sys>(sys), spec);
    case Method::gauss4: return run_fixed(numerics::Gauss4<Sys>(sys), spec);
    case Method::gauss6: return run_fixed(numerics::Gauss6<Sys>(sys), spec);
    case Method::splitting:
      if constexpr (requires { Sys::n_flows; })
        return run_fixed(numerics::StrangSplitting<Sys>(sys), spec);
      break;
  }
  throw std::invalid_argument(*incompatibility(spec.method, spec.formulation));
}

}  // namespace

std::vector<double> output_times(double t_end, int samples) {
  std::vector<double> t(std::size_t(samples) + 1);
  for (int k = 0; k <= samples; ++k) t[std::size_t(k)] = t_end * double(k) / double(samples);
  return t;
}

RunResult simulate(const RunSpec& spec) {
  if (auto why = incompatibility(spec.method, spec.formulation)) throw std::invalid_argument(*why);
  if (!(spec.t_end > 0.0) || spec.samples < 1)
    throw std::invalid_argument("t_end must be positive and samples at least 1");
  switch (spec.formulation) {
    case Formulation::direct: return run_with(physics::DirectSystem(spec.body), spec);
    case Formulation::riccati:
      return run_with(physics::RiccatiSystem(spec.body, spec.chart_switch), spec);
    case Formulation::spinor: return run_with(physics::SpinorSystem(spec.body), spec);
  }
  throw std::invalid_argument("unknown formulation");
}

}  // namespace epviz::sim
