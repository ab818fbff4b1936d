// Numerical failures of real runs arrive as data: the kind of trouble and a
// plain fact, with no advice naming a command-line option or a panel control
// (the front ends word that for their users).
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "run_helpers.hpp"

namespace epviz {
namespace {

using numerics::FailureKind;

// A steady rotation about axis 1 carries gamma exactly through the south pole,
// where the Riccati coordinates of the north chart have a true pole.
sim::RunSpec through_south_pole(sim::Method m) {
  auto spec = sim::preset_run(physics::Case::euler, m, sim::Formulation::riccati, 6.0, 60);
  spec.initial.omega = {1.0, 0.0, 0.0};
  spec.initial.gamma = {0.0, 0.6, 0.8};
  spec.chart_switch = false;
  return spec;
}

void expect_fact_only(const numerics::Failure& f) {
  EXPECT_FALSE(f.detail.empty());
  EXPECT_EQ(f.detail.find("--"), std::string::npos) << f.detail;
  EXPECT_EQ(f.message().find("--"), std::string::npos) << f.message();
}

TEST(FailureKinds, RiccatiPoleIsAChartPole) {
  for (sim::Method m : {sim::Method::dop853, sim::Method::rk4}) {
    auto spec = through_south_pole(m);
    spec.step = 1e-3;
    const auto r = sim::simulate(spec);
    ASSERT_TRUE(r.failure.has_value()) << sim::name(m);
    EXPECT_EQ(r.failure->kind, FailureKind::chart_pole) << r.failure->message();
    EXPECT_EQ(r.failure->method, sim::name(m));
    // gamma3 = cos(t + atan2(0.6, 0.8)) reaches -1 at t = pi - atan2(0.6, 0.8).
    EXPECT_NEAR(r.failure->t, M_PI - std::atan2(0.6, 0.8), 0.05) << r.failure->message();
    expect_fact_only(*r.failure);
  }
}

TEST(FailureKinds, ImplicitStepTooLargeIsSolverDivergence) {
  // A fast top with a step longer than its period: the fixed-point iteration
  // of the stage equations cannot contract.
  auto spec = sim::preset_run(physics::Case::lagrange, sim::Method::gauss4,
                              sim::Formulation::direct, 20.0, 2);
  spec.initial.omega = {0.0, 0.0, 50.0};
  spec.step = 5.0;
  const auto r = sim::simulate(spec);
  ASSERT_TRUE(r.failure.has_value());
  EXPECT_EQ(r.failure->kind, FailureKind::solver_divergence) << r.failure->message();
  EXPECT_EQ(r.failure->t, 0.0);  // the first step already fails
  expect_fact_only(*r.failure);
}

}  // namespace
}  // namespace epviz
