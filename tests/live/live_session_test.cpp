// The interactive scene driven by input events, as a browser would drive it:
// each test sends events at the controls the session names and checks the
// simulation state and the picture.
#include <gtest/gtest.h>

#include <nlohmann/json.hpp>

#include "physics/cases.hpp"
#include "session_driver.hpp"

namespace epviz::live {
namespace {

using testing::SessionDriver;
using testing::starting_with;

TEST(LiveSession, DrawsTheSceneWithPanelsAndNamesItsControls) {
  SessionDriver d(starting_with(physics::Case::generic));
  for (const char* name : {"play", "step", "restart", "speed", "case", "I1", "weight", "panel"})
    EXPECT_TRUE(d.has_control(name)) << name;
  const auto c = nlohmann::json::parse(d.session->controls_json());
  EXPECT_EQ(c["view3d"].size(), 4u);
  EXPECT_FALSE(d.session->scene().playing());
  // Idle and paused: nothing to draw until something happens.
  EXPECT_FALSE(d.session->wants_frame());
}

TEST(LiveSession, PickingACaseFromTheComboLoadsItsPreset) {
  SessionDriver d(starting_with(physics::Case::generic));
  const auto before = d.last_hash;
  d.click("case");
  ASSERT_TRUE(d.has_control("case:kovalevskaya")) << "the combo did not open";
  d.click("case:kovalevskaya");
  const auto& run = d.session->scene().setup().run;
  EXPECT_EQ(run.case_id, physics::Case::kovalevskaya);
  EXPECT_EQ(run.body.inertia, physics::preset(physics::Case::kovalevskaya).body.inertia);
  EXPECT_NE(d.last_hash, before);
}

TEST(LiveSession, DraggingAMomentSliderKeepsTheCaseConditions) {
  SessionDriver d(starting_with(physics::Case::kovalevskaya));
  const double I3 = d.session->scene().setup().run.body.inertia.z();
  const auto before = d.last_hash;
  const Rect r = d.control("I3");
  d.drag(r[0] + r[2] / 2, r[1] + r[3] / 2, 60.0f, 0.0f);
  const auto& run = d.session->scene().setup().run;
  EXPECT_GT(run.body.inertia.z(), I3 + 0.1);  // 0.01 per pixel
  EXPECT_EQ(run.case_id, physics::Case::kovalevskaya);
  EXPECT_FALSE(physics::broken_condition(physics::Case::kovalevskaya, run.body, run.initial));
  EXPECT_NE(d.last_hash, before);
  EXPECT_FALSE(d.session->dragging()) << "a drag on the panel must not orbit the camera";
}

TEST(LiveSession, PlayAdvancesTimeAndThePicture) {
  SessionDriver d(starting_with(physics::Case::kovalevskaya));
  EXPECT_EQ(d.session->scene().time(), 0.0);
  d.click("play");
  ASSERT_TRUE(d.session->scene().playing());
  const double speed = d.session->scene().setup().speed;
  const double t0 = d.session->scene().time();
  const auto h0 = d.last_hash;
  d.frames(30);  // one second of the fixed clock
  EXPECT_NEAR(d.session->scene().time() - t0, speed, 2 * speed / 240.0);
  EXPECT_NE(d.last_hash, h0);
  d.click("play");  // now "Pause"
  EXPECT_FALSE(d.session->scene().playing());
}

TEST(LiveSession, KeyboardShortcutsPlayPauseAndRestart) {
  SessionDriver d(starting_with(physics::Case::lagrange));
  d.key(" ");
  d.frames(10);
  EXPECT_TRUE(d.session->scene().playing());
  EXPECT_GT(d.session->scene().time(), 0.0);
  d.key(" ");
  d.frames(2);
  EXPECT_FALSE(d.session->scene().playing());
  d.key("r");
  d.settle();
  EXPECT_EQ(d.session->scene().time(), 0.0);
}

TEST(LiveSession, TextFieldsAcceptTyping) {
  SessionDriver d(starting_with(physics::Case::kovalevskaya));
  d.click("weight");
  d.key("a", /*ctrl=*/true);  // select all, then type over it
  d.type("2.5");
  d.key("Enter");
  d.settle();
  EXPECT_DOUBLE_EQ(d.session->scene().setup().run.body.weight, 2.5);
}

TEST(LiveSession, DragInTheViewOrbitsAndWheelZooms) {
  SessionDriver d(starting_with(physics::Case::kovalevskaya));
  const auto cam0 = d.session->scene().setup().scene.camera;
  const auto& v = d.session->view_3d();
  const float x = float(v.x + v.width) - 60.0f,
              y = float(v.y + v.height) / 2.0f;  // clear of the panel
  ASSERT_FALSE(d.session->panel().contains(x, y));
  const auto before = d.last_hash;
  d.drag(x, y, -80.0f, 30.0f);
  const auto cam1 = d.session->scene().setup().scene.camera;
  EXPECT_GT(cam1.azimuth_deg,
            cam0.azimuth_deg + 10.0);  // dragging left turns the camera the other way
  EXPECT_GT(cam1.elevation_deg, cam0.elevation_deg + 3.0);
  EXPECT_NE(d.last_hash, before);
  d.wheel(x, y, 2.0f);
  EXPECT_LT(d.session->scene().setup().scene.camera.distance, cam1.distance * 0.85);
}

TEST(LiveSession, SavesTheFrameAndARenderJob) {
  SessionDriver d(starting_with(physics::Case::hess));
  d.click("save_frame");
  d.settle();
  d.click("save_job");
  auto downloads = d.session->take_downloads();
  ASSERT_EQ(downloads.size(), 2u);
  EXPECT_EQ(downloads[0].mime, "image/png");
  ASSERT_GT(downloads[0].bytes.size(), 8u);
  EXPECT_EQ(downloads[0].bytes[1], 'P');  // "\x89PNG"
  EXPECT_EQ(downloads[1].mime, "application/json");
  const auto job = nlohmann::json::parse(downloads[1].bytes.begin(), downloads[1].bytes.end());
  EXPECT_EQ(job["simulation"]["case"], "hess");
  EXPECT_EQ(d.session->take_notices().size(), 2u);
}

TEST(LiveSession, ANumericalFailureStopsTheRunWithAReport) {
  SessionOptions o = starting_with(physics::Case::generic);
  o.initial.run.method = sim::Method::rk4;
  // Samples 1000/240 apart; RK4 steps of 2 are far beyond its stability for this body.
  o.initial.run.step = 2.0;
  o.initial.speed = 1000.0;
  SessionDriver d(o);
  d.click("play");
  d.frames(120);
  const auto& failure = d.session->scene().failure();
  ASSERT_TRUE(failure.has_value()) << "t = " << d.session->scene().time();
  EXPECT_NE(failure->find("rk4"), std::string::npos) << *failure;
  EXPECT_NE(failure->find("t = "), std::string::npos) << *failure;
  EXPECT_FALSE(d.session->scene().playing());
  EXPECT_TRUE(std::isfinite(d.session->scene().frame().current.norm()));
}

}  // namespace
}  // namespace epviz::live
