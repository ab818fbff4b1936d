#pragma once
// Inside sim/: the two ways a stepper becomes a Trajectory (fixed steps that
// land on the output times, or adaptive steps with dense output). Each formulation instantiates these in its
// own file (see trajectory_start.hpp).
#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <type_traits>
#include <utility>

#include "sim/steppers.hpp"
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

// The direct formulation's state (Omega, gamma) of a state of `sys`.
template <class Sys>
DenseStep::State direct_state(const Sys& sys, const typename Sys::State& x) {
  DenseStep::State d;
  d << sys.omega(x), sys.gamma(x);
  return d;
}

// A step shown to a dense step observer: its dense output is `at`'s.
template <class At>
class DenseStepOf final : public DenseStep {
 public:
  explicit DenseStepOf(const At& at) : at_(at) {}
  State at(double t) const override { return at_(t); }

 private:
  const At& at_;
};

template <class Sys>
long chart_switches_of(const Sys& sys) {
  if constexpr (requires { sys.chart_switches(); })
    return sys.chart_switches();
  else
    return 0;
}

// Fixed-step methods: steps of exactly spec.step from t = 0, whatever the
// output spacing. An output time on a step (within rounding) gets that step's
// state; one between two steps gets the cubic Hermite interpolant of the
// states and derivatives at both ends (error O(h^4) per step, the order of
// rk4 and gauss4: the drawn curve is as good as the steps, never better).
template <class Stepper>
class FixedStepTrajectory final : public Trajectory {
  using Sys = std::decay_t<decltype(std::declval<Stepper&>().system())>;
  using State = typename Sys::State;
  static constexpr bool kHasCharts = requires(const Sys& s) { s.chart_switches(); };
  // An output time this close to a step, in units of the step, is on it.
  static constexpr double kOnStep = 1e-9;

 public:
  FixedStepTrajectory(Stepper stepper, const RunSpec& spec)
      : Trajectory(spec.t_end / spec.samples), stepper_(std::move(stepper)), h_(spec.step) {
    x1_ = stepper_.system().pack(spec.initial);
  }
  Sample initial() const override { return make_sample(stepper_.system(), 0.0, x1_); }
  Sample next() override {
    const double t = double(++k_) * spacing_;
    while (t1() < t - kOnStep * h_) advance();
    const auto& sys = stepper_.system();
    if (t >= t1() - kOnStep * h_) return make_sample(sys, t, x1_);
    return make_sample(sys, t, hermite(t));
  }
  numerics::Stats stats() const override { return stepper_.stats(); }
  long chart_switches() const override { return chart_switches_of(stepper_.system()); }
  double effective_step() const override { return h_; }
  long interpolation_evals() const override { return interpolation_evals_; }
  void observe_dense_steps(DenseStepObserver observer) override {
    dense_observer_ = std::move(observer);
    x_shown_ = direct_state(stepper_.system(), x1_);
  }

 private:
  double t1() const { return double(n_) * h_; }

  // The step just taken, with the interpolant the samples use (its
  // derivatives evaluated only if the observer asks within the step).
  void show_step() {
    DenseStep::State x1 = direct_state(stepper_.system(), x1_);
    const auto at = [this](double t) { return direct_state(stepper_.system(), hermite(t)); };
    DenseStepOf step(at);
    step.t0 = t1() - h_;
    step.t1 = t1();
    step.x0 = x_shown_;
    step.x1 = x1;
    dense_observer_(step);
    x_shown_ = x1;
  }

  void advance() {
    const double t0 = t1();
    x0_ = x1_;
    // The derivative at the old step end serves as the next start's, unless
    // the step remaps the state (below).
    d0_ = d1_;
    have_d0_ = have_d1_;
    have_d1_ = false;
    if constexpr (kHasCharts) {
      // A chart switch at the start of the step remaps the state; the
      // interpolant needs both ends in the chart the step ran in, so the start
      // is remapped the same way (by a copy of the system before the step).
      Sys before = stepper_.system();
      stepper_.step(x1_, t0, h_);
      if (stepper_.system().chart_switches() != before.chart_switches()) {
        numerics::detail::regularize(before, x0_);
        have_d0_ = false;
      }
    } else {
      stepper_.step(x1_, t0, h_);
    }
    ++n_;
    if (observing_steps()) notify_step(make_sample(stepper_.system(), t1(), x1_));
    if (dense_observer_) show_step();
  }

