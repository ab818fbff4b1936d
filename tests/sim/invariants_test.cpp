// Long-run behaviour of the invariants |gamma|^2, C0, C1 per method.
#include <gtest/gtest.h>

#include <cmath>

#include "run_helpers.hpp"
#include "sim/drift.hpp"

namespace epviz {
namespace {

// 1e5 steps of h = 0.01 on the Kovalevskaya top, sampled 1000 times.
sim::RunSpec long_run(sim::Method m, double t_end = 1000.0, int samples = 1000) {
  auto spec =
      sim::preset_run(physics::Case::kovalevskaya, m, sim::Formulation::direct, t_end, samples);
  spec.step = 0.01;
  return spec;
}

sim::Drifts run_drift(const sim::RunSpec& spec, std::vector<sim::Sample>* samples = nullptr) {
  const auto r = sim::simulate(spec);
  EXPECT_FALSE(r.failure) << r.failure->message();
  EXPECT_EQ(r.stats.steps, long(std::llround(spec.t_end / spec.step)));
  if (samples) *samples = r.samples;
  return sim::InvariantMonitor(spec.body, spec.case_id, spec.initial).max_relative_drift(r.samples);
}

class ImplicitMethod : public ::testing::TestWithParam<sim::Method> {};

TEST_P(ImplicitMethod, KeepsQuadraticInvariantsOver1e5Steps) {
  const auto d = run_drift(long_run(GetParam()));
  EXPECT_LT(d.gamma_norm2, 1e-12);
  EXPECT_LT(d.area, 1e-12);
  EXPECT_LT(d.energy, 1e-12);
}

INSTANTIATE_TEST_SUITE_P(Gauss, ImplicitMethod,
                         ::testing::Values(sim::Method::midpoint, sim::Method::gauss4,
                                           sim::Method::gauss6),
                         [](const auto& param_info) {
                           return std::string(sim::name(param_info.param));
                         });

TEST(Splitting, KeepsCasimirsToRoundOffAndEnergyBounded) {
  std::vector<sim::Sample> samples;
  const auto spec = long_run(sim::Method::splitting);
  const auto d = run_drift(spec, &samples);
  EXPECT_LT(d.gamma_norm2, 1e-12);
  EXPECT_LT(d.area, 1e-12);
  // Energy error of a symplectic-like splitting oscillates without drift: the
  // worst error in the last tenth is no larger than twice that of the first tenth.
  const sim::InvariantMonitor m(spec.body, spec.case_id, spec.initial);
  double first = 0.0, last = 0.0;
  const std::size_t n = samples.size();
  for (std::size_t i = 0; i < n / 10; ++i)
    first = std::max(first, m.relative_drift(m.at(samples[i])).energy);
  for (std::size_t i = n - n / 10; i < n; ++i)
    last = std::max(last, m.relative_drift(m.at(samples[i])).energy);
  EXPECT_GT(first, 0.0);
  EXPECT_LT(last, 2.0 * first);
  EXPECT_LT(d.energy, 1e-2);
}

TEST(Rk4, InvariantDriftGrowsWithTime) {
  std::vector<sim::Sample> samples;
  auto spec = long_run(sim::Method::rk4);
  spec.step = 0.05;  // coarse enough for the drift to stand well above round-off
  run_drift(spec, &samples);
  const sim::InvariantMonitor m(spec.body, spec.case_id, spec.initial);
  const auto early = m.relative_drift(m.at(samples[samples.size() / 10]));
  const auto late = m.relative_drift(m.at(samples.back()));
  EXPECT_GT(late.energy, 3.0 * early.energy);
  EXPECT_GT(late.gamma_norm2, 3.0 * early.gamma_norm2);
  EXPECT_GT(late.energy, 1e-10);  // measured, not round-off
}

}  // namespace
}  // namespace epviz
