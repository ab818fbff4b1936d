// The interactive scene stops where `epviz simulate` and `epviz render` do: at
// the first output time whose energy drift exceeds the limit, with the last
// good frame on screen and advice worded for the panel.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <numbers>
#include <string>

#include "live/live_scene.hpp"
#include "sim/simulate.hpp"

namespace epviz::live {
namespace {

// A fast sleeping top with RK4 and a step of 1 in the Riccati formulation,
// played at one simulation time unit per sample (240 per second).
LiveSetup coarse_fast_top() {
  LiveSetup s = preset_setup(physics::Case::lagrange);
  const double tilt = 5.0 * std::numbers::pi / 180.0;
  s.run.initial.omega = {0.0, 0.0, 50.0};
  s.run.initial.gamma = {std::sin(tilt), 0.0, std::cos(tilt)};
  s.run.method = sim::Method::rk4;
  s.run.step = 1.0;
  s.run.formulation = sim::Formulation::riccati;
  s.scene.formulation_given = true;
  s.speed = 240.0;
  return s;
}

double failure_time(const std::string& line) {
  const std::string at = "failed at t = ";
  const auto p = line.find(at);
  EXPECT_NE(p, std::string::npos) << line;
  return p == std::string::npos ? NAN : std::strtod(line.c_str() + p + at.size(), nullptr);
}

TEST(LiveLostMotion, StopsWithTheSameFailureAsABatchRun) {
  const LiveSetup setup = coarse_fast_top();
  LiveScene scene(setup);
  scene.set_playing(true);
  for (int i = 0; i < 300 && !scene.failure(); ++i) scene.step();
  ASSERT_TRUE(scene.failure().has_value()) << "still running at t = " << scene.time();
  const std::string& line = *scene.failure();
  EXPECT_EQ(line.rfind("rk4 failed at t = ", 0), 0u) << line;
  EXPECT_NE(line.find("lost the motion: relative energy drift"), std::string::npos) << line;
  EXPECT_NE(line.find("use a smaller step in the Integrator panel"), std::string::npos) << line;
  EXPECT_EQ(line.find("--"), std::string::npos) << line;
  EXPECT_FALSE(scene.playing());

  // The batch run of the same spec, with the same output spacing, fails at the same time.
  sim::RunSpec batch = setup.run;
  batch.samples = 1000;
  batch.t_end = 1000.0;  // spacing 1 = speed / 240
  const auto r = sim::simulate(batch);
  ASSERT_TRUE(r.failure.has_value());
  EXPECT_EQ(r.failure->kind, numerics::FailureKind::lost_motion);
  const double t_fail = failure_time(line);
  EXPECT_DOUBLE_EQ(t_fail, r.failure->t);

  // The last good frame stays: before the failure, finite, and no later.
  const double shown = scene.time();
  EXPECT_LT(shown, t_fail);
  EXPECT_TRUE(scene.frame().current.allFinite());
  scene.step();
  scene.update(1.0);
  EXPECT_EQ(scene.time(), shown);
  for (const auto& d : scene.drift_history()) EXPECT_LE(d.drift.energy, 1.0) << "t = " << d.t;
}

}  // namespace
}  // namespace epviz::live
