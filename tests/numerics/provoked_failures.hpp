#pragma once
// The failures only the adaptive step control raises, each provoked on a tiny
// test system: step_underflow (y' = y^2 runs into its pole at t = 1),
// step_budget (ten steps allowed for a run that needs a hundred) and
// rejections (a first step far too long, two rejections allowed). Shared by
// the numerics tests and the tests of the command line's wording.
#include <gtest/gtest.h>

#include <vector>

#include "numerics/embedded_rk.hpp"
#include "numerics/test_systems.hpp"

namespace epviz::numerics::testing {

// Runs f, which must throw IntegrationError; returns its Failure.
template <class F>
Failure failure_thrown_by(F&& f) {
  try {
    f();
  } catch (const IntegrationError& e) {
    return e.failure();
  }
  ADD_FAILURE() << "no IntegrationError thrown";
  return {};
}

inline std::vector<Failure> step_control_failures() {
  std::vector<Failure> all;
  {
    AdaptiveOptions o;
    o.rtol = o.atol = 1e-8;
    Dop853<BlowUp> s({}, o);
    s.init(0.0, Vec<1>(1.0));
    all.push_back(failure_thrown_by([&] {
      while (s.t() < 2.0) s.step();
    }));
  }
  {
    AdaptiveOptions o;
    o.max_steps = 10;
    o.h_max = 0.01;
    Dopri5<Linear1> s(Linear1{-1.0}, o);
    s.init(0.0, Vec<1>(1.0));
    all.push_back(failure_thrown_by([&] {
      while (s.t() < 1.0) s.step();
    }));
  }
  {
    AdaptiveOptions o;
    o.max_consecutive_rejects = 2;
    o.h_init = 10.0;
    Dop853<Linear1> s(Linear1{1.0}, o);
    s.init(0.0, Vec<1>(1.0));
    all.push_back(failure_thrown_by([&] { s.step(); }));
  }
  return all;
}

}  // namespace epviz::numerics::testing
