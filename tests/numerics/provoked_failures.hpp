#pragma once
// The failures only the adaptive step control raises, each provoked on a tiny
// test system: step_underflow (y' = y^2 runs into its pole at t = 1),
// step_budget (ten steps allowed for a run that needs a hundred) and
// rejections (a first step far too long, two rejections allowed). Shared by
// the numerics tests and the tests of the command line's wording.
#include <gtest/gtest.h>

#include <string>
#include <utility>
#include <vector>

#include "numerics/embedded_rk.hpp"
#include "numerics/test_systems.hpp"

namespace epviz::numerics::testing {

// Runs f, which must throw IntegrationError whose message is its Failure's;
// returns that Failure.
template <class F>
Failure failure_thrown_by(F&& f) {
  try {
    f();
  } catch (const IntegrationError& e) {
    EXPECT_EQ(std::string(e.what()), e.failure().message());
    return e.failure();
  }
  ADD_FAILURE() << "no IntegrationError thrown";
  return {};
}

// A provoked failure and the stepper as it left it.
template <class Stepper>
struct Provoked {
  Stepper stepper;
  Failure failure;
};

// Steps `stepper`, started at (0, x0), until it has passed `t_end`.
template <class Stepper>
Provoked<Stepper> run_until_failure(Stepper stepper, double x0, double t_end) {
  Provoked<Stepper> p{std::move(stepper), {}};
  p.stepper.init(0.0, Vec<1>(x0));
  p.failure = failure_thrown_by([&] {
    while (p.stepper.t() < t_end) p.stepper.step();
  });
  return p;
}

// A failure provoked by fixed steps, the stepper and the state it left.
template <class Stepper>
struct Stepped {
  Stepper stepper;
  Vec<1> x;
  Failure failure;
};

// Steps x = x0 from t = 0 by `h`, `steps` times, where it must fail.
template <class Stepper>
Stepped<Stepper> step_until_failure(Stepper stepper, double x0, double h, int steps = 1) {
  Stepped<Stepper> p{std::move(stepper), Vec<1>(x0), {}};
  double t = 0.0;
  p.failure = failure_thrown_by([&] {
    for (int i = 0; i < steps; ++i, t += h) p.stepper.step(p.x, t, h);
  });
  return p;
}

template <template <class> class Method = Dop853>
Provoked<Method<BlowUp>> provoke_step_underflow() {
  AdaptiveOptions o;
  o.rtol = o.atol = 1e-8;
  return run_until_failure(Method<BlowUp>({}, o), 1.0, 2.0);
}

inline Provoked<Dopri5<Linear1>> provoke_step_budget() {
  AdaptiveOptions o;
  o.max_steps = 10;
  o.h_max = 0.01;
  return run_until_failure(Dopri5<Linear1>(Linear1{-1.0}, o), 1.0, 1.0);
}

inline Provoked<Dop853<Linear1>> provoke_rejections() {
  AdaptiveOptions o;
  o.max_consecutive_rejects = 2;
  o.h_init = 10.0;  // far too long for y' = y: the error test fails three times in a row
  return run_until_failure(Dop853<Linear1>(Linear1{1.0}, o), 1.0, 1.0);
}

inline std::vector<Failure> step_control_failures() {
  return {provoke_step_underflow().failure, provoke_step_budget().failure,
          provoke_rejections().failure};
}

}  // namespace epviz::numerics::testing
