// The overlay's drifts are those of what the picture draws: every sample of
// the run, interpolated ones included, not only the integrator's steps.
#include <gtest/gtest.h>

#include "physics/cases.hpp"
#include "scene/frame_source.hpp"
#include "sim/drift.hpp"
#include "sim/simulate.hpp"

namespace epviz {
namespace {

TEST(DrawnDrift, OverlayShowsTheDriftOfTheSamplesDrawn) {
  scene::SceneSettings s;
  s.width = 320, s.height = 240, s.fps = 5, s.duration = 2.8;  // 14 frames, 104 samples
  // Implicit midpoint at step 0.1 with a sample every 0.07: most samples lie
  // between two steps, on the cubic interpolant.
  auto run = sim::preset_run(physics::Case::kovalevskaya, sim::Method::midpoint,
                             sim::Formulation::direct, 7.28, 1);
  run.step = 0.1;
  const auto plan = scene::plan_scene(run, s, scene::Horizon::none);
  ASSERT_EQ(plan.run.method, sim::Method::midpoint);
  scene::FrameSource src(plan, s);
  scene::Frame f;
  for (int i = 0; i < src.frame_count(); ++i) f = src.frame(i);

  // The oracle: the same run's samples, kept and measured afterwards.
  const auto samples = sim::simulate(plan.run).samples;
  ASSERT_EQ(long(samples.size()), long(plan.run.samples) + 1);
  const auto drawn = sim::InvariantMonitor(plan.run.body, plan.run.case_id, plan.run.initial)
                         .max_relative_drift(samples);
  ASSERT_GE(f.overlay.drifts.size(), 3u);
  EXPECT_EQ(f.overlay.drifts[0].second, drawn.gamma_norm2);
  EXPECT_EQ(f.overlay.drifts[1].second, drawn.area);
  EXPECT_EQ(f.overlay.drifts[2].second, drawn.energy);
  // Midpoint keeps the quadratic energy at its steps; the drawn samples do not.
  EXPECT_LT(src.run(0).drifts().steps.energy, 1e-12);
  EXPECT_GT(f.overlay.drifts[2].second, 1e-9);
}

}  // namespace
}  // namespace epviz