  State hermite(double t) {
    const auto& sys = stepper_.system();
    const double t0 = t1() - h_;
    if (!have_d0_) {
      sys.rhs(t0, x0_, d0_);
      ++interpolation_evals_;
      have_d0_ = true;
    }
    if (!have_d1_) {
      sys.rhs(t1(), x1_, d1_);
      ++interpolation_evals_;
      have_d1_ = true;
    }
    const double s = (t - t0) / h_, r = 1.0 - s;
    const double h00 = (1.0 + 2.0 * s) * r * r, h10 = s * r * r;
    const double h01 = s * s * (3.0 - 2.0 * s), h11 = -s * s * r;
    return State(h00 * x0_ + (h10 * h_) * d0_ + h01 * x1_ + (h11 * h_) * d1_);
  }

  Stepper stepper_;
  double h_;
  State x0_, x1_, d0_, d1_;
  bool have_d0_ = false, have_d1_ = false;
  long n_ = 0;  // steps taken: x1_ is the state at n_ * h_
  long k_ = 0;  // output times handed out
  long interpolation_evals_ = 0;
  DenseStepObserver dense_observer_;
  DenseStep::State x_shown_;  // the direct state at the end of the last step shown
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
    while (stepper_.t() < t) {
      const double t0 = stepper_.t();
      stepper_.step();
      if (observing_steps())
        notify_step(make_sample(stepper_.system(), stepper_.t(), stepper_.state()));
      if (dense_observer_) show_step(t0);
    }
    // The system's chart is the one the last step ran in, so the dense state
    // and the chart agree.
    return make_sample(stepper_.system(), t, stepper_.dense(t));
  }
  numerics::Stats stats() const override { return stepper_.stats(); }
  long chart_switches() const override { return chart_switches_of(stepper_.system()); }
  double effective_step() const override { return 0.0; }
  void observe_dense_steps(DenseStepObserver observer) override {
    dense_observer_ = std::move(observer);
    x_shown_ = direct_state(stepper_.system(), stepper_.state());
  }

 private:
  // The step just taken from t0, with the stepper's dense output (in the
  // chart the step ran in, as for the samples).
  void show_step(double t0) {
    const auto& sys = stepper_.system();
    DenseStep::State x1 = direct_state(sys, stepper_.state());
    const auto at = [this](double t) { return direct_state(stepper_.system(), stepper_.dense(t)); };
    DenseStepOf step(at);
    step.t0 = t0;
    step.t1 = stepper_.t();
    step.x0 = x_shown_;
    step.x1 = x1;
    dense_observer_(step);
    x_shown_ = x1;
  }

  Stepper stepper_;
  long k_ = 0;
  DenseStepObserver dense_observer_;
  DenseStep::State x_shown_;  // the direct state at the end of the last step shown
};

template <class Stepper>
std::unique_ptr<Trajectory> fixed(Stepper s, const RunSpec& spec) {
  return std::make_unique<FixedStepTrajectory<Stepper>>(std::move(s), spec);
}
template <class Stepper>
std::unique_ptr<Trajectory> adaptive(Stepper s, const RunSpec& spec) {
  return std::make_unique<AdaptiveTrajectory<Stepper>>(std::move(s), spec);
}

// The trajectory of spec.method for `sys` (sim/steppers.hpp builds the stepper).
template <class Sys>
std::unique_ptr<Trajectory> start_with(Sys sys, const RunSpec& spec) {
  return with_stepper(std::move(sys), spec, [&spec](auto stepper) -> std::unique_ptr<Trajectory> {
    if constexpr (AdaptiveStepper<decltype(stepper)>)
      return adaptive(std::move(stepper), spec);
    else
      return fixed(std::move(stepper), spec);
  });
}

}  // namespace epviz::sim::detail
