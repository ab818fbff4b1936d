// Points a log y axis cannot show (y <= 0) are marked in a row under the plot
// and counted in a note (ChartSpec::nonpositive_label), never dropped unsaid.
// The count is the test's own; the marks are found on the pixels.
#include <gtest/gtest.h>

#include <string>

#include "paint/chart_painter.hpp"
#include "paint/figure_drawing.hpp"
#include "paint/figure_fixtures.hpp"
#include "render/render_test_support.hpp"

namespace epviz {
namespace {

namespace et = epviz::testing;
constexpr int W = 640, H = 400;

// A λ(T)-like series: negative at T = 1 and 2, zero at 4, positive after.
paint::ChartSpec lambda_chart() {
  paint::ChartSpec c;
  c.title = "test";
  c.log_x = c.log_y = true;
  c.nonpositive_label = "L <= 0";
  paint::ChartSeries s;
  s.name = "regular";
  s.points = {{1, -0.16}, {2, -0.04}, {4, 0.0}, {8, 0.03}, {16, 0.04}, {32, 0.02}};
  c.series.push_back(s);
  return c;
}

bool has_text(const paint::FigureDrawing& d, const std::string& part) {
  for (const auto& layer : d.layers)
    for (const auto& t : layer.list.labels())
      if (t.text.find(part) != std::string::npos) return true;
  return false;
}

TEST(ChartNonpositive, PointsOffTheLogAxisAreMarkedAndCounted) {
  const auto c = lambda_chart();
  const auto& font = et::builtin_chart_font();
  const auto l = paint::chart_layout(c, W, H, font);
  EXPECT_EQ(l.nonpositive_points, 3u);
  const auto& r = l.nonpositive_row;
  ASSERT_GT(r.height, 0);
  EXPECT_EQ(r.y, l.plot_area.y + l.plot_area.height) << "right under the plot";
  const auto d = paint::draw_chart(c, et::builtin_font_options(W, H), font);
  EXPECT_TRUE(has_text(d, "L <= 0")) << "the row's label";
  EXPECT_TRUE(has_text(d, "3 points not on the log axis"));

  // The series' colour in the row at T = 1, 2 and 4, nowhere else along it.
  const auto img = paint::paint_chart(et::shared_gl_context(), c, et::builtin_font_options(W, H));
  const glm::vec4 colour = paint::colour_of(c.series[0], 0);
  const int cy = r.y + r.height / 2;
  auto coloured_near = [&](int x) {
    int n = 0;
    for (int dx = -3; dx <= 3; ++dx)
      n += et::max_channel_difference(et::pixel_colour(img, x + dx, cy), colour) < 0.1f;
    return n;
  };
  for (double t : {1.0, 2.0, 4.0})
    EXPECT_GT(coloured_near(int(l.to_pixel(t, 1.0).x)), 0) << "no mark at T = " << t;
  for (double t : {8.0, 16.0, 32.0})
    EXPECT_EQ(coloured_near(int(l.to_pixel(t, 1.0).x)), 0) << "a mark at T = " << t;
}

// All positive, or a linear y axis (where y <= 0 is on the axis): no row, no note.
TEST(ChartNonpositive, NoRowWhereEveryPointIsOnTheAxis) {
  auto c = lambda_chart();
  const auto& font = et::builtin_chart_font();
  c.log_y = false;
  auto l = paint::chart_layout(c, W, H, font);
  EXPECT_EQ(l.nonpositive_points, 0u);
  EXPECT_EQ(l.nonpositive_row.height, 0);
  c = lambda_chart();
  c.series[0].points = {{1, 0.1}, {2, 0.2}};
  l = paint::chart_layout(c, W, H, font);
  EXPECT_EQ(l.nonpositive_points, 0u);
  EXPECT_FALSE(has_text(paint::draw_chart(c, et::builtin_font_options(W, H), font), "log axis"));
}

}  // namespace
}  // namespace epviz
