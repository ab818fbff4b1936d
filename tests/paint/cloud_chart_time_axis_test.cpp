// A gallery's tiles share the cloud's spread chart's time axis: the drawer
// hands the value it is given to every frame's cloud, and a scene's own end
// is its last frame's time (none without a cloud).
#include <gtest/gtest.h>

#include "paint/frame_drawer.hpp"
#include "physics/cases.hpp"
#include "scene/plan.hpp"

namespace epviz {
namespace {

struct Scene {
  scene::SceneSettings settings;
  scene::ScenePlan plan;
};

Scene small_scene(int members) {
  Scene s;
  s.settings.width = 160, s.settings.height = 120, s.settings.fps = 5, s.settings.duration = 2;
  s.settings.cloud.members = members;
  s.plan = scene::plan_scene(sim::preset_run(physics::Case::kovalevskaya, sim::Method::dop853,
                                             sim::Formulation::direct, 3.0, 1),
                             s.settings);
  return s;
}

TEST(CloudChartTimeAxis, ASceneEndsAtItsLastFramesTimeAndNoneWithoutACloud) {
  const auto with = small_scene(20);
  EXPECT_DOUBLE_EQ(paint::cloud_chart_t_end(with.plan, with.settings),
                   with.plan.frame_time(with.plan.frames - 1));
  EXPECT_GT(paint::cloud_chart_t_end(with.plan, with.settings), 0.0);
  const auto without = small_scene(0);
  EXPECT_EQ(paint::cloud_chart_t_end(without.plan, without.settings), 0.0);
}

TEST(CloudChartTimeAxis, TheDrawerGivesEveryFrameTheSharedEnd) {
  const auto s = small_scene(20);
  paint::FrameDrawer own(s.plan, s.settings);
  const auto f = own.frame(1);
  ASSERT_TRUE(f.cloud);
  EXPECT_EQ(f.cloud->chart_t_end, 0.0);
  paint::FrameDrawer shared(s.plan, s.settings);
  shared.set_cloud_chart_t_end(99.0);
  EXPECT_EQ(shared.frame(1).cloud->chart_t_end, 99.0);
}

}  // namespace
}  // namespace epviz
