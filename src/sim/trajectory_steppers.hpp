#pragma once
// Inside sim/: the two ways a stepper becomes a Trajectory (fixed steps that
// land on the output times, or adaptive steps with dense output), and the
// choice of stepper for one system. Each formulation instantiates these in its
// own file (see trajectory_start.hpp).
#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "numerics/embedded_rk.hpp"
#include "numerics/gauss_legendre.hpp"
#include "numerics/rk4.hpp"
#include "numerics/splitting.hpp"
#include "sim/trajectory.hpp"
#include "sim/trajectory_start.hpp"

namespace epviz::sim::detail {

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

// Fixed-step methods: `substeps` equal steps per output interval, so that the
// steps land on the output times.
template <class Stepper>
class FixedStepTrajectory final : public Trajectory {
 public:
  FixedStepTrajectory(Stepper stepper, const RunSpec& spec)
      : Trajectory(spec.t_end / spec.samples), stepper_(std::move(stepper)) {
    substeps_ = std::max(1L, long(std::ceil(spacing_ / spec.step * (1.0 - 1e-12))));
    h_ = spacing_ / double(substeps_);
    x_ = stepper_.system().pack(spec.initial);
  }
  Sample initial() const override { return make_sample(stepper_.system(), 0.0, x_); }
  Sample next() override {
    const double t0 = double(k_) * spacing_;
    for (long j = 0; j < substeps_; ++j) stepper_.step(x_, t0 + double(j) * h_, h_);
    ++k_;
    return make_sample(stepper_.system(), double(k_) * spacing_, x_);
  }
  numerics::Stats stats() const override { return stepper_.stats(); }
  long chart_switches() const override { return chart_switches_of(stepper_.system()); }
  double effective_step() const override { return h_; }

 private:
  Stepper stepper_;
  typename std::decay_t<decltype(std::declval<Stepper&>().system())>::State x_;
  long substeps_ = 1;
  double h_ = 0.0;
  long k_ = 0;
};

// Adaptive methods: steps as the error control wants; output by dense output.
template <class Stepper>
class AdaptiveTrajectory final : public Trajectory {
 public:
  AdaptiveTrajectory(Stepper stepper, const RunSpec& spec)
      : Trajectory(spec.t_end / spec.samples), stepper_(std::move(stepper)) {
    stepper_.init(0.0, stepper_.system().pack(spec.initial));
  }
  Sample initial() const override { return make_sample(stepper_.system(), 0.0, stepper_.state()); }
  Sample next() override {
    const double t = double(++k_) * spacing_;
    while (stepper_.t() < t) stepper_.step();
    // The system's chart is the one the last step ran in, so the dense state
    // and the chart agree.
    return make_sample(stepper_.system(), t, stepper_.dense(t));
  }
  numerics::Stats stats() const override { return stepper_.stats(); }
  long chart_switches() const override { return chart_switches_of(stepper_.system()); }
  double effective_step() const override { return 0.0; }

 private:
  Stepper stepper_;
  long k_ = 0;
};

template <class Stepper>
std::unique_ptr<Trajectory> fixed(Stepper s, const RunSpec& spec) {
  return std::make_unique<FixedStepTrajectory<Stepper>>(std::move(s), spec);
}
template <class Stepper>
std::unique_ptr<Trajectory> adaptive(Stepper s, const RunSpec& spec) {
  return std::make_unique<AdaptiveTrajectory<Stepper>>(std::move(s), spec);
}

// The methods that integrate `sys` itself. The exact splittings integrate a
// differently split system and are started by start_direct.
template <class Sys>
std::unique_ptr<Trajectory> start_with(Sys sys, const RunSpec& spec) {
  numerics::AdaptiveOptions opts;
  opts.rtol = spec.tol;
  opts.atol = spec.tol;
  opts.max_steps = spec.max_steps;
  switch (spec.method) {
    case Method::rk4: return fixed(numerics::Rk4<Sys>(sys), spec);
    case Method::dopri5: return adaptive(numerics::Dopri5<Sys>(sys, opts), spec);
    case Method::dop853: return adaptive(numerics::Dop853<Sys>(sys, opts), spec);
    case Method::midpoint: return fixed(numerics::ImplicitMidpoint<Sys>(sys), spec);
    case Method::gauss4: return fixed(numerics::Gauss4<Sys>(sys), spec);
    case Method::gauss6: return fixed(numerics::Gauss6<Sys>(sys), spec);
    case Method::splitting:
      if constexpr (requires { Sys::n_flows; })
        return fixed(numerics::StrangSplitting<Sys>(sys), spec);
      break;
    case Method::exact_split2:
    case Method::exact_split4: break;
  }
  throw std::invalid_argument(*incompatibility(spec.method, spec.formulation));
}

}  // namespace epviz::sim::detail
