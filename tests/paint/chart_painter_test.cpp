// The chart painter: a log-log chart of two known series checked pixel by
// pixel (checks that can fail) and against a reviewed golden.
#include <gtest/gtest.h>

#include <cmath>

#include "paint/chart_painter.hpp"
#include "paint/figure_fixtures.hpp"
#include "render/render_test_support.hpp"
#include "render/snapshot.hpp"

namespace epviz {
namespace {

namespace et = epviz::testing;
constexpr int W = 640, H = 400;

paint::ChartOptions test_options() { return et::builtin_font_options(W, H); }

// Whether a pixel near `at` (within r) is close to `colour`.
bool colour_near(const render::RgbaImage& img, glm::vec2 at, const glm::vec4& colour, int r = 3) {
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx) {
      const int x = int(at.x) + dx, y = int(at.y) + dy;
      if (x < 0 || y < 0 || x >= img.width || y >= img.height) continue;
      if (et::max_channel_difference(et::pixel_colour(img, x, y), colour) < 0.12f) return true;
    }
  return false;
}

int colour_count(const render::RgbaImage& img, const render::Viewport& box,
                 const glm::vec4& colour) {
  int n = 0;
  for (int y = std::max(0, box.y); y < std::min(img.height, box.y + box.height); ++y)
    for (int x = std::max(0, box.x); x < std::min(img.width, box.x + box.width); ++x)
      if (et::max_channel_difference(et::pixel_colour(img, x, y), colour) < 0.12f) ++n;
  return n;
}

// Print typography: powers of ten in superscripts, every decade alike.
TEST(ChartPainter, DecadeLabels) {
  EXPECT_EQ(paint::decade_label(-8), "10⁻⁸");
  EXPECT_EQ(paint::decade_label(0), "10⁰");
  EXPECT_EQ(paint::decade_label(3), "10³");
  EXPECT_EQ(paint::decade_label(-12), "10⁻¹²");
}

// A minus sign (U+2212) for negative numbers, not the hyphen, and no "e".
TEST(ChartPainter, NumbersInPrint) {
  EXPECT_EQ(paint::print_number(-0.25), "−0.25");
  EXPECT_EQ(paint::print_number(0.25), "0.25");
  EXPECT_EQ(paint::print_number(2.6e-5, 2), "2.6×10⁻⁵");
  EXPECT_EQ(paint::print_number(-3e7), "−3×10⁷");
  EXPECT_EQ(paint::print_number(1e-8), "10⁻⁸");
  EXPECT_EQ(paint::print_number(-1e-8), "−10⁻⁸");
  EXPECT_EQ(paint::print_scientific(2.6e-4), "2.6×10⁻⁴");
  EXPECT_EQ(paint::print_scientific(1e-15), "1.0×10⁻¹⁵");
  EXPECT_EQ(paint::print_scientific(-3.0), "−3.0×10⁰");
  EXPECT_EQ(paint::print_minus("-0.5"), "−0.5");
  EXPECT_EQ(paint::print_minus("t = -.5"), "t = −.5");
  EXPECT_EQ(paint::print_minus("Gauss-4, RK-45"), "Gauss-4, RK-45");  // hyphens in names kept
}

// Every tick label of a linear axis across zero: negative ones with the minus sign.
TEST(ChartPainter, LinearTicksUseTheMinusSign) {
  int negative = 0;
  for (const auto& t : paint::axis_ticks(-2.5, 2.5, false, 6)) {
    EXPECT_EQ(t.label.find('-'), std::string::npos) << t.label;
    if (t.at < 0.0) {
      ++negative;
      EXPECT_EQ(t.label.rfind("−", 0), 0u) << t.label;
    }
  }
  EXPECT_GE(negative, 2);
  for (const auto& t : paint::axis_ticks(-9.0, -3.0, true, 8))
    EXPECT_EQ(t.label.find('e'), std::string::npos) << t.label;
}

TEST(ChartPainter, LogLayoutCoversWholeDecades) {
  const auto spec = et::two_series();
  const auto l = paint::chart_layout(spec, W, H, et::builtin_chart_font());
  EXPECT_EQ(l.range.x_min, std::floor(l.range.x_min));
  EXPECT_EQ(l.range.y_max, std::floor(l.range.y_max));
  for (const auto& s : spec.series)
    for (const auto& p : s.points) {
      const glm::vec2 q = l.to_pixel(p.x, p.y);
      EXPECT_GE(q.x, l.plot_area.x - 0.5f);
      EXPECT_LE(q.x, l.plot_area.x + l.plot_area.width + 0.5f);
      EXPECT_GE(q.y, l.plot_area.y - 0.5f);
      EXPECT_LE(q.y, l.plot_area.y + l.plot_area.height + 0.5f);
    }
  EXPECT_TRUE(std::isnan(l.to_pixel(-1.0, 1.0).x));  // a log axis cannot show x <= 0
}

TEST(ChartPainter, SeriesAppearAtTheirPointsAndInTheLegend) {
  const auto spec = et::two_series();
  const auto img = paint::paint_chart(et::shared_gl_context(), spec, test_options());
  ASSERT_EQ(img.width, W);
  ASSERT_EQ(img.height, H);
  const auto l = paint::chart_layout(spec, W, H, et::builtin_chart_font());
  for (std::size_t i = 0; i < spec.series.size(); ++i)
    for (const auto& p : spec.series[i].points)
      EXPECT_TRUE(colour_near(img, l.to_pixel(p.x, p.y), paint::series_colour(i)))
          << "series " << i << " at " << p.x << ", " << p.y;
  // The plot area is not blank: plenty of non-white pixels.
  int ink = 0;
  for (int y = l.plot_area.y; y < l.plot_area.y + l.plot_area.height; ++y)
    for (int x = l.plot_area.x; x < l.plot_area.x + l.plot_area.width; ++x)
      if (et::luminance(et::pixel_colour(img, x, y)) < 0.8f) ++ink;
  EXPECT_GT(ink, 400);
  // The legend shows both colours, and no data runs under it.
  EXPECT_GT(colour_count(img, l.legend, paint::series_colour(0)), 10);
  EXPECT_GT(colour_count(img, l.legend, paint::series_colour(1)), 10);
  // The background is white, for papers.
  EXPECT_LT(et::max_channel_difference(et::pixel_colour(img, 2, H - 2), glm::vec4(1.0f)), 0.02f);
}

TEST(ChartPainter, MatchesTheReviewedGolden) {
  const auto img = paint::paint_chart(et::shared_gl_context(), et::two_series(), test_options());
  EXPECT_TRUE(et::matches_snapshot("chart_loglog", img.width, img.height, img.pixels));
}

// Series that share a colour key share a colour (colour by method), whatever
// their position; the keyed legend shows each colour once.
TEST(ChartPainter, SeriesWithOneColourKeyShareTheColour) {
  auto spec = et::two_series();
  spec.series[0].colour_key = 9;
  spec.series[1].colour_key = 9;
  spec.series[0].marker_key = 0;
  spec.series[1].marker_key = 1;
  spec.colour_legend = {{"rk4", 9}};
  spec.marker_legend = {{"direct", 0}, {"riccati", 1}};
  const auto img = paint::paint_chart(et::shared_gl_context(), spec, test_options());
  const auto l = paint::chart_layout(spec, W, H, et::builtin_chart_font());
  for (const auto& s : spec.series)
    for (const auto& p : s.points)
      EXPECT_TRUE(colour_near(img, l.to_pixel(p.x, p.y), paint::series_colour(9)));
  EXPECT_EQ(paint::colour_of(spec.series[1], 1), paint::series_colour(9));
  EXPECT_EQ(paint::colour_of(paint::ChartSeries{}, 4), paint::series_colour(4));
  EXPECT_GT(colour_count(img, l.legend, paint::series_colour(9)), 10);
  EXPECT_EQ(colour_count(img, l.legend, paint::series_colour(0)), 0);
}

// A series with nothing to draw (no points, or none on a log axis) has no
// legend row, nor has a key that only such series use.
TEST(ChartPainter, TheLegendNamesOnlyWhatIsDrawn) {
  auto spec = et::two_series();
  spec.series.push_back({"no points", {}});
  spec.series.push_back({"not on a log axis", {{-1.0, 1.0}, {1.0, 0.0}}});
  const auto with_empty = paint::chart_layout(spec, W, H, et::builtin_chart_font());
  const auto plain = paint::chart_layout(et::two_series(), W, H, et::builtin_chart_font());
  EXPECT_EQ(with_empty.legend.height, plain.legend.height) << "rows for series not drawn";
  const auto img = paint::paint_chart(et::shared_gl_context(), spec, test_options());
  EXPECT_EQ(colour_count(img, with_empty.legend, paint::series_colour(2)), 0);
  EXPECT_EQ(colour_count(img, with_empty.legend, paint::series_colour(3)), 0);
  EXPECT_GT(colour_count(img, with_empty.legend, paint::series_colour(1)), 10);

  // Keyed: colour 7 and marker 5 belong only to the empty series.
  spec.series[0].colour_key = spec.series[1].colour_key = 9;
  spec.series[2].colour_key = spec.series[3].colour_key = 7;
  spec.series[0].marker_key = spec.series[2].marker_key = 0;
  spec.series[1].marker_key = 1;
  spec.series[3].marker_key = 5;
  spec.colour_legend = {{"rk4", 9}, {"splitting", 7}};
  spec.marker_legend = {{"direct", 0}, {"riccati", 1}, {"spinor", 5}};
  auto shown = spec;
  shown.series.resize(2);
  shown.colour_legend.pop_back();
  shown.marker_legend.pop_back();
  EXPECT_EQ(paint::chart_layout(spec, W, H, et::builtin_chart_font()).legend.height,
            paint::chart_layout(shown, W, H, et::builtin_chart_font()).legend.height);
}

// Sixteen colours before one repeats: enough for every method of the bench
// (nine of epviz, six of the peers).
TEST(ChartPainter, PaletteColoursAreDistinct) {
  for (std::size_t i = 0; i < paint::kSeriesColours; ++i)
    for (std::size_t j = i + 1; j < paint::kSeriesColours; ++j)
      EXPECT_GT(et::max_channel_difference(paint::series_colour(i), paint::series_colour(j)), 0.1f)
          << i << " vs " << j;
}

// The last x tick label is centred on the plot's right edge: the margin
// leaves room for its right half.
TEST(ChartPainter, LastXLabelIsNotClipped) {
  paint::ChartSpec s;
  s.log_x = s.log_y = true;
  paint::ChartSeries a;
  a.name = "a";
  a.points = {{1e-3, 1.0}, {123456.0, 1e-9}};
  s.series = {a};
  const auto& font = et::builtin_chart_font();
  const auto l = paint::chart_layout(s, W, H, font);
  const float last_label_w = font.width(paint::decade_label(int(l.range.x_max)));
  EXPECT_GE(float(W - (l.plot_area.x + l.plot_area.width)), 0.5f * last_label_w);
}

}  // namespace
}  // namespace epviz
