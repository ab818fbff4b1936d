// The cloud's spread chart as drawn into a list: one scale in every tile (a
// small share and a large one draw at different heights, between the right
// percent labels), a time axis shared when a gallery sets one, and its
// caption on its own panel, clear of the plot and of the other labels.
#include <gtest/gtest.h>

#include <algorithm>
#include <set>
#include <string>
#include <vector>

#include "paint/cloud_spread_chart.hpp"
#include "paint/fixed_width_font.hpp"
#include "scene/theme.hpp"

namespace epviz {
namespace {

// A stand-in for the font: 7 px per character, 13 px tall.
const auto& measure = epviz::testing::fixed_width_measure;

const glm::vec4 kCurve{1.0f, 0.0f, 1.0f, 1.0f};    // a colour nothing else in the chart has
const render::Viewport kTileView{0, 0, 420, 360};  // a gallery tile's 3D view

// A cloud whose spread rises from 0.1 % to `last` (a fraction) by `t_end`.
scene::CloudFrame cloud(float last, double t_end) {
  scene::CloudFrame c;
  c.members = 10000;
  c.t_end = t_end;
  for (int i = 0; i <= 20; ++i)
    c.spread.emplace_back(float(t_end * i / 20.0), 0.001f + (last - 0.001f) * float(i) / 20.0f);
  return c;
}

struct Drawn {
  render::DrawList list;
  paint::CloudSpreadBoxes boxes;
};
Drawn draw(const scene::CloudFrame& c) {
  Drawn d;
  d.boxes = paint::draw_cloud_spread_chart(d.list, kTileView, c, kCurve, scene::dark_theme(), 1.0f,
                                           measure);
  return d;
}

// The curve's vertices: those in its colour.
std::vector<glm::vec3> curve(const render::DrawList& list) {
  std::vector<glm::vec3> out;
  for (const auto& v : list.line_vertices())
    if (v.colour == kCurve) out.push_back(v.position);
  return out;
}

// A label's vertical centre, by its text.
float label_y(const render::DrawList& list, const std::string& text) {
  for (const auto& l : list.labels())
    if (l.text == text) return l.position.y;
  ADD_FAILURE() << "no label " << text;
  return 0.0f;
}

std::vector<std::string> y_labels(const render::DrawList& list) {
  std::vector<std::string> out;
  for (const auto& l : list.labels())
    if (l.anchor == render::TextAnchor::right) out.push_back(l.text);
  return out;
}

TEST(CloudSpreadChart, ASmallAndALargeShareDrawAtDifferentHeightsOnOneScale) {
  const auto small = draw(cloud(0.0079f, 60.0));
  const auto large = draw(cloud(0.79f, 60.0));
  // The same scale: the same labels at the same places.
  ASSERT_EQ(y_labels(small.list), y_labels(large.list));
  for (const auto& text : y_labels(small.list))
    EXPECT_EQ(label_y(small.list, text), label_y(large.list, text)) << text;
  const float small_y = curve(small.list).back().y, large_y = curve(large.list).back().y;
  EXPECT_LT(large_y, small_y - 20.0f);  // higher in the picture
  // Each between the labels of the decades around it (y grows downwards).
  EXPECT_GT(large_y, label_y(large.list, "100 %"));
  EXPECT_LT(large_y, label_y(large.list, "10 %"));
  EXPECT_GT(small_y, label_y(small.list, "1 %"));
  EXPECT_LT(small_y, label_y(small.list, "0.1 %"));
}

TEST(CloudSpreadChart, LabelsEveryDecadeInPercent) {
  const auto d = draw(cloud(0.5f, 60.0));
  const auto labels = y_labels(d.list);
  EXPECT_EQ(std::set<std::string>(labels.begin(), labels.end()),
            (std::set<std::string>{"0.1 %", "1 %", "10 %", "100 %"}));
}

TEST(CloudSpreadChart, AGalleryTimeAxisIsSharedByItsTiles) {
  auto shorter = cloud(0.3f, 30.0);
  auto longer = cloud(0.3f, 60.0);
  shorter.chart_t_end = longer.chart_t_end = 60.0;
  const auto a = draw(shorter), b = draw(longer);
  auto x_labels = [](const render::DrawList& list) {
    std::vector<std::string> out;
    for (const auto& l : list.labels())
      if (l.anchor == render::TextAnchor::top) out.push_back(l.text);
    return out;
  };
  EXPECT_EQ(x_labels(a.list), x_labels(b.list));
  EXPECT_EQ(x_labels(a.list).back(), "60");
  // t = 30 halfway along the plot in the shorter run's tile.
  const float mid = 0.5f * (a.boxes.plot.min.x + a.boxes.plot.max.x);
  EXPECT_NEAR(curve(a.list).back().x, mid, 1.0f);
  EXPECT_NEAR(curve(b.list).back().x, b.boxes.plot.max.x, 1.0f);
  // Without a shared axis each tile ends at its own time.
  EXPECT_NEAR(curve(draw(cloud(0.3f, 30.0)).list).back().x, a.boxes.plot.max.x, 1.0f);
}

bool inside(const paint::TextBox& inner, const paint::TextBox& outer) {
  return inner.min.x >= outer.min.x - 0.5f && inner.min.y >= outer.min.y - 0.5f &&
         inner.max.x <= outer.max.x + 0.5f && inner.max.y <= outer.max.y + 0.5f;
}

TEST(CloudSpreadChart, TheCaptionIsOnTheChartsPanelClearOfThePlotAndLabels) {
  for (const auto& view : {kTileView, render::Viewport{0, 0, 860, 720}}) {
    SCOPED_TRACE(std::to_string(view.width));
    render::DrawList list;
    const auto boxes = paint::draw_cloud_spread_chart(list, view, cloud(0.79f, 60.0), kCurve,
                                                      scene::dark_theme(), 1.0f, measure);
    const paint::TextBox whole{{float(view.x), float(view.y)},
                               {float(view.x + view.width), float(view.y + view.height)}};
    EXPECT_TRUE(inside(boxes.panel, whole));
    EXPECT_TRUE(inside(boxes.caption, boxes.panel));
    EXPECT_FALSE(boxes.caption.intersects(boxes.plot));
    // The panel is opaque: the cloud's dots under it do not show through.
    ASSERT_FALSE(list.triangles().empty());
    EXPECT_EQ(list.triangles().front().colour.a, 1.0f);
    std::vector<paint::TextBox> texts;
    for (const auto& l : list.labels()) texts.push_back(paint::text_box(l, measure(l.text)));
    for (std::size_t i = 0; i < texts.size(); ++i) {
      EXPECT_TRUE(inside(texts[i], boxes.panel)) << list.labels()[i].text;
      for (std::size_t j = i + 1; j < texts.size(); ++j)
        EXPECT_FALSE(texts[i].intersects(texts[j]))
            << list.labels()[i].text << " / " << list.labels()[j].text;
    }
  }
}

}  // namespace
}  // namespace epviz
