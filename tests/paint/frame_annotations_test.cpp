// What the painter draws over the 3D view and the plane: labels placed clear
// of each other, of the marks and of the other parts of the picture; the
// colour bar that explains the trail's time colouring; text that grows with
// the picture.
#include <gtest/gtest.h>

#include "paint/frame_painter.hpp"
#include "paint/preset_frame.hpp"
#include "paint/trail_colours.hpp"
#include "physics/cases.hpp"
#include "render/render_test_support.hpp"

namespace epviz {
namespace {

namespace et = epviz::testing;

// A frame of a preset's short run, at this size, view and camera.
scene::Frame frame_of(physics::Case c, scene::View view, int w, int h, double distance = 3.4,
                      int trace_axis = 3) {
  scene::SceneSettings s;
  s.width = w;
  s.height = h;
  s.view = view;
  s.camera.distance = distance;
  s.trace_axis = trace_axis;
  s.trail_length = 6.0;
  return et::preset_frame(c, s);
}

paint::Box box_of(const scene::Rect& v) {
  return {glm::vec2(v.x, v.y), glm::vec2(v.x + v.width, v.y + v.height)};
}

paint::FramePainter& painter_720() {
  static paint::FramePainter p(et::shared_gl_context(), 1280, 720, {.builtin_font = true});
  return p;
}

struct Job {
  physics::Case c;
  scene::View view;
  double distance;
  int trace_axis;
};

TEST(FrameAnnotations, LabelsNeitherCollideNorLeaveTheirPart) {
  // The Euler job's close camera (its "N" was cut off at the top), both views.
  for (const Job& job : {Job{physics::Case::euler, scene::View::space, 3.3, 2},
                         Job{physics::Case::euler, scene::View::space, 3.3, 3},
                         Job{physics::Case::lagrange, scene::View::space, 3.4, 3},
                         Job{physics::Case::kovalevskaya, scene::View::body, 3.4, 3},
                         Job{physics::Case::generic, scene::View::body, 2.6, 3}}) {
    const auto f = frame_of(job.c, job.view, 1280, 720, job.distance, job.trace_axis);
    painter_720().paint(f);
    const auto& a = painter_720().annotations();
    const auto layout = paint::layout_for(f, 1280, 720);
    const paint::Box panel = box_of(*layout.panel_column), view = box_of(*layout.view_3d);
    std::vector<std::string> texts;
    for (const auto& l : a.labels) texts.push_back(l.text);
    for (const char* expected : {"e1", "e2", "e3", "N", "S", "equator"})
      EXPECT_NE(std::find(texts.begin(), texts.end(), expected), texts.end()) << expected;

    // The current point's marker, which "e3" used to cover in the space view.
    const auto view_3d = paint::to_viewport(*layout.view_3d);
    const auto marker = render::project_to_pixel(paint::camera_for(f, view_3d), view_3d,
                                                 {f.current.x(), f.current.y(), f.current.z()});
    ASSERT_TRUE(marker);
    const paint::Box marker_box = paint::box_around(glm::vec2(*marker), glm::vec2(8.0f));
    for (std::size_t i = 0; i < a.labels.size(); ++i) {
      const auto& l = a.labels[i];
      EXPECT_TRUE(l.bounds.contains(l.box)) << l.text;
      EXPECT_GT(l.box.width(), 0.0f) << l.text;
      if (view.contains(l.box)) {
        EXPECT_FALSE(l.box.intersects(panel)) << l.text;
        EXPECT_FALSE(l.box.intersects(marker_box)) << l.text;
      } else {
        EXPECT_TRUE(panel.contains(l.box)) << l.text << " is in neither part";
      }
      for (std::size_t j = i + 1; j < a.labels.size(); ++j)
        EXPECT_FALSE(l.box.intersects(a.labels[j].box)) << l.text << " / " << a.labels[j].text;
    }
  }
}

TEST(FrameAnnotations, ColourBarFollowsTheTimeColourMap) {
  const auto f = frame_of(physics::Case::lagrange, scene::View::space, 1280, 720);
  const auto& img = painter_720().paint(f);
  const auto& a = painter_720().annotations();
  ASSERT_TRUE(a.colour_bar);
  const paint::Box bar = *a.colour_bar;
  EXPECT_GT(bar.width(), 60.0f);
  const float y = 0.5f * (bar.min.y + bar.max.y);
  float previous_lightness = -1.0f;
  for (int k = 0; k < 10; ++k) {
    const float x = bar.min.x + bar.width() * (float(k) + 0.5f) / 10.0f;
    // The left end is the oldest point of the trail (age 1), the right end now.
    const float age = 1.0f - (x - bar.min.x) / bar.width();
    const glm::vec4 expected = paint::age_colour_opaque(age, a.map_top);
    const glm::vec4 got = et::pixel_colour(img, int(x), int(y));
    EXPECT_LT(et::max_channel_difference(got, expected), 0.05f) << "at age " << age;
    const float lightness = et::luminance(got);
    EXPECT_GT(lightness, previous_lightness) << "the map brightens towards now";
    previous_lightness = lightness;
  }
}

TEST(FrameAnnotations, TextGrowsWithThePicture) {
  for (bool builtin : {true, false}) {
    paint::FramePainter small(et::shared_gl_context(), 1280, 720, {.builtin_font = builtin});
    paint::FramePainter big(et::shared_gl_context(), 3840, 2160, {.builtin_font = builtin});
    const double ratio = 3.0;
    EXPECT_NEAR(big.gui().label_font_px() / small.gui().label_font_px(), ratio, 0.1 * ratio);
    // The labels as drawn: "N" is as many times taller as the picture.
    auto n_height = [](paint::FramePainter& p, int w, int h) {
      p.paint(frame_of(physics::Case::kovalevskaya, scene::View::body, w, h));
      for (const auto& l : p.annotations().labels)
        if (l.text == "N") return l.box.height();
      return 0.0f;
    };
    const float hs = n_height(small, 1280, 720), hb = n_height(big, 3840, 2160);
    ASSERT_GT(hs, 0.0f);
    EXPECT_NEAR(hb / hs, ratio, 0.1 * ratio) << (builtin ? "built-in font" : "TTF");
  }
}

TEST(FrameAnnotations, AGalleryTilesCaptionHasItsOwnLineAndTheSphereFitsTheTile) {
  // A gallery tile, its caption as long as a shipped job's, for every case.
  paint::FramePainter tile(et::shared_gl_context(), 640, 360, {.builtin_font = true});
  for (const Job& job : {Job{physics::Case::euler, scene::View::space, 3.3, 2},
                         Job{physics::Case::lagrange, scene::View::space, 3.4, 3},
                         Job{physics::Case::kovalevskaya, scene::View::body, 3.4, 3},
                         Job{physics::Case::goryachev_chaplygin, scene::View::body, 3.4, 3},
                         Job{physics::Case::generic, scene::View::body, 3.4, 3}}) {
    auto f = frame_of(job.c, job.view, 640, 360, job.distance, job.trace_axis);
    f.caption = "goryachev-chaplygin: dop853, tol 2.6e-05 (auto, tightened)";
    // A shipped job's long title widens the overlay that floats over the view.
    f.overlay.title = "Generic heavy top: the same cloud of 10,000 states smears";
    tile.paint(f);
    const auto& a = tile.annotations();
    const auto layout = paint::layout_for(f, 640, 360);
    ASSERT_TRUE(layout.caption_area);
    const paint::Box caption_line = box_of(*layout.caption_area), view = box_of(*layout.view_3d);
    const auto caption = std::find_if(a.legend.begin(), a.legend.end(),
                                      [&](const auto& l) { return l.text == f.caption; });
    ASSERT_NE(caption, a.legend.end()) << "the caption is not drawn whole";
    EXPECT_TRUE(caption_line.contains(caption->box));
    EXPECT_FALSE(caption_line.intersects(view));
    if (a.marks_key) {
      EXPECT_FALSE(caption->box.intersects(*a.marks_key));
      // The overlay floats over a tile's view: the key keeps out of it.
      ASSERT_TRUE(a.overlay_window);
      EXPECT_FALSE(a.overlay_window->intersects(*a.marks_key));
    }
    for (const auto& l : a.labels) EXPECT_FALSE(caption->box.intersects(l.box)) << l.text;
    // The whole sphere inside its view, with the pole labels inside the picture.
    ASSERT_TRUE(a.sphere);
    const glm::vec2 r(a.sphere->radius);
    EXPECT_TRUE(view.contains({a.sphere->centre - r, a.sphere->centre + r}));
    for (const auto& l : a.labels) EXPECT_TRUE(l.bounds.contains(l.box)) << l.text;
  }
}

// The overlay in the corner of the 3D view a job asks for: inside the view,
// against that corner's edges (the bottom ones above the trail's key).
TEST(FrameAnnotations, TheOverlayGoesToTheCornerAsked) {
  for (const auto place : {scene::OverlayPlace::top_left, scene::OverlayPlace::top_right,
                           scene::OverlayPlace::bottom_left, scene::OverlayPlace::bottom_right}) {
    auto f = frame_of(physics::Case::kovalevskaya, scene::View::body, 1280, 720);
    f.page.overlay = place;
    painter_720().paint(f);
    const auto& a = painter_720().annotations();
    const auto layout = paint::layout_for(f, 1280, 720);
    ASSERT_TRUE(a.overlay_window && layout.view_3d);
    const paint::Box view = box_of(*layout.view_3d), w = *a.overlay_window;
    EXPECT_TRUE(view.contains(w)) << scene::name(place);
    const bool right =
        place == scene::OverlayPlace::top_right || place == scene::OverlayPlace::bottom_right;
    const bool bottom =
        place == scene::OverlayPlace::bottom_left || place == scene::OverlayPlace::bottom_right;
    // Against the edges of its corner: within a margin of them.
    EXPECT_LT(right ? view.max.x - w.max.x : w.min.x - view.min.x, 20.0f) << scene::name(place);
    if (bottom)
      EXPECT_GT(w.max.y, 0.5f * (view.min.y + view.max.y)) << scene::name(place);
    else
      EXPECT_LT(w.min.y - view.min.y, 20.0f) << scene::name(place);
    // The labels and the marks' key keep out of it.
    for (const auto& l : a.labels) EXPECT_FALSE(l.box.intersects(w)) << l.text;
    if (a.marks_key) {
      EXPECT_FALSE(a.marks_key->intersects(w));
    }
  }
}

}  // namespace
}  // namespace epviz
