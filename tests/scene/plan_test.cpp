#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

#include "physics/cases.hpp"
#include "scene/frame_source.hpp"
#include "scene/plan.hpp"
#include "sim/simulate.hpp"
#include "true_error.hpp"

namespace epviz {
namespace {

sim::RunSpec preset_run(physics::Case c, double t_end) {
  return sim::preset_run(c, sim::Method::dop853, sim::Formulation::direct, t_end, 200);
}

double tolerance_for(const scene::SceneSettings& s, double t_end) {
  const auto run = preset_run(physics::Case::lagrange, t_end);
  return scene::tolerance_for_layout(scene::planned_layout(s, run), s.plane_extent, t_end);
}

TEST(Tolerance, TightensWithResolutionAndDuration) {
  scene::SceneSettings small, large;
  small.width = 1280, small.height = 720;
  large.width = 3840, large.height = 2160;
  EXPECT_GT(tolerance_for(small, 10), tolerance_for(large, 10));
  EXPECT_GT(tolerance_for(small, 10), tolerance_for(small, 100));
  EXPECT_GE(tolerance_for(large, 1e9), 1e-13);
  small.width = 64, small.height = 48;
  EXPECT_LE(tolerance_for(small, 0), 1e-4);
}

std::string describe(const std::optional<scene::Rect>& r) {
  if (!r) return "none";
  return std::to_string(r->x) + "," + std::to_string(r->y) + " " + std::to_string(r->width) + "x" +
         std::to_string(r->height);
}

std::string describe(const scene::FrameLayout& l) {
  return "3d " + describe(l.view_3d) + ", column " + describe(l.panel_column) + ", plot " +
         describe(l.plot_area) + ", chart " + describe(l.chart_area) + ", legend " +
         describe(l.legend_area) + ", overlay in column " + std::to_string(l.overlay_in_column) +
         ", px/unit " + std::to_string(l.sphere_px_per_unit) + " " +
         std::to_string(l.plane_px_per_unit);
}

// The painter's layout of a picture with these settings.
scene::FrameLayout painted(const scene::SceneSettings& s, int chart_height = 0,
                           int legend_rows = 0) {
  scene::LayoutRequest q;
  q.width = s.width;
  q.height = s.height;
  q.layers = s.layers;
  q.camera_distance = s.camera.distance;
  q.plane_extent = s.plane_extent;
  q.chart_height = chart_height;
  q.legend_rows = legend_rows;
  return scene::frame_layout(q);
}

// The plan lays the picture out as the painter will, following every setting
// the layout depends on: each variation below moves something in the picture.
TEST(Plan, LaysOutThePictureAsThePainterWill) {
  const auto run = preset_run(physics::Case::kovalevskaya, 10);
  const scene::SceneSettings base;  // 1280 x 720: the overlay sits above the plot
  ASSERT_TRUE(painted(base).overlay_in_column);
  std::vector<scene::SceneSettings> variants(5, base);
  variants[1].layers.overlay = false;  // the plot takes the overlay's room
  variants[2].width = 640, variants[2].height = 360;
  variants[3].camera.distance = 5.0;
  variants[4].plane_extent = 1.5f;
  for (std::size_t i = 0; i < variants.size(); ++i) {
    SCOPED_TRACE("variant " + std::to_string(i));
    const auto plan = scene::plan_scene(run, variants[i], scene::Horizon::none);
    EXPECT_EQ(describe(plan.layout), describe(painted(variants[i])));
    if (i > 0) {
      EXPECT_NE(describe(painted(variants[i])), describe(painted(base)));
    }
  }
  // A comparison scene keeps room for its separation chart under the plot
  // and for its legend under the 3D view.
  scene::RunRequest request;
  request.run = run;
  const auto plan = scene::plan_scene({request, request}, base, scene::Horizon::none);
  EXPECT_TRUE(plan.layout.chart_area);
  EXPECT_TRUE(plan.layout.legend_area);
  EXPECT_EQ(describe(plan.layout),
            describe(painted(base, scene::comparison_chart_height(base.height),
                             scene::comparison_legend_rows(2))));
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

// Trails are kept fine enough for any layers the picture may switch on later.
TEST(Plan, TrailsAreDecimatedForTheLargestScaleOfEachPart) {
  scene::SceneSettings s;
  s.layers = scene::Layers::only({scene::Layer::riccati});  // planned with the plane alone
  const auto plan = scene::plan_scene(preset_run(physics::Case::euler, 10), s);
  for (unsigned bits = 1; bits < (1u << scene::layer_count); ++bits) {
    scene::LayoutRequest q;
    q.width = s.width;
    q.height = s.height;
    for (std::size_t i = 0; i < scene::layer_count; ++i)
      q.layers.*scene::layer_table()[i].member = bits & (1u << i);
    q.overlay = {scene::kOverlayLines, 3};
    const auto l = scene::frame_layout(q);
    EXPECT_GE(plan.trail_sphere_px, l.sphere_px_per_unit) << bits;
    EXPECT_GE(plan.trail_plane_px, l.plane_px_per_unit) << bits;
  }
  EXPECT_GT(plan.trail_sphere_px, 0.0);
}

// The tolerance chosen for a resolution keeps the drawn error below half a
// pixel, measured against a run at tol 1e-13.
class AutoToleranceIsEnough : public ::testing::TestWithParam<physics::Case> {};

TEST_P(AutoToleranceIsEnough, ErrorBelowHalfAPixel) {
  scene::SceneSettings s;
  s.width = 1280, s.height = 720;
  const auto plan = scene::plan_scene(preset_run(GetParam(), 30), s);
  double worst_px = 0.0;
  for (const auto& [t, e] : testing::true_error_px(plan, s.plane_extent))
    worst_px = std::max(worst_px, e);
  EXPECT_LT(worst_px, 0.5) << "tol " << plan.run.tol;
}

INSTANTIATE_TEST_SUITE_P(Integrable, AutoToleranceIsEnough,
                         ::testing::Values(physics::Case::euler, physics::Case::lagrange,
                                           physics::Case::kovalevskaya,
                                           physics::Case::goryachev_chaplygin,
                                           physics::Case::hess));

}  // namespace
}  // namespace epviz
