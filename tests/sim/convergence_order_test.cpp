// Observed order of every method on the Euler-Poisson equations: a step-halving
// study on a smooth case against a reference from a different method (Gauss6
// with a tiny step, itself checked against DOP853 at tol 1e-14).
#include <gtest/gtest.h>

#include <cmath>

#include "numerics/embedded_rk.hpp"
#include "numerics/gauss_legendre.hpp"
#include "numerics/rk4.hpp"
#include "numerics/splitting.hpp"
#include "physics/cases.hpp"
#include "physics/direct.hpp"
#include "physics/riccati.hpp"
#include "physics/spinor.hpp"
#include "sim/simulate.hpp"
#include "sim/steppers.hpp"

namespace epviz {
namespace {

constexpr double kT = 2.0;
const physics::CasePreset& smooth_case() { return physics::preset(physics::Case::generic); }

using Vec6 = Eigen::Matrix<double, 6, 1>;

template <class Stepper>
Vec6 fixed_step_final(Stepper s, long n) {
  auto x = s.system().pack(smooth_case().initial);
  const double h = kT / double(n);
  for (long i = 0; i < n; ++i) s.step(x, double(i) * h, h);
  Vec6 out;
  out << s.system().omega(x), s.system().gamma(x);
  return out;
}

const Vec6& reference() {
  static const Vec6 ref = [] {
    return fixed_step_final(
        numerics::Gauss6<physics::DirectSystem>(physics::DirectSystem(smooth_case().body)), 2000);
  }();
  return ref;
}

TEST(Reference, AgreesWithDop853AtTightTolerance) {
  numerics::AdaptiveOptions o;
  o.rtol = o.atol = 1e-14;
  numerics::Dop853<physics::DirectSystem> s(physics::DirectSystem(smooth_case().body), o);
  s.init(0.0, s.system().pack(smooth_case().initial));
  while (s.t() < kT) s.step();
  const auto x = s.dense(kT);
  Vec6 v;
  v << s.system().omega(x), s.system().gamma(x);
  EXPECT_LT((v - reference()).norm(), 1e-12);
}

// Order from errors at steps kT/n and kT/(2n).
template <class Make>
double observed_order(Make make, long n) {
  const double e1 = (fixed_step_final(make(), n) - reference()).norm();
  const double e2 = (fixed_step_final(make(), 2 * n) - reference()).norm();
  EXPECT_GT(e2, 1e-13) << "step too small: round-off dominates";
  return std::log2(e1 / e2);
}

template <template <class> class Stepper, class Sys>
auto maker() {
  return [] { return Stepper<Sys>(Sys(smooth_case().body)); };
}

template <template <class> class Stepper, class Sys>
auto adaptive_maker() {
  return [] { return Stepper<Sys>(Sys(smooth_case().body), numerics::AdaptiveOptions{}); };
}

using physics::DirectSystem;
using physics::RiccatiSystem;
using physics::SpinorSystem;

TEST(ConvergenceOrder, Rk4) {
  EXPECT_NEAR(observed_order(maker<numerics::Rk4, DirectSystem>(), 40), 4.0, 0.2);
  EXPECT_NEAR(observed_order(maker<numerics::Rk4, RiccatiSystem>(), 40), 4.0, 0.2);
  EXPECT_NEAR(observed_order(maker<numerics::Rk4, SpinorSystem>(), 40), 4.0, 0.2);
}
TEST(ConvergenceOrder, Dopri5FixedStep) {
  EXPECT_NEAR(observed_order(adaptive_maker<numerics::Dopri5, DirectSystem>(), 20), 5.0, 0.2);
}
TEST(ConvergenceOrder, Dop853FixedStep) {
  EXPECT_NEAR(observed_order(adaptive_maker<numerics::Dop853, DirectSystem>(), 8), 8.0, 0.2);
}
TEST(ConvergenceOrder, ImplicitMidpoint) {
  EXPECT_NEAR(observed_order(maker<numerics::ImplicitMidpoint, DirectSystem>(), 100), 2.0, 0.2);
}
TEST(ConvergenceOrder, Gauss4) {
  EXPECT_NEAR(observed_order(maker<numerics::Gauss4, DirectSystem>(), 20), 4.0, 0.2);
  EXPECT_NEAR(observed_order(maker<numerics::Gauss4, SpinorSystem>(), 20), 4.0, 0.2);
}
TEST(ConvergenceOrder, Gauss6) {
  EXPECT_NEAR(observed_order(maker<numerics::Gauss6, DirectSystem>(), 10), 6.0, 0.2);
}
TEST(ConvergenceOrder, Splitting) {
  EXPECT_NEAR(observed_order(maker<numerics::StrangSplitting, DirectSystem>(), 100), 2.0, 0.2);
}

}  // namespace
}  // namespace epviz
