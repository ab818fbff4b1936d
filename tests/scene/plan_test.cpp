#include <gtest/gtest.h>

#include "physics/cases.hpp"
#include "scene/plan.hpp"
#include "sim/simulate.hpp"

namespace epviz {
namespace {

sim::RunSpec preset_run(physics::Case c, double t_end) {
  return sim::preset_run(c, sim::Method::dop853, sim::Formulation::direct, t_end, 200);
}

TEST(Tolerance, TightensWithResolutionAndDuration) {
  scene::SceneSettings small, large;
  small.width = 1280, small.height = 720;
  large.width = 3840, large.height = 2160;
  EXPECT_GT(scene::tolerance_for_resolution(small, 10), scene::tolerance_for_resolution(large, 10));
  EXPECT_GT(scene::tolerance_for_resolution(small, 10), scene::tolerance_for_resolution(small, 100));
  EXPECT_GE(scene::tolerance_for_resolution(large, 1e9), 1e-13);
  small.width = 64, small.height = 48;
  EXPECT_LE(scene::tolerance_for_resolution(small, 0), 1e-4);
}

TEST(Plan, SpaceViewIntegratesTheAttitude) {
  scene::SceneSettings s;
  s.view = scene::View::space;
  const auto plan = scene::plan_scene(preset_run(physics::Case::lagrange, 10), s);
  EXPECT_EQ(plan.run.formulation, sim::Formulation::spinor);
}

TEST(Plan, BodyViewIntegratesOnlyGamma) {
  scene::SceneSettings s;
  auto run = preset_run(physics::Case::lagrange, 10);
  run.formulation = sim::Formulation::spinor;
  EXPECT_EQ(scene::plan_scene(run, s).run.formulation, sim::Formulation::direct);
  s.formulation_given = true;  // but a job that asks for a formulation gets it
  EXPECT_EQ(scene::plan_scene(run, s).run.formulation, sim::Formulation::spinor);
}

TEST(Plan, SpaceViewRejectsAFormulationWithoutAttitude) {
  scene::SceneSettings s;
  s.view = scene::View::space;
  s.formulation_given = true;
  auto run = preset_run(physics::Case::lagrange, 10);
  run.formulation = sim::Formulation::riccati;
  EXPECT_THROW(scene::plan_scene(run, s), scene::PlanError);
}

TEST(Plan, FramesAndTrailSamples) {
  scene::SceneSettings s;
  s.fps = 25;
  s.duration = 4;
  const auto plan = scene::plan_scene(preset_run(physics::Case::euler, 20), s);
  EXPECT_EQ(plan.frames, 100);
  EXPECT_EQ(plan.run.samples, 99 * plan.samples_per_frame);
  EXPECT_DOUBLE_EQ(plan.frame_time(0), 0.0);
  EXPECT_DOUBLE_EQ(plan.frame_time(99), 20.0);
  EXPECT_NE(plan.accuracy_note.find("auto"), std::string::npos);
}

// The tolerance chosen for a resolution keeps the drawn error below half a
// pixel, measured against a run at tol 1e-13.
class AutoToleranceIsEnough : public ::testing::TestWithParam<physics::Case> {};

TEST_P(AutoToleranceIsEnough, ErrorBelowHalfAPixel) {
  scene::SceneSettings s;
  s.width = 1280, s.height = 720;
  const auto plan = scene::plan_scene(preset_run(GetParam(), 30), s);
  auto run = plan.run;
  const auto coarse = sim::simulate(run);
  run.tol = 1e-13;
  const auto fine = sim::simulate(run);
  ASSERT_FALSE(coarse.failure);
  ASSERT_FALSE(fine.failure);
  double worst = 0.0;
  for (std::size_t i = 0; i < coarse.samples.size(); ++i)
    worst = std::max(worst, (coarse.samples[i].gamma - fine.samples[i].gamma).norm());
  const double e = s.plane_extent;
  const double px = std::max(scene::sphere_pixels_per_unit(s), scene::plane_pixels_per_unit(s) * (1 + e * e) / 2);
  EXPECT_LT(worst * px, 0.5) << "tol " << plan.run.tol;
}

INSTANTIATE_TEST_SUITE_P(Integrable, AutoToleranceIsEnough,
                         ::testing::Values(physics::Case::euler, physics::Case::lagrange,
                                           physics::Case::kovalevskaya, physics::Case::goryachev_chaplygin,
                                           physics::Case::hess));

}  // namespace
}  // namespace epviz
