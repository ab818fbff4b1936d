// What a browser tab shows, at 960x540 with ImGui's built-in font: the
// scene with the panels, the case combo open, and three runs compared. Goldens in
// tests/snapshots/live_*.png, reviewed by looking at them.
#include <gtest/gtest.h>

#include "render/snapshot.hpp"
#include "session_driver.hpp"

namespace epviz::live {
namespace {

using testing::SessionDriver;

TEST(LiveSnapshot, PanelsOverTheScene) {
  SessionOptions o;
  o.initial = preset_setup(physics::Case::kovalevskaya);
  SessionDriver d(o);
  d.click("play");
  d.frames(45);
  d.click("play");  // pause
  const auto& img = d.session->render();
  EXPECT_TRUE(epviz::testing::matches_snapshot("live_panels", img.width, img.height, img.pixels));
}

TEST(LiveSnapshot, CaseComboOpen) {
  SessionOptions o;
  o.initial = preset_setup(physics::Case::hess);
  SessionDriver d(o);
  d.click("case");
  const auto& img = d.session->render();
  EXPECT_TRUE(
      epviz::testing::matches_snapshot("live_case_combo", img.width, img.height, img.pixels));
}

TEST(LiveSnapshot, ThreeRunsCompared) {
  SessionOptions o;
  o.initial = preset_setup(physics::Case::generic);
  o.initial.compared.push_back(with_method(sim::Method::rk4, 0.25, 0.0));
  o.initial.compared.push_back(nudged_by(1e-3));
  SessionDriver d(o);
  d.click("header:case");
  d.click("header:runs");
  d.click("play");
  d.frames(90);
  d.click("play");  // pause
  const auto& img = d.session->render();
  EXPECT_TRUE(epviz::testing::matches_snapshot("live_compare", img.width, img.height, img.pixels));
}

}  // namespace
}  // namespace epviz::live
