// The open-ended scene against an independent run: the same body integrated
// by sim::simulate at a much tighter tolerance.
#include <gtest/gtest.h>

#include "live/live_scene.hpp"
#include "sim/simulate.hpp"

namespace epviz::live {
namespace {

TEST(LiveScene, PlayingFollowsTheTrajectoryOfAnIndependentRun) {
  LiveSetup s = preset_setup(physics::Case::kovalevskaya);
  LiveScene scene(s);
  scene.set_playing(true);
  for (int i = 0; i < 90; ++i) scene.update(1.0 / 30.0);  // 3 s of wall-clock time
  const double t = scene.time();
  EXPECT_NEAR(t, 3.0 * s.speed, s.speed / 240.0);

  sim::RunSpec ref = s.run;
  ref.tol = 1e-13;
  ref.t_end = t;
  ref.samples = 1;
  const auto r = sim::simulate(ref);
  ASSERT_FALSE(r.failure);
  const Eigen::Vector3f g = r.samples.back().gamma.cast<float>();
  EXPECT_LT((scene.frame().current - g).norm(), 1e-5f) << "at t = " << t;
}

TEST(LiveScene, PausedTheSceneStaysAndStepAdvancesOneFrame) {
  LiveSetup s = preset_setup(physics::Case::lagrange);
  LiveScene scene(s);
  scene.update(1.0);
  EXPECT_EQ(scene.time(), 0.0);
  scene.step();
  EXPECT_NEAR(scene.time(), s.speed / 30.0, s.speed / 240.0);
}

TEST(LiveScene, ARestartWithASetupThatCannotRunKeepsTheRunningScene) {
  LiveSetup s = preset_setup(physics::Case::generic);
  LiveScene scene(s);
  scene.step();
  const double t = scene.time();
  LiveSetup bad = s;
  bad.run.method = sim::Method::splitting;
  bad.run.formulation = sim::Formulation::riccati;  // splitting needs the direct formulation
  bad.scene.formulation_given = true;
  EXPECT_THROW(scene.restart(bad), std::invalid_argument);
  EXPECT_EQ(scene.time(), t);
  EXPECT_EQ(scene.setup().run.method, s.run.method);
}

TEST(LiveScene, DriftHistoryIsBounded) {
  LiveScene scene(preset_setup(physics::Case::euler));
  scene.set_playing(true);
  for (std::size_t i = 0; i < LiveScene::kDriftHistory + 50; ++i) scene.update(0.01);
  EXPECT_EQ(scene.drift_history().size(), LiveScene::kDriftHistory);
  EXPECT_LT(scene.drift_history().back().drift.energy, 1e-6);
}

}  // namespace
}  // namespace epviz::live
