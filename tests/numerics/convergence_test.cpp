// Observed convergence orders from step-halving studies on problems with
// closed-form solutions: each method must show its theoretical order within
// 0.2 in the asymptotic regime (step ranges chosen above round-off).
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "numerics/embedded_rk.hpp"
#include "numerics/gauss_legendre.hpp"
#include "numerics/rk4.hpp"
#include "numerics/splitting.hpp"
#include "test_systems.hpp"

namespace epviz::numerics {
namespace {

using testing::DecayingRotation;
using testing::ExpSin;
using testing::Kepler;
using testing::observed_orders;
using testing::Oscillator;
using testing::TimeDependentRiccati;

// Max-norm error at t_end after n fixed steps from exact(0).
template <class Stepper, class Exact>
double fixed_step_error(Stepper stepper, Exact exact, double t_end, int n) {
  auto x = exact(0.0);
  const double h = t_end / n;
  for (int k = 0; k < n; ++k) stepper.step(x, k * h, h);
  return (x - exact(t_end)).cwiseAbs().maxCoeff();
}

template <class Stepper, class Exact>
void expect_order(const Stepper& proto, Exact exact, double t_end, int n0, int halvings,
                  const std::string& what) {
  std::vector<double> errors;
  for (int i = 0, n = n0; i <= halvings; ++i, n *= 2)
    errors.push_back(fixed_step_error(proto, exact, t_end, n));
  const auto p = observed_orders(errors);
  for (std::size_t i = 0; i < p.size(); ++i) {
    EXPECT_NEAR(p[i], Stepper::order, 0.2)
        << what << " " << Stepper::name << ": n = " << (n0 << i) << " -> " << (n0 << (i + 1))
        << ", errors " << errors[i] << " -> " << errors[i + 1];
  }
}

Kepler kepler() { return Kepler{0.5}; }
auto kepler_exact = [](double t) { return kepler().exact(t); };
auto riccati_exact = [](double t) { return TimeDependentRiccati::exact(t); };

TEST(Convergence, Rk4) {
  expect_order(Rk4<Kepler>(kepler()), kepler_exact, 2.0, 40, 3, "kepler");
  expect_order(Rk4<TimeDependentRiccati>({}), riccati_exact, 2.0, 10, 3, "riccati");
}

// The 5th-order error constant of dopri5 is small, so the asymptotic regime
// starts late: the ranges below were chosen where it has begun and round-off
// has not. (On Kepler, 640 steps leave an error of 3e-14 of which round-off
// is a fifth, enough to move the observed order by 0.2 with the order of the
// sums: the study stops at 480.)
TEST(Convergence, Dopri5FixedStep) {
  const Kepler k{0.2};
  expect_order(
      Dopri5<Kepler>(k), [&](double t) { return k.exact(t); }, 3.0, 60, 3, "kepler");
  expect_order(
      Dopri5<ExpSin>({}), [](double t) { return ExpSin::exact(t); }, 10.0, 200, 3, "exp(sin)");
}

// Order 8 leaves a narrow window between the pre-asymptotic regime and
// round-off: several problems, short studies each.
TEST(Convergence, Dop853FixedStep) {
  expect_order(
      Dop853<DecayingRotation>({}), [](double t) { return DecayingRotation::exact(t); }, 10.0, 20,
      3, "decaying rotation");
  const Kepler k5{0.5}, k7{0.7};
  expect_order(
      Dop853<Kepler>(k5), [&](double t) { return k5.exact(t); }, 3.0, 24, 1, "kepler e=.5");
  expect_order(
      Dop853<Kepler>(k7), [&](double t) { return k7.exact(t); }, 1.0, 24, 1, "kepler e=.7");
}

TEST(Convergence, ImplicitMidpoint) {
  expect_order(ImplicitMidpoint<Kepler>(kepler()), kepler_exact, 2.0, 100, 3, "kepler");
  expect_order(ImplicitMidpoint<TimeDependentRiccati>({}), riccati_exact, 2.0, 20, 3, "riccati");
}

TEST(Convergence, Gauss4) {
  expect_order(Gauss4<Kepler>(kepler()), kepler_exact, 2.0, 20, 3, "kepler");
  expect_order(Gauss4<TimeDependentRiccati>({}), riccati_exact, 2.0, 10, 3, "riccati");
}

TEST(Convergence, Gauss6) {
  expect_order(Gauss6<Kepler>(kepler()), kepler_exact, 2.0, 10, 3, "kepler");
  expect_order(Gauss6<TimeDependentRiccati>({}), riccati_exact, 2.0, 5, 3, "riccati");
}

TEST(Convergence, StrangSplitting) {
  expect_order(StrangSplitting<Kepler>(kepler()), kepler_exact, 2.0, 100, 3, "kepler");
  Oscillator osc{1.3};
  expect_order(
      StrangSplitting<Oscillator>(osc), [&](double t) { return osc.exact(t); }, 3.0, 20, 3,
      "oscillator");
}

}  // namespace
}  // namespace epviz::numerics
