// The splitting "gravity kick + exact free rigid body flow" (exact-split2: Strang,
// exact-split4: Suzuki's 4th-order composition): order, long-run invariants and
// work against the axis-by-axis Lie-Poisson splitting ("splitting").
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <map>

#include "numerics/composition.hpp"
#include "numerics/gauss_legendre.hpp"
#include "physics/cases.hpp"
#include "physics/direct.hpp"
#include "physics/free_rigid_body_flow.hpp"
#include "run_helpers.hpp"
#include "sim/drift.hpp"

namespace epviz {
namespace {

using Vec6 = Eigen::Matrix<double, 6, 1>;
using physics::ExactSplitSystem;

Vec6 final_state(const sim::RunResult& r) {
  EXPECT_FALSE(r.failure) << r.failure->message();
  Vec6 v;
  v << r.samples.back().omega, r.samples.back().gamma;
  return v;
}

// Final state of a run with n fixed steps (or DOP853 at tol when method is adaptive).
Vec6 run_final(physics::Case c, sim::Method m, double t_end, long n, double tol = 1e-10) {
  auto spec = sim::preset_run(c, m, sim::Formulation::direct, t_end, 1);
  spec.step = t_end / double(n);
  spec.tol = tol;
  const auto r = sim::simulate(spec);
  if (!sim::is_adaptive(m)) {
    EXPECT_EQ(r.stats.steps, n);
  }
  return final_state(r);
}

// Reference by a different method: DOP853 at tol 1e-14 (checked against Gauss6 below).
const Vec6& reference(physics::Case c, double t_end) {
  static std::map<std::pair<int, double>, Vec6> cache;
  auto key = std::make_pair(int(c), t_end);
  auto it = cache.find(key);
  if (it == cache.end())
    it = cache.emplace(key, run_final(c, sim::Method::dop853, t_end, 1, 1e-14)).first;
  return it->second;
}

double error(physics::Case c, sim::Method m, double t_end, long n) {
  return (run_final(c, m, t_end, n) - reference(c, t_end)).norm();
}

TEST(ExactSplit, ReferenceAgreesWithGauss6) {
  const Vec6 g6 = run_final(physics::Case::generic, sim::Method::gauss6, 2.0, 2000);
  EXPECT_LT((g6 - reference(physics::Case::generic, 2.0)).norm(), 1e-12);
}

double observed_order(sim::Method m, long n) {
  const double e1 = error(physics::Case::generic, m, 2.0, n);
  const double e2 = error(physics::Case::generic, m, 2.0, 2 * n);
  EXPECT_GT(e2, 1e-13) << "step too small: round-off dominates";
  return std::log2(e1 / e2);
}

TEST(ExactSplit, ObservedOrderTwo) {
  EXPECT_NEAR(observed_order(sim::Method::exact_split2, 100), 2.0, 0.2);
}
TEST(ExactSplit, ObservedOrderFour) {
  EXPECT_NEAR(observed_order(sim::Method::exact_split4, 20), 4.0, 0.2);
}

// 1e5 steps of h = 0.01 on the Kovalevskaya top, sampled 1000 times.
void expect_long_run_invariants(sim::Method m) {
  auto spec =
      sim::preset_run(physics::Case::kovalevskaya, m, sim::Formulation::direct, 1000.0, 1000);
  spec.step = 0.01;
  const auto r = sim::simulate(spec);
  ASSERT_FALSE(r.failure) << r.failure->message();
  EXPECT_EQ(r.stats.steps, 100000);
  const sim::InvariantMonitor mon(spec.body, spec.case_id, spec.initial);
  const auto d = mon.max_relative_drift(r.samples);
  EXPECT_LT(d.gamma_norm2, 1e-12);
  EXPECT_LT(d.area, 1e-12);
  // Energy error bounded without drift: the worst in the last tenth is no
  // larger than twice that of the first tenth.
  double first = 0.0, last = 0.0;
  const std::size_t n = r.samples.size();
  for (std::size_t i = 0; i < n / 10; ++i)
    first = std::max(first, mon.relative_drift(mon.at(r.samples[i])).energy);
  for (std::size_t i = n - n / 10; i < n; ++i)
    last = std::max(last, mon.relative_drift(mon.at(r.samples[i])).energy);
  EXPECT_GT(first, 0.0);
  EXPECT_LT(last, 2.0 * first);
  EXPECT_LT(d.energy, 1e-3);
  std::printf(
      "%s: max drift |gamma|^2 %.2e  C0 %.2e  C1 %.2e (first tenth %.2e, last tenth %.2e)\n",
      std::string(sim::name(m)).c_str(), d.gamma_norm2, d.area, d.energy, first, last);
}

TEST(ExactSplit, Split2KeepsCasimirsToRoundOffAndEnergyBounded) {
  expect_long_run_invariants(sim::Method::exact_split2);
}
TEST(ExactSplit, Split4KeepsCasimirsToRoundOffAndEnergyBounded) {
  expect_long_run_invariants(sim::Method::exact_split4);
}

// Smallest step count in a geometric sweep with final-time error <= target.
long steps_for(sim::Method m, physics::Case c, double t_end, double target) {
  for (long n = 16; n <= (1L << 22); n = long(std::ceil(double(n) * 1.25)))
    if (error(c, m, t_end, n) <= target) return n;
  return -1;
}

TEST(ExactSplit, Split4NeedsFewerStepsThanAxisSplittingOnKovalevskaya) {
  const double t_end = 10.0;
  for (double target : {1e-6, 1e-9}) {
    const long ns = steps_for(sim::Method::splitting, physics::Case::kovalevskaya, t_end, target);
    const long n2 =
        steps_for(sim::Method::exact_split2, physics::Case::kovalevskaya, t_end, target);
    const long n4 =
        steps_for(sim::Method::exact_split4, physics::Case::kovalevskaya, t_end, target);
    std::printf(
        "error %.0e at t = %.0f: steps splitting %ld, exact-split2 %ld, exact-split4 %ld "
        "(ratio splitting/exact-split4 %.1f)\n",
        target, t_end, ns, n2, n4, double(ns) / double(n4));
    ASSERT_GT(ns, 0);
    ASSERT_GT(n4, 0);
    EXPECT_LT(n4, ns);
    EXPECT_LT(n2, ns);  // Strang over the exact free flow has the smaller error constant too
  }
}

// Why Composition4 uses Suzuki's 5-stage scheme: at equal work (5 Strang steps
// of h against 3 of 3h/5) it is more accurate than Yoshida's triple jump.
template <class Stepper>
Vec6 composition_final(Stepper s, double t_end, long n) {
  const auto& p = physics::preset(physics::Case::generic);
  auto x = s.system().pack(p.initial);
  const double h = t_end / double(n);
  for (long i = 0; i < n; ++i) s.step(x, double(i) * h, h);
  return x;
}

TEST(ExactSplit, Suzuki5BeatsTripleJumpAtEqualWork) {
  const auto& body = physics::preset(physics::Case::generic).body;
  for (long n5 : {30L, 60L}) {
    const long n3 = n5 * 5 / 3;
    const Vec6 s5 = composition_final(
        numerics::Composition4<ExactSplitSystem>(ExactSplitSystem(body)), 2.0, n5);
    const Vec6 tj = composition_final(
        numerics::Composition4<ExactSplitSystem, numerics::TripleJump4>(ExactSplitSystem(body)),
        2.0, n3);
    const double e5 = (s5 - reference(physics::Case::generic, 2.0)).norm();
    const double e3 = (tj - reference(physics::Case::generic, 2.0)).norm();
    std::printf(
        "equal work: Suzuki5 %ld steps error %.2e, triple jump %ld steps error %.2e (ratio %.1f)\n",
        n5, e5, n3, e3, e3 / e5);
    EXPECT_LT(e5, e3);
  }
}

TEST(ExactSplit, RejectsOtherFormulations) {
  for (auto m : {sim::Method::exact_split2, sim::Method::exact_split4}) {
    EXPECT_TRUE(sim::incompatibility(m, sim::Formulation::riccati));
    EXPECT_TRUE(sim::incompatibility(m, sim::Formulation::spinor));
    EXPECT_FALSE(sim::incompatibility(m, sim::Formulation::direct));
    EXPECT_EQ(sim::method_from_name(sim::name(m)), m);
  }
}

}  // namespace
}  // namespace epviz
