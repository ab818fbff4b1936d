// The section panel as the painter draws it: a dot in the run's colour at
// each crossing's place on the plot, the newest ringed in the marker's edge,
// and, for vector stills, the same dots and titles in the flat lists.
#include <gtest/gtest.h>

#include <algorithm>
#include <string>
#include <vector>

#include "paint/frame_painter.hpp"
#include "paint/preset_frame.hpp"
#include "render/panel_2d.hpp"
#include "render/render_test_support.hpp"

namespace epviz {
namespace {

namespace et = epviz::testing;
constexpr int W = 640, H = 360;

paint::FramePainter& painter() {
  static paint::FramePainter p(et::shared_gl_context(), W, H, {.builtin_font = true});
  return p;
}

const scene::Rgba kRunColour{1.0f, 0.0f, 1.0f, 1.0f};  // a magenta nothing else in the frame has

// A Kovalevskaya frame with a section panel of `n` dots on an oval, clear
// of the axis titles in the plot's corners.
scene::Frame frame_with_dots(int n) {
  scene::SceneSettings s;
  s.width = W;
  s.height = H;
  s.section = scene::SectionPanelSettings{};
  scene::Frame f = et::preset_frame(physics::Case::kovalevskaya, s);
  scene::SectionPanel p;
  p.title = "γ₃ = 0, upward";
  p.axes = {"γ₁", "Ω₁"};
  p.range = {-1.2, 1.2, 0.0, 2.0};
  p.colours = {kRunColour};
  auto& dots = p.runs.emplace_back();
  for (int k = 0; k < n; ++k) {
    const double a = 2.0 * M_PI * k / 24.0;
    dots.emplace_back(0.6 * std::cos(a), 1.0 + 0.5 * std::sin(a));
  }
  f.section = p;
  return f;
}

render::Panel2D section_plot(const scene::Frame& f) {
  const auto& r = f.section->range;
  return {paint::to_viewport(*paint::layout_for(f, W, H).section_area),
          {r[0], r[1], r[2], r[3]},
          false};
}

bool is_run_colour(const glm::vec4& c) {
  return et::max_channel_difference(c, {kRunColour[0], kRunColour[1], kRunColour[2], 1}) < 0.1f;
}

// A pixel of the run's colour within one pixel of `at` (a dot is two pixels
// wide at this height, and where it lands on the pixel grid is the rasterizer's).
bool dot_near(const render::RgbaImage& img, glm::vec2 at) {
  for (int dy = -1; dy <= 1; ++dy)
    for (int dx = -1; dx <= 1; ++dx)
      if (is_run_colour(et::pixel_colour(img, int(at.x) + dx, int(at.y) + dy))) return true;
  return false;
}

TEST(SectionPanelPaint, EachCrossingIsADotInTheRunsColourAtItsPlace) {
  const auto f = frame_with_dots(12);
  ASSERT_TRUE(paint::layout_for(f, W, H).section_area);
  const auto& img = painter().paint(f);
  const auto plot = section_plot(f);
  const auto& dots = f.section->runs.front();
  // Every dot but the newest (ringed by the marker) in the run's colour.
  for (std::size_t k = 0; k + 1 < dots.size(); ++k) {
    SCOPED_TRACE(k);
    const glm::vec2 at = plot.to_pixel({dots[k].x(), dots[k].y()});
    EXPECT_TRUE(dot_near(img, at));
  }
  // Where the 24-point circle has no crossing yet: no dot.
  for (int k = 14; k < 24; ++k) {
    const double a = 2.0 * M_PI * k / 24.0;
    const glm::vec2 at = plot.to_pixel({0.6 * std::cos(a), 1.0 + 0.5 * std::sin(a)});
    EXPECT_FALSE(dot_near(img, at)) << k;
  }
}

TEST(SectionPanelPaint, MoreCrossingsColourMorePixels) {
  auto count = [](const render::RgbaImage& img) {
    int n = 0;
    for (int y = 0; y < img.height; ++y)
      for (int x = 0; x < img.width; ++x) n += is_run_colour(et::pixel_colour(img, x, y));
    return n;
  };
  const int few = count(painter().paint(frame_with_dots(4)));
  const int more = count(painter().paint(frame_with_dots(16)));
  EXPECT_GT(few, 0);
  EXPECT_GT(more, few * 2);
}

TEST(SectionPanelPaint, VectorStillsGetTheDotsAndTitlesInTheFlatLists) {
  const auto f = frame_with_dots(9);
  std::size_t dots = 0;
  std::vector<std::string> texts;
  painter().set_flat_sink([&](const render::DrawList& list) {
    for (const auto& d : list.dots()) {
      const auto& v = list.dot_vertices()[d.first];
      if (v.colour.r > 0.9f && v.colour.g < 0.1f && v.colour.b > 0.9f) dots += d.count;
    }
    for (const auto& l : list.labels()) texts.push_back(l.text);
  });
  painter().paint(f);
  painter().set_flat_sink({});
  EXPECT_EQ(dots, 9u);
  for (const char* t : {"γ₁", "Ω₁"})
    EXPECT_NE(std::find(texts.begin(), texts.end(), t), texts.end()) << t;
  EXPECT_TRUE(std::any_of(texts.begin(), texts.end(), [](const std::string& s) {
    return s.find("γ₃ = 0, upward") != std::string::npos;
  }));
}

// The count of crossings on the sheet not drawn is written under the plot,
// clear of every dot, and only when there is one.
TEST(SectionPanelPaint, TheNoteOfTheOtherSheetIsWrittenUnderThePlot) {
  for (const bool with_note : {true, false}) {
    SCOPED_TRACE(with_note);
    auto f = frame_with_dots(9);
    if (with_note) {
      f.section->hidden = 4;
      f.section->note = "4 crossings on γ₂ < 0 not drawn";
    }
    std::vector<render::TextLabel> labels;
    painter().set_flat_sink([&](const render::DrawList& list) {
      for (const auto& l : list.labels()) labels.push_back(l);
    });
    painter().paint(f);
    painter().set_flat_sink({});
    const auto note = std::find_if(labels.begin(), labels.end(), [](const auto& l) {
      return l.text.find("not drawn") != std::string::npos;
    });
    ASSERT_EQ(note != labels.end(), with_note);
    if (!with_note) continue;
    const auto area = *paint::layout_for(f, W, H).section_area;
    EXPECT_GT(note->position.y, float(area.y + area.height)) << "below the plot";
  }
}

}  // namespace
}  // namespace epviz
