// Small multiples: a chart's panels drawn as one figure, each in its own
// cell, on axes that span every panel's points.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "paint/chart_painter.hpp"
#include "paint/figure_drawing.hpp"

namespace epviz {
namespace {

// A font measured without GL: every character 7 px wide.
const paint::ChartFont kFont{13.0f, [](const std::string& s) { return 7.0f * float(s.size()); }};

paint::ChartSpec panel(const std::string& title, double y0, double y1) {
  paint::ChartSpec p;
  p.title = title;
  p.x_label = "time";
  p.y_label = "relative drift";
  p.log_y = true;
  paint::ChartSeries s;
  s.name = title + " series";
  s.points = {{1.0, y0}, {2.0, y1}};
  p.series.push_back(s);
  return p;
}

// The labels of a drawing with their positions.
std::vector<render::TextLabel> labels(const paint::FigureDrawing& d) {
  std::vector<render::TextLabel> out;
  for (const auto& layer : d.layers)
    for (const auto& l : layer.list.labels()) out.push_back(l);
  return out;
}

TEST(SmallMultiples, AnExtentWidensTheAxes) {
  auto low = panel("low", 1e-12, 1e-11);
  const auto alone = paint::chart_layout(low, 640, 400, kFont);
  low.axis_extent = {{1.0, 1e-4}};
  const auto widened = paint::chart_layout(low, 640, 400, kFont);
  EXPECT_EQ(alone.range.y_max, -11.0);
  EXPECT_EQ(widened.range.y_max, -4.0);
  EXPECT_EQ(widened.range.y_min, alone.range.y_min);
}

TEST(SmallMultiples, PanelsStackOnSharedAxes) {
  paint::ChartSpec chart;
  chart.title = "Relative drift";
  chart.log_y = true;
  chart.panels = {panel("low", 1e-12, 1e-11), panel("high", 1e-5, 1e-4)};
  const paint::ChartOptions options{.width = 640, .height = 400};
  const auto d = paint::draw_chart(chart, options, kFont);
  EXPECT_EQ(d.width, 640);
  const auto all = labels(d);
  const auto y_of = [&](const std::string& text) {
    std::vector<float> ys;
    for (const auto& l : all)
      if (l.text == text) ys.push_back(l.position.y);
    return ys;
  };
  // One title over the panels, then each panel's title, the second below the first.
  ASSERT_EQ(y_of("Relative drift").size(), 1u);
  ASSERT_EQ(y_of("low").size(), 1u);
  ASSERT_EQ(y_of("high").size(), 1u);
  EXPECT_LT(y_of("Relative drift")[0], y_of("low")[0]);
  EXPECT_LT(y_of("low")[0], y_of("high")[0]);
  EXPECT_GE(float(d.height), y_of("high")[0] + 100.0f);
  // Both panels' y axes span 10⁻¹² to 10⁻⁴: the same decade labels in each,
  // the low panel's smallest among the high panel's.
  std::vector<std::string> first, second;
  for (const auto& l : all)
    if (l.text.rfind("10", 0) == 0)
      (l.position.y < y_of("high")[0] ? first : second).push_back(l.text);
  EXPECT_EQ(first, second);
  EXPECT_NE(std::find(second.begin(), second.end(), "10⁻¹²"), second.end());
  EXPECT_GE(second.size(), 3u);
  // The panels' own series are drawn, and nothing of the chart's own.
  std::size_t polylines = 0;
  for (const auto& layer : d.layers) polylines += layer.list.polylines().size();
  EXPECT_GT(polylines, 2u);
}

}  // namespace
}  // namespace epviz
