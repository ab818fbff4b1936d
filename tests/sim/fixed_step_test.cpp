// Fixed-step methods integrate at exactly the step asked for, whatever the
// output spacing; output times between steps come from a cubic Hermite
// interpolant, checked against an independent tight DOP853 run.
#include <gtest/gtest.h>

#include <cmath>

#include "sim/simulate.hpp"
#include "sim/trajectory.hpp"

namespace epviz {
namespace {

sim::RunSpec kovalevskaya_rk4(double step, double t_end, int samples) {
  auto spec = sim::preset_run(physics::Case::kovalevskaya, sim::Method::rk4,
                              sim::Formulation::direct, t_end, samples);
  spec.step = step;
  return spec;
}

// The same run by DOP853 at tol 1e-13: the oracle for the states themselves.
std::vector<sim::Sample> reference(sim::RunSpec spec) {
  spec.method = sim::Method::dop853;
  spec.tol = 1e-13;
  const auto r = sim::simulate(spec);
  EXPECT_FALSE(r.failure);
  return r.samples;
}

double state_distance(const sim::Sample& a, const sim::Sample& b) {
  return std::max((a.omega - b.omega).norm(), (a.gamma - b.gamma).norm());
}

TEST(FixedStep, TakesTheStepAskedForWhateverTheSampling) {
  // 0.3 divides none of the spacings 0.25, 6/7 and 6: still 20 steps of 0.3.
  for (int samples : {24, 7, 1}) {
    const auto r = sim::simulate(kovalevskaya_rk4(0.3, 6.0, samples));
    ASSERT_FALSE(r.failure);
    EXPECT_EQ(r.effective_step, 0.3) << samples;
    EXPECT_EQ(r.stats.steps, 20) << samples;
    EXPECT_EQ(r.stats.rhs_evals, 80) << samples;
  }
}

TEST(FixedStep, SamplesOnStepsAreTheStepStatesExactly) {
  // Every 4th sample of the fine run falls on a step of 0.1: it must be that
  // step's state to the bit, as the coarse run (a sample per step) hands it out.
  const auto per_step = sim::simulate(kovalevskaya_rk4(0.1, 4.0, 40)).samples;
  const auto fine = sim::simulate(kovalevskaya_rk4(0.1, 4.0, 160)).samples;
  ASSERT_EQ(per_step.size(), 41u);
  ASSERT_EQ(fine.size(), 161u);
  for (std::size_t k = 0; k < per_step.size(); ++k) {
    EXPECT_EQ(fine[4 * k].omega, per_step[k].omega) << k;
    EXPECT_EQ(fine[4 * k].gamma, per_step[k].gamma) << k;
  }
}

TEST(FixedStep, InterpolatesBetweenStepsToFourthOrder) {
  // Step 0.2, samples every 0.025: most samples lie between steps. A linear
  // interpolant would be off by h^2/8 |x''| ~ 1e-2 here; the cubic Hermite
  // one by ~h^4/384 |x''''|, as small as RK4's own error at this step.
  auto spec = kovalevskaya_rk4(0.2, 4.0, 160);
  const auto run = sim::simulate(spec).samples;
  const auto ref = reference(spec);
  ASSERT_EQ(run.size(), ref.size());
  double on_steps = 0.0, between = 0.0;
  for (std::size_t k = 0; k < run.size(); ++k) {
    double& worst = k % 8 == 0 ? on_steps : between;
    worst = std::max(worst, state_distance(run[k], ref[k]));
  }
  EXPECT_LT(between, 1e-3);
  EXPECT_LT(between, 3.0 * on_steps + 1e-5);
}

TEST(FixedStep, InterpolatesAcrossARiccatiChartSwitch) {
  // A start that runs through the south pole: the Riccati state switches
  // charts between steps, and the interpolant must stay in one chart.
  sim::RunSpec spec;
  spec.body.inertia = {1.0, 1.7, 2.3};
  spec.body.com = {0.6, 0.4, 0.7};
  spec.body.weight = 1.0;
  spec.initial.omega = {0.0, 3.0, 0.0};
  spec.initial.gamma = Eigen::Vector3d(0.3, 0.0, -0.953939).normalized();
  spec.formulation = sim::Formulation::riccati;
  spec.method = sim::Method::rk4;
  spec.step = 0.02;
  spec.t_end = 4.0;
  spec.samples = 700;  // spacing 1/175: almost every sample between steps
  const auto r = sim::simulate(spec);
  ASSERT_FALSE(r.failure) << r.failure->message();
  ASSERT_GT(r.chart_switches, 0);
  const auto ref = reference(spec);
  double worst = 0.0;
  for (std::size_t k = 0; k < r.samples.size(); ++k)
    worst = std::max(worst, (r.samples[k].gamma - ref[k].gamma).norm());
  EXPECT_LT(worst, 1e-5);
}

TEST(FixedStep, ReportsEveryStepToItsObserver) {
  auto t = sim::Trajectory::start(kovalevskaya_rk4(0.3, 6.0, 7));
  std::vector<double> times;
  t->observe_steps([&](const sim::Sample& s) { times.push_back(s.t); });
  for (int k = 0; k < 7; ++k) t->next();
  ASSERT_EQ(times.size(), 20u);
  for (std::size_t i = 0; i < times.size(); ++i) EXPECT_NEAR(times[i], 0.3 * double(i + 1), 1e-12);
}

TEST(FixedStep, RefusesAStepThatIsNotPositive) {
  auto spec = kovalevskaya_rk4(0.0, 1.0, 10);
  EXPECT_THROW(sim::Trajectory::start(spec), std::invalid_argument);
}

}  // namespace
}  // namespace epviz
