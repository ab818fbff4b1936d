#pragma once
// The classical fourth-order Runge–Kutta method, fixed step.
#include "numerics/stepper_common.hpp"

namespace epviz::numerics {

template <OdeSystem Sys>
class Rk4 : public StepperCore<Sys> {
  using StepperCore<Sys>::sys_;
  using StepperCore<Sys>::stats_;

 public:
  using System = Sys;
  using State = typename Sys::State;
  static constexpr const char* name = "rk4";
  static constexpr int order = 4;

  explicit Rk4(Sys sys) : StepperCore<Sys>(std::move(sys)) {}

  // Advances x from t to t + h. Throws IntegrationError on a non-finite
  // result or when the system's check() objects; x is then left unchanged
  // (apart from a regularize() remapping at the start of the step).
  inline void step(State& x, double t, double h) {
    detail::regularize(sys_, x);
    const double h2 = 0.5 * h;
    sys_.rhs(t, x, k1_);
    tmp_ = x + h2 * k1_;
    sys_.rhs(t + h2, tmp_, k2_);
    tmp_ = x + h2 * k2_;
    sys_.rhs(t + h2, tmp_, k3_);
    tmp_ = x + h * k3_;
    sys_.rhs(t + h, tmp_, k4_);
    tmp_ = x + (h / 6.0) * (k1_ + 2.0 * (k2_ + k3_) + k4_);
    stats_.rhs_evals += 4;
    this->accept(x, tmp_, t + h, name);
  }

 private:
  State k1_ = State::Zero(), k2_ = State::Zero(), k3_ = State::Zero(), k4_ = State::Zero();
  State tmp_ = State::Zero();
};

}  // namespace epviz::numerics
