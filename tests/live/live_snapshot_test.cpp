// What a browser tab shows, at 960x540 with ImGui's built-in font: the
// scene with the panels, and the case combo open. Goldens in
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

}  // namespace
}  // namespace epviz::live
