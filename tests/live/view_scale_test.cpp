// The server draws a moving view smaller (adaptive resolution) and the page
// stretches each frame to the same window: a control must lie where the page
// shows it at any scale, and a click given in the old size's pixels but
// applied after the view shrank must still land on the control it aimed at.
#include <gtest/gtest.h>

#include "session_driver.hpp"

namespace epviz::live {
namespace {

using testing::SessionDriver;

constexpr int kWidth = 1280, kHeight = 720;

bool contains(const Rect& r, float x, float y) {
  return x >= r[0] && y >= r[1] && x < r[0] + r[2] && y < r[1] + r[3];
}

TEST(LiveViewScale, ControlsDrawnSmallerLieWhereThePageShowsThemFullSize) {
  SessionDriver full_size({}, kWidth, kHeight);
  const auto full = full_size.session->panel().controls();
  ASSERT_GT(full.size(), 10u);
  for (const double scale : {0.5, 0.625, 0.75}) {
    SCOPED_TRACE(scale);
    SessionDriver d({}, kWidth, kHeight);
    const int w = int(kWidth * scale), h = int(kHeight * scale);
    d.session->set_view_scale(double(h) / kHeight);
    d.session->resize(w, h);
    d.settle();
    const auto small = d.session->panel().controls();
    EXPECT_EQ(small.size(), full.size());
    const float sx = float(kWidth) / float(w), sy = float(kHeight) / float(h);
    for (const auto& [name, r] : small) {
      SCOPED_TRACE(name);
      ASSERT_TRUE(full.count(name));
      const Rect& f = full.at(name);
      // Stretched to the window as the page shows it: within a pixel of the
      // full-size control, and holding its centre.
      const Rect stretched = {r[0] * sx, r[1] * sy, r[2] * sx, r[3] * sy};
      for (int k = 0; k < 4; ++k) EXPECT_NEAR(stretched[k], f[k], 1.0f) << "component " << k;
      EXPECT_TRUE(contains(stretched, f[0] + f[2] / 2, f[1] + f[3] / 2));
    }
  }
}

TEST(LiveViewScale, AClickGivenBeforeTheViewShrankLandsOnTheControlItAimedAt) {
  SessionDriver d({}, kWidth, kHeight);
  ASSERT_FALSE(d.session->scene().playing());
  const Rect play = d.control("play");
  const float x = play[0] + play[2] / 2, y = play[1] + play[3] / 2;
  // The press and release wait for frames of their own; the view shrinks first.
  d.move(x, y);
  d.button(x, y, true);
  d.button(x, y, false);
  d.session->set_view_scale(0.5);
  d.session->resize(kWidth / 2, kHeight / 2);
  d.settle();
  EXPECT_TRUE(d.session->scene().playing()) << "the click missed Play after the resize";
}

// A combo opens its list a frame after the click: the click, queued in the
// full size's pixels, and the list both outlive the resize between.
TEST(LiveViewScale, AComboClickedBeforeTheViewShrankOpens) {
  SessionDriver d({}, kWidth, kHeight);
  const Rect c = d.control("case");
  const float x = c[0] + c[2] / 2, y = c[1] + c[3] / 2;
  d.move(x, y);
  d.button(x, y, true);
  d.button(x, y, false);
  d.frames(1);  // the move only: the press and the release wait for frames of their own
  d.session->set_view_scale(0.5);
  d.session->resize(kWidth / 2, kHeight / 2);
  d.settle();
  EXPECT_TRUE(d.has_control("case:generic")) << "the case list did not open";
}

}  // namespace
}  // namespace epviz::live
