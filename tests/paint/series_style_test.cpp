// A series' style: a scatter (`markers`) puts a marker at every point, however
// many, and joins none; a `line` has no markers; the legend's row of each
// shows what it draws. Checked in the drawing (what both painters paint) and
// in the GL painter's pixels.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>

#include "paint/chart_painter.hpp"
#include "paint/figure_drawing.hpp"
#include "paint/figure_fixtures.hpp"
#include "render/render_test_support.hpp"

namespace epviz {
namespace {

namespace et = epviz::testing;
using chart::MarkerSize;
using chart::SeriesStyle;
constexpr int W = 640, H = 400;

// `n` points on one period of a sine, x from 0 to 1.
paint::ChartSeries sine(const std::string& name, int n, double phase, SeriesStyle style) {
  paint::ChartSeries s;
  s.name = name;
  s.style = style;
  for (int i = 0; i < n; ++i) {
    const double x = double(i) / (n - 1);
    s.points.push_back({x, std::sin(2.0 * M_PI * x + phase)});
  }
  return s;
}

// The drawing's layers, as draw_chart makes them.
struct Layers {
  paint::FigureDrawing drawing;
  const render::DrawList& lines() const { return drawing.layers.at(1).list; }
  const render::DrawList& markers() const { return drawing.layers.at(2).list; }
  const render::DrawList& legend() const { return drawing.layers.at(3).list; }
};
Layers draw(const paint::ChartSpec& spec) {
  return {paint::draw_chart(spec, et::builtin_font_options(W, H), et::builtin_chart_font())};
}

std::size_t markers_of(const render::DrawList& list, const glm::vec4& colour) {
  std::size_t n = 0;
  for (const auto& m : list.markers()) n += m.fill == colour;
  return n;
}
std::size_t lines_of(const render::DrawList& list, const glm::vec4& colour) {
  std::size_t n = 0;
  for (const auto& p : list.polylines()) n += list.line_vertices()[p.first].colour == colour;
  return n;
}

// Whether a pixel within `r` of `at` has `colour`.
bool is_colour(const render::RgbaImage& img, glm::vec2 at, const glm::vec4& colour, int r = 0) {
  for (int dy = -r; dy <= r; ++dy)
    for (int dx = -r; dx <= r; ++dx)
      if (et::max_channel_difference(et::pixel_colour(img, int(at.x) + dx, int(at.y) + dy),
                                     colour) < 0.12f)
        return true;
  return false;
}

// 80 points (past the 60 where a line's markers thin out to a dozen): a
// marker at each, no line; between two neighbours, 7 pixels apart, paper.
TEST(SeriesStyle, AScatterMarksEveryPointAndJoinsNone) {
  paint::ChartSpec spec;
  spec.series = {sine("scatter", 80, 0.0, SeriesStyle::markers)};
  spec.series[0].marker_size = MarkerSize::dot;
  const glm::vec4 colour = paint::series_colour(0);
  const Layers d = draw(spec);
  EXPECT_EQ(markers_of(d.markers(), colour), 80u);
  EXPECT_EQ(d.lines().polylines().size(), 0u);

  const auto img =
      paint::paint_chart(et::shared_gl_context(), spec, et::builtin_font_options(W, H));
  const auto l = paint::chart_layout(spec, W, H, et::builtin_chart_font());
  int dots = 0, gaps = 0;
  const auto& p = spec.series[0].points;
  for (std::size_t i = 0; i < p.size(); ++i) {
    const glm::vec2 at = l.to_pixel(p[i].x, p[i].y);
    dots += is_colour(img, at, colour);
    if (i + 1 == p.size()) break;
    const glm::vec2 next = l.to_pixel(p[i + 1].x, p[i + 1].y);
    ASSERT_GT(glm::length(next - at), 6.0f);
    gaps += et::luminance(et::pixel_colour(img, int((at.x + next.x) * 0.5f),
                                           int((at.y + next.y) * 0.5f))) > 0.9f;
  }
  EXPECT_EQ(dots, 80);
  EXPECT_GE(gaps, 76);  // a gridline may cross a gap
}

// The default style draws the same points as a line with about a dozen
// markers, evenly spaced.
TEST(SeriesStyle, ALongLineHasADozenMarkers) {
  paint::ChartSpec spec;
  spec.series = {sine("line", 80, 0.0, SeriesStyle::lines_and_markers)};
  const Layers d = draw(spec);
  EXPECT_GE(markers_of(d.markers(), paint::series_colour(0)), 10u);
  EXPECT_LE(markers_of(d.markers(), paint::series_colour(0)), 12u);
  EXPECT_EQ(lines_of(d.lines(), paint::series_colour(0)), 1u);
}

// A `line` has its line and no marker, short or long.
TEST(SeriesStyle, ALineHasNoMarkers) {
  for (const int n : {10, 80}) {
    paint::ChartSpec spec;
    spec.series = {sine("guide", n, 0.0, SeriesStyle::line)};
    const glm::vec4 colour = paint::series_colour(0);
    const Layers d = draw(spec);
    EXPECT_EQ(d.markers().markers().size(), 0u) << n;
    EXPECT_EQ(d.markers().triangles().size(), 0u) << n;
    EXPECT_EQ(lines_of(d.lines(), colour), 1u) << n;
    // Drawn: the line passes half-way between its points.
    const auto img =
        paint::paint_chart(et::shared_gl_context(), spec, et::builtin_font_options(W, H));
    const auto l = paint::chart_layout(spec, W, H, et::builtin_chart_font());
    const auto& p = spec.series[0].points;
    int on_line = 0;
    for (std::size_t i = 0; i + 1 < p.size(); ++i)
      on_line += is_colour(
          img, (l.to_pixel(p[i].x, p[i].y) + l.to_pixel(p[i + 1].x, p[i + 1].y)) * 0.5f, colour, 1);
    EXPECT_GE(on_line, int(p.size()) - 3) << n;
  }
}

// A row per series, each showing what its series draws: a line and a marker,
// a marker alone (at the series' size), a line alone.
TEST(SeriesStyle, LegendRowsShowWhatIsDrawn) {
  paint::ChartSpec spec;
  spec.series = {sine("both", 20, 0.0, SeriesStyle::lines_and_markers),
                 sine("scatter", 20, 2.0, SeriesStyle::markers),
                 sine("guide", 20, 4.0, SeriesStyle::line)};
  spec.series[1].marker_size = MarkerSize::dot;
  const Layers d = draw(spec);
  const auto& legend = d.legend();
  EXPECT_EQ(lines_of(legend, paint::series_colour(0)), 1u);
  EXPECT_EQ(markers_of(legend, paint::series_colour(0)), 1u);
  EXPECT_EQ(lines_of(legend, paint::series_colour(1)), 0u);
  EXPECT_EQ(markers_of(legend, paint::series_colour(2)), 0u);
  EXPECT_EQ(lines_of(legend, paint::series_colour(2)), 1u);
  // The scatter's legend marker is a dot like its points (series 1 is a
  // square: its shape is two triangles, no outline).
  const auto& tris = legend.triangles();
  std::size_t dot_vertices = 0;
  for (const auto& v : tris) dot_vertices += v.colour == paint::series_colour(1);
  EXPECT_EQ(dot_vertices, 6u);
  std::size_t outlines = 0;
  for (const auto& p : legend.polylines())
    outlines += p.closed && legend.line_vertices()[p.first].colour.a == 1.0f &&
                legend.line_vertices()[p.first].colour != paint::series_colour(0);
  EXPECT_EQ(outlines, 0u);

  // In pixels: left of the scatter's marker, where a line sample would
  // start, the legend is paper; the same place in the line's row is not.
  const auto img =
      paint::paint_chart(et::shared_gl_context(), spec, et::builtin_font_options(W, H));
  const float font_px = et::builtin_chart_font().px;
  glm::vec2 scatter_marker{};
  for (const auto& v : tris)
    if (v.colour == paint::series_colour(1)) scatter_marker += glm::vec2(v.position) / 6.0f;
  EXPECT_TRUE(is_colour(img, scatter_marker, paint::series_colour(1)));
  EXPECT_GT(
      et::luminance(et::pixel_colour(img, int(scatter_marker.x - font_px), int(scatter_marker.y))),
      0.9f);
  const auto guide_line =
      legend.line_vertices()
          [std::find_if(legend.polylines().begin(), legend.polylines().end(), [&](const auto& p) {
             return legend.line_vertices()[p.first].colour == paint::series_colour(2);
           })->first];
  EXPECT_TRUE(is_colour(img, glm::vec2(guide_line.position) + glm::vec2(2.0f, 0.0f),
                        paint::series_colour(2), 1));
}

// A keyed legend: a colour whose series draw only markers shows a marker,
// not a line; a marker key only line series use has no row.
TEST(SeriesStyle, KeyedLegendRowsShowWhatIsDrawn) {
  paint::ChartSpec spec;
  spec.series = {sine("a", 20, 0.0, SeriesStyle::markers), sine("b", 20, 2.0, SeriesStyle::line)};
  spec.series[0].colour_key = 5;
  spec.series[0].marker_key = 0;
  spec.series[1].colour_key = 6;
  spec.series[1].marker_key = 1;
  spec.colour_legend = {{"orbits", 5}, {"guide", 6}};
  spec.marker_legend = {{"crossings", 0}, {"never drawn", 1}};
  const Layers d = draw(spec);
  const auto& legend = d.legend();
  EXPECT_EQ(lines_of(legend, paint::series_colour(5)), 0u);
  EXPECT_EQ(markers_of(legend, paint::series_colour(5)), 1u);
  EXPECT_EQ(lines_of(legend, paint::series_colour(6)), 1u);
  // Three rows (two colours, one marker), not four.
  auto three = spec;
  three.marker_legend.pop_back();
  auto two = three;
  two.marker_legend.clear();
  const auto& font = et::builtin_chart_font();
  const int h3 = paint::chart_layout(three, W, H, font).legend.height;
  EXPECT_EQ(paint::chart_layout(spec, W, H, font).legend.height, h3);
  EXPECT_GT(h3, paint::chart_layout(two, W, H, font).legend.height);
}

}  // namespace
}  // namespace epviz
