#include <gtest/gtest.h>

#include "physics/cases.hpp"
#include "scene/frame_source.hpp"

namespace epviz {
namespace {

scene::ScenePlan lagrange_plan(scene::SceneSettings& s) {
  const auto r = sim::preset_run(physics::Case::lagrange, sim::Method::dop853,
                                 sim::Formulation::direct, 10, 200);
  s.width = 320, s.height = 240, s.fps = 10, s.duration = 2;
  return scene::plan_scene(r, s);
}

TEST(FrameSource, BodyViewTrailIsGammaEndingAtTheCurrentPoint) {
  scene::SceneSettings s;
  scene::FrameSource src(lagrange_plan(s), s);
  ASSERT_EQ(src.frame_count(), 20);
  const auto f0 = src.frame(0);
  EXPECT_DOUBLE_EQ(f0.t, 0.0);
  const auto f = src.frame(19);
  EXPECT_NEAR(f.t, 10.0, 1e-12);
  ASSERT_GT(f.trail.size(), 10u);
  EXPECT_TRUE(f.trail.back().p.isApprox(f.current));
  EXPECT_FLOAT_EQ(f.trail.back().age, 0.0f);
  EXPECT_NEAR(f.trail.front().age, 1.0f, 0.05f);
  // On the unit sphere to well below a pixel (the auto tolerance at 320x240 is loose).
  const double px = src.plan().trail_sphere_px;
  for (const auto& p : f.trail) EXPECT_LT(std::abs(p.p.norm() - 1.0f) * px, 0.1);
  EXPECT_TRUE(f.body_rotation.isApprox(Eigen::Quaternionf::Identity()));
  EXPECT_EQ(f.overlay.title, "Lagrange top");
  ASSERT_EQ(f.overlay.drifts.size(), 4u);
  // Drifts at the loose auto tolerance of a 320x240 frame: small, not round-off.
  for (const auto& [name, v] : f.overlay.drifts) {
    EXPECT_LT(v, 1e-2) << name;
    EXPECT_GE(v, 0.0) << name;
  }
}

TEST(FrameSource, SpaceViewTurnsTheBodyAndTracesItsAxis) {
  scene::SceneSettings s;
  s.view = scene::View::space;
  scene::FrameSource src(lagrange_plan(s), s);
  const auto f = src.frame(15);
  // The body's axis 3 in space is where the rotation sends e3, and the
  // vertical seen from the body is the rotation's preimage of e_z.
  EXPECT_TRUE((f.body_rotation * Eigen::Vector3f::UnitZ()).isApprox(f.current, 1e-5f));
  EXPECT_FALSE(f.body_rotation.isApprox(Eigen::Quaternionf::Identity(), 1e-3f));
  // Lagrange top: the symmetry axis keeps a tilt between the nutation limits.
  for (const auto& p : f.trail) EXPECT_GT(p.p.z(), 0.5f);
}

}  // namespace
}  // namespace epviz
