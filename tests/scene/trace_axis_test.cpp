// The space view's trail follows the body axis the job names: the traced
// points of axes 1, 2 and 3 at one instant are the columns of the attitude,
// an orthonormal frame, and the trail's caption says which axis it is.
#include <gtest/gtest.h>

#include "physics/cases.hpp"
#include "scene/frame_source.hpp"

namespace epviz {
namespace {

scene::Frame space_frame(int trace_axis) {
  const auto run =
      sim::preset_run(physics::Case::euler, sim::Method::dop853, sim::Formulation::spinor, 6.0, 60);
  scene::SceneSettings s;
  s.view = scene::View::space;
  s.fps = 10;
  s.duration = 2;
  s.trace_axis = trace_axis;
  scene::FrameSource source(scene::plan_scene(run, s), s);
  return source.frame(12);
}

TEST(TraceAxis, TrailFollowsTheNamedBodyAxis) {
  Eigen::Matrix3f columns;
  for (int axis = 1; axis <= 3; ++axis) {
    const auto f = space_frame(axis);
    columns.col(axis - 1) = f.current;
    // The body's drawn rotation carries that body axis to the current point.
    const Eigen::Vector3f expected = f.body_rotation * Eigen::Vector3f::Unit(axis - 1);
    EXPECT_NEAR((f.current - expected).norm(), 0.0f, 1e-5f) << axis;
    EXPECT_NE(f.trail_label.find("body axis " + std::to_string(axis)), std::string::npos);
    EXPECT_GT(f.trail_time, 0.0);
    ASSERT_GE(f.trail.size(), 2u);
    for (const auto& p : f.trail) EXPECT_NEAR(p.p.norm(), 1.0f, 1e-4f);
  }
  // The three traced points at one instant form an orthonormal right-handed frame.
  EXPECT_NEAR((columns.transpose() * columns - Eigen::Matrix3f::Identity()).norm(), 0.0f, 1e-4f);
  EXPECT_NEAR(columns.determinant(), 1.0f, 1e-4f);
}

}  // namespace
}  // namespace epviz
