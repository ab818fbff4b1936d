// Near the south pole the Riccati coordinates (a, b) blow up. With the Moebius
// chart switch and in the spinor form all three formulations agree; without the
// switch the Riccati run fails, and says so.
#include <gtest/gtest.h>

#include "sim/run_helpers.hpp"
#include "study/pole_passage.hpp"

namespace epviz {
namespace {

constexpr double kPassTime = 2.0;

// Distance from the south pole at the passage. At 5e-4 the north chart still
// copes (|eta| ~ 4e3, with tiny steps); at 1e-7 (|eta| ~ 2e7) it cannot.
sim::RunSpec pole_spec(sim::Formulation f, double distance = 5e-4) {
  auto spec = sim::preset_run(physics::Case::generic, sim::Method::dop853, f, 6.0, 600);
  spec.case_id = physics::Case::custom;
  spec.initial =
      study::pole_passage_initial_state(spec.body, {0.3, 1.2, -0.4}, kPassTime, distance);
  spec.tol = 1e-12;
  return spec;
}

TEST(PolePassage, TrajectoryReallyPassesNearTheSouthPole) {
  const auto spec = pole_spec(sim::Formulation::direct);
  // It starts in the northern hemisphere, so the Riccati run starts in the
  // north chart and has to switch.
  EXPECT_GT(spec.initial.gamma.z(), 0.3);
  const auto r = sim::simulate(spec);
  ASSERT_FALSE(r.failure);
  double closest = 2.0;
  for (const auto& s : r.samples)
    closest = std::min(closest, (s.gamma + Eigen::Vector3d::UnitZ()).norm());
  EXPECT_LT(closest, 1e-3);
}

class PolePassageAt : public ::testing::TestWithParam<double> {};

TEST_P(PolePassageAt, ThreeFormulationsAgree) {
  const double d = GetParam();
  const auto direct = sim::simulate(pole_spec(sim::Formulation::direct, d));
  const auto riccati = sim::simulate(pole_spec(sim::Formulation::riccati, d));
  const auto spinor = sim::simulate(pole_spec(sim::Formulation::spinor, d));
  ASSERT_FALSE(direct.failure);
  ASSERT_FALSE(riccati.failure) << riccati.failure->message();
  ASSERT_FALSE(spinor.failure) << spinor.failure->message();
  ASSERT_EQ(direct.samples.size(), 601u);
  ASSERT_EQ(riccati.samples.size(), 601u);
  ASSERT_EQ(spinor.samples.size(), 601u);
  EXPECT_LT(test::max_gamma_difference(direct, riccati), 1e-9);
  EXPECT_LT(test::max_gamma_difference(direct, spinor), 1e-9);
  EXPECT_GE(riccati.chart_switches, 1);  // from the north chart into the south one
}

INSTANTIATE_TEST_SUITE_P(Distances, PolePassageAt, ::testing::Values(5e-4, 1e-7));

TEST(PolePassage, RiccatiWithoutChartSwitchFailsAndReportsIt) {
  auto spec = pole_spec(sim::Formulation::riccati, 1e-7);
  spec.chart_switch = false;
  const auto r = sim::simulate(spec);
  ASSERT_TRUE(r.failure.has_value()) << "the north chart cannot cross the south pole";
  EXPECT_EQ(r.failure->method, "dop853");
  EXPECT_NEAR(r.failure->t, kPassTime, 0.2);
  EXPECT_EQ(r.failure->kind, numerics::FailureKind::chart_pole) << r.failure->message();
  EXPECT_FALSE(r.failure->detail.empty());
  // Samples stop before the failure and none of them is garbage.
  ASSERT_FALSE(r.samples.empty());
  EXPECT_LT(r.samples.back().t, r.failure->t);
  for (const auto& s : r.samples) EXPECT_TRUE(s.gamma.allFinite() && s.omega.allFinite());
}

TEST(PolePassage, FixedStepRiccatiWithoutChartSwitchAlsoFails) {
  auto spec = pole_spec(sim::Formulation::riccati, 1e-7);
  spec.chart_switch = false;
  spec.method = sim::Method::rk4;
  spec.step = 1e-3;
  const auto r = sim::simulate(spec);
  ASSERT_TRUE(r.failure.has_value());
  EXPECT_EQ(r.failure->method, "rk4");
  EXPECT_NEAR(r.failure->t, kPassTime, 0.2);
}

}  // namespace
}  // namespace epviz
