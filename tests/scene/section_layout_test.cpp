// A section panel's place in the layout: beside the Riccati plane in the
// panel column, both square, clear of each other and of the 3D view, the
// overlay above them where a 720p picture has the room, and the same
// rectangles for the plan (from the job's settings) as for the painter (from
// the frame).
#include <gtest/gtest.h>

#include "scene/layout.hpp"
#include "scene/plan.hpp"

namespace epviz {
namespace {

using scene::Rect;

bool overlap(const Rect& a, const Rect& b) {
  return a.x < b.right() && b.x < a.right() && a.y < b.bottom() && b.y < a.bottom();
}
bool within(const Rect& r, const Rect& outer) {
  return r.x >= outer.x && r.y >= outer.y && r.right() <= outer.right() &&
         r.bottom() <= outer.bottom();
}

class SectionLayoutAtSize : public ::testing::TestWithParam<std::pair<int, int>> {};

TEST_P(SectionLayoutAtSize, BesideThePlaneSquareAndClear) {
  const auto [w, h] = GetParam();
  scene::LayoutRequest q;
  q.width = w;
  q.height = h;
  q.section_panel = true;
  const auto l = scene::frame_layout(q);
  ASSERT_TRUE(l.view_3d && l.panel_column && l.plot_area && l.section_area);
  const Rect& s = *l.section_area;
  EXPECT_EQ(s.width, s.height);
  EXPECT_EQ(s.width, l.plot_area->width);
  EXPECT_TRUE(within(s, *l.panel_column));
  EXPECT_TRUE(within(*l.plot_area, *l.panel_column));
  EXPECT_FALSE(overlap(s, *l.plot_area));
  EXPECT_FALSE(overlap(s, *l.view_3d));
  EXPECT_GT(s.x, l.plot_area->right());  // beside it, to its right
  EXPECT_EQ(s.y, l.plot_area->y);
  // Room for the tick labels between the two plots.
  EXPECT_GE(s.x - l.plot_area->right(), 30);
  // Without it the plane keeps its place of every other job.
  q.section_panel = false;
  const auto plain = scene::frame_layout(q);
  EXPECT_FALSE(plain.section_area);
  EXPECT_EQ(plain.view_3d->width, w * 3 / 5);
}

INSTANTIATE_TEST_SUITE_P(Sizes, SectionLayoutAtSize,
                         ::testing::Values(std::pair{1280, 720}, std::pair{640, 360},
                                           std::pair{1920, 1080}));

TEST(SectionLayout, OverlayStaysInTheColumnAt720p) {
  scene::LayoutRequest q;
  q.section_panel = true;
  EXPECT_TRUE(scene::frame_layout(q).overlay_in_column);
}

TEST(SectionLayout, PlanAndFrameAskForTheSameLayout) {
  scene::SceneSettings s;
  s.section = scene::SectionPanelSettings{};
  const auto run = sim::preset_run(physics::Case::kovalevskaya, sim::Method::dop853,
                                   sim::Formulation::direct, 10.0, 10);
  const auto planned = scene::planned_layout(s, run);
  ASSERT_TRUE(planned.section_area);
  scene::Frame f;
  f.layers = s.layers;
  f.section = scene::SectionPanel{};
  const auto drawn = scene::frame_layout(scene::layout_request(f, s.width, s.height));
  ASSERT_TRUE(drawn.section_area);
  EXPECT_EQ(drawn.section_area->x, planned.section_area->x);
  EXPECT_EQ(drawn.section_area->width, planned.section_area->width);
  EXPECT_EQ(drawn.plot_area->width, planned.plot_area->width);
  EXPECT_EQ(drawn.plane_px_per_unit, planned.plane_px_per_unit);
}

TEST(SectionLayout, InteractiveScenesLayNoPanelOut) {
  // Their frames carry none (no end to find crossings to), so their plan has none.
  scene::SceneSettings s;
  s.section = scene::SectionPanelSettings{};
  auto run = sim::preset_run(physics::Case::kovalevskaya, sim::Method::dop853,
                             sim::Formulation::direct, 10.0, 10);
  run.tol = 1e-10;
  EXPECT_TRUE(scene::plan_scene(run, s, scene::Horizon::search).layout.section_area);
  EXPECT_FALSE(scene::plan_scene(run, s, scene::Horizon::none).layout.section_area);
}

}  // namespace
}  // namespace epviz
