// Geometric properties: Gauss–Legendre methods conserve quadratic first
// integrals to round-off (and explicit RK4 does not); Strang splitting applies
// its sub-flows in the symmetric order, is time-reversible and conserves what
// each sub-flow conserves.
#include <gtest/gtest.h>

#include <cmath>
#include <utility>
#include <vector>

#include "numerics/gauss_legendre.hpp"
#include "numerics/rk4.hpp"
#include "numerics/splitting.hpp"
#include "test_systems.hpp"

namespace epviz::numerics {
namespace {

using testing::HeavyTop;
using testing::Kepler;
using testing::Oscillator;

struct Drift {
  double gamma2 = 0, area = 0, energy = 0;
};

// Max deviation of the three quadratic invariants of the heavy top over n steps.
template <class Stepper>
Drift invariant_drift(Stepper s, int n, double h) {
  const HeavyTop& top = s.system();
  auto x = HeavyTop::initial();
  const double g0 = top.gamma2(x), c0 = top.area(x), e0 = top.energy(x);
  Drift d;
  for (int i = 0; i < n; ++i) {
    s.step(x, i * h, h);
    if (i % 64 == 0 || i == n - 1) {
      d.gamma2 = std::max(d.gamma2, std::abs(top.gamma2(x) - g0));
      d.area = std::max(d.area, std::abs(top.area(x) - c0));
      d.energy = std::max(d.energy, std::abs(top.energy(x) - e0));
    }
  }
  return d;
}

template <class Stepper>
void expect_conserves(Stepper s) {
  const Drift d = invariant_drift(std::move(s), 100000, 0.05);
  EXPECT_LT(d.gamma2, 1e-13) << Stepper::name;
  EXPECT_LT(d.area, 1e-13) << Stepper::name;
  EXPECT_LT(d.energy, 1e-13) << Stepper::name;
}

TEST(QuadraticInvariants, GaussMethodsConserveThemToRoundOff) {
  expect_conserves(ImplicitMidpoint<HeavyTop>({}));
  expect_conserves(Gauss4<HeavyTop>({}));
  expect_conserves(Gauss6<HeavyTop>({}));
}

TEST(QuadraticInvariants, Rk4DriftsOnTheSameRun) {
  const Drift d = invariant_drift(Rk4<HeavyTop>({}), 100000, 0.05);
  EXPECT_GT(std::max({d.gamma2, d.area, d.energy}), 1e-9);
}

TEST(QuadraticInvariants, OscillatorEnergyWithGauss6) {
  Oscillator osc{2.0};
  Gauss6<Oscillator> s(osc);
  auto x = osc.exact(0.0);
  const double e0 = osc.energy(x);
  for (int i = 0; i < 100000; ++i) s.step(x, i * 0.1, 0.1);
  EXPECT_NEAR(osc.energy(x), e0, 1e-13 * e0);
}

TEST(GaussLegendre, ExtrapolatedStartSavesIterations) {
  Gauss6<HeavyTop> s({});
  auto x = HeavyTop::initial();
  const int n = 1000;
  for (int i = 0; i < n; ++i) s.step(x, i * 0.05, 0.05);
  const Stats& st = s.stats();
  EXPECT_EQ(st.steps, n);
  // The first step starts from the Euler guess (1 evaluation), the others
  // from the previous collocation polynomial.
  EXPECT_EQ(st.rhs_evals, 1 + 3 * st.solver_iterations);
  const double per_step = double(st.solver_iterations) / n;
  EXPECT_LT(per_step, 12.0);

  // Breaking the continuation (a different state) falls back to the Euler guess.
  Gauss6<HeavyTop> t({});
  auto y = HeavyTop::initial();
  t.step(y, 0.0, 0.05);
  auto z = y;
  z[0] += 1e-3;
  t.step(z, 0.05, 0.05);
  EXPECT_EQ(t.stats().rhs_evals, 2 + 3 * t.stats().solver_iterations);
}

TEST(GaussLegendre, IsSymmetric) {
  // One step forward and one backward return to the start (to round-off).
  const Kepler k{0.5};
  Gauss4<Kepler> s(k);
  auto x = k.initial();
  const auto x0 = x;
  s.step(x, 0.0, 0.1);
  s.step(x, 0.1, -0.1);
  EXPECT_LT((x - x0).cwiseAbs().maxCoeff(), 1e-14);
}

// Records the sub-flows applied.
struct Recorder {
  static constexpr int dim = 1;
  static constexpr int n_flows = 4;
  using State = Vec<1>;
  mutable std::vector<std::pair<int, double>>* log = nullptr;
  void flow(int i, double h, State&) const { log->emplace_back(i, h); }
};

TEST(Splitting, AppliesTheSymmetricComposition) {
  std::vector<std::pair<int, double>> log;
  StrangSplitting<Recorder> s(Recorder{&log});
  Vec<1> x(0.0);
  s.step(x, 0.0, 0.5);
  const std::vector<std::pair<int, double>> expected = {{0, 0.25}, {1, 0.25}, {2, 0.25}, {3, 0.5},
                                                        {2, 0.25}, {1, 0.25}, {0, 0.25}};
  EXPECT_EQ(log, expected);
  EXPECT_EQ(s.stats().flow_evals, 7);
  EXPECT_EQ(s.stats().steps, 1);
  EXPECT_EQ(s.stats().rhs_evals, 0);
}

TEST(Splitting, IsTimeReversible) {
  const Kepler k{0.5};
  StrangSplitting<Kepler> s(k);
  auto x = k.initial();
  const auto x0 = x;
  for (int i = 0; i < 100; ++i) s.step(x, i * 0.01, 0.01);
  for (int i = 100; i > 0; --i) s.step(x, i * 0.01, -0.01);
  EXPECT_LT((x - x0).cwiseAbs().maxCoeff(), 1e-13);
}

TEST(Splitting, ConservesWhatEverySubflowConserves) {
  // Drift and kick both keep the angular momentum q x p: so does the method,
  // while the energy only stays bounded (symplectic), not exact.
  const Kepler k{0.5};
  StrangSplitting<Kepler> s(k);
  auto x = k.initial();
  const double l0 = k.angular_momentum(x), e0 = k.energy(x);
  double de = 0;
  for (int i = 0; i < 100000; ++i) {
    s.step(x, i * 0.01, 0.01);
    de = std::max(de, std::abs(k.energy(x) - e0));
  }
  EXPECT_NEAR(k.angular_momentum(x), l0, 1e-12);
  EXPECT_GT(de, 1e-8);
  EXPECT_LT(de, 1e-2);
}

}  // namespace
}  // namespace epviz::numerics
