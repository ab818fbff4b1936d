// Heat maps whose values go beyond a fixed colour range (paint/heat_map_range.hpp),
// and sets of maps that share one plot rectangle (HeatMapSpec::margin_peers).
// The counts are those of the test's own values; marks are found on the pixels.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "paint/figure_drawing.hpp"
#include "paint/figure_fixtures.hpp"
#include "paint/heat_map_painter.hpp"
#include "render/colour_map.hpp"
#include "render/render_test_support.hpp"

namespace epviz {
namespace {

namespace et = epviz::testing;
constexpr int W = 640, H = 400;

// One row of cells on a linear map fixed to 0..0.3: two above it, one below.
paint::HeatMapSpec clipped() {
  paint::HeatMapSpec s;
  s.title = "clipped";
  s.value_label = "lambda";
  s.columns = {"a", "b", "c", "d", "e"};
  s.rows = {"only"};
  s.log_scale = false;
  s.values = {{0.1, 0.5, 0.3, 0.62, -0.2}};
  s.range_min = 0.0;
  s.range_max = 0.3;
  return s;
}

std::vector<std::string> texts(const paint::FigureDrawing& d) {
  std::vector<std::string> out;
  for (const auto& layer : d.layers)
    for (const auto& t : layer.list.labels()) out.push_back(t.text);
  return out;
}

bool has_text(const paint::FigureDrawing& d, const std::string& part) {
  for (const auto& t : texts(d))
    if (t.find(part) != std::string::npos) return true;
  return false;
}

// Pixels in the box that differ from `fill` by more than a shade.
int marks_in(const render::RgbaImage& img, int x0, int y0, int x1, int y1, const glm::vec4& fill) {
  int n = 0;
  for (int y = y0; y < y1; ++y)
    for (int x = x0; x < x1; ++x)
      n += et::max_channel_difference(et::pixel_colour(img, x, y), fill) > 0.25f;
  return n;
}

TEST(HeatMapRange, ValuesBeyondTheRangeAreCountedMarkedAndKeyed) {
  const auto s = clipped();
  const auto& font = et::builtin_chart_font();
  const auto l = paint::heat_map_layout(s, W, H, font);
  // 0.5 and 0.62 lie above 0.3 (0.3 itself does not); -0.2 below 0.
  EXPECT_EQ(l.beyond.above, 2u);
  EXPECT_EQ(l.beyond.below, 1u);
  const auto d = paint::draw_heat_map(s, et::builtin_font_options(W, H), font, false);
  EXPECT_TRUE(has_text(d, "> 0.3")) << "the colour bar's end says its bound";
  EXPECT_TRUE(has_text(d, "< 0")) << "the colour bar's end says its bound";
  EXPECT_TRUE(has_text(d, "2 cells above 0.3"));
  EXPECT_TRUE(has_text(d, "1 cell below 0"));

  // The triangle in the top right corner of a clipped cell, none in the
  // same corner of a cell inside the range, nor of the cell at the bound.
  const auto img =
      paint::paint_heat_map(et::shared_gl_context(), s, et::builtin_font_options(W, H));
  ASSERT_TRUE(l.value_text);
  auto corner = [&](std::size_t j) {
    const auto& c = l.cells[0][j];
    const glm::vec4 fill = *paint::heat_map_colour(s, l, s.values[0][j]);
    const int size = 13;  // the built-in font's size
    return marks_in(img, c.x + c.width - size - 2, c.y + 2, c.x + c.width - 2, c.y + size, fill);
  };
  EXPECT_GT(corner(1), 10) << "0.5: no mark";
  EXPECT_GT(corner(3), 10) << "0.62: no mark";
  EXPECT_GT(corner(4), 10) << "-0.2: no mark";
  EXPECT_EQ(corner(0), 0) << "0.1 is marked";
  EXPECT_EQ(corner(2), 0) << "0.3, the bound itself, is marked";

  // The bar is shortened at both ends, each end a triangle in its end colour.
  const auto& b = l.colour_bar;
  EXPECT_GT(b.y, l.grid.y);
  EXPECT_LT(b.y + b.height, l.grid.y + l.grid.height);
  const auto map = render::ColourMap::time();
  const int xm = b.x + b.width / 2;
  EXPECT_LT(et::max_channel_difference(et::pixel_colour(img, xm, b.y - 2), map(1.0f)), 0.06f);
  EXPECT_LT(et::max_channel_difference(et::pixel_colour(img, xm, b.y + b.height + 2), map(0.0f)),
            0.06f);
}

// A map whose values stay inside its range, or whose range is their own, has none of it.
TEST(HeatMapRange, NoMarksInsideTheRange) {
  auto s = clipped();
  s.values = {{0.0, 0.1, 0.2, 0.3, 0.05}};
  const auto& font = et::builtin_chart_font();
  auto l = paint::heat_map_layout(s, W, H, font);
  EXPECT_EQ(l.beyond.above + l.beyond.below, 0u);
  EXPECT_EQ(l.colour_bar.y, l.grid.y);
  EXPECT_EQ(l.colour_bar.height, l.grid.height);
  s = clipped();
  s.range_min = s.range_max = NAN;
  l = paint::heat_map_layout(s, W, H, font);
  EXPECT_EQ(l.beyond.above + l.beyond.below, 0u);
  const auto d = paint::draw_heat_map(s, et::builtin_font_options(W, H), font, false);
  EXPECT_FALSE(has_text(d, "above"));
}

// On a 64 x 64 grid (no text in the cells) a clipped cell still carries its triangle.
TEST(HeatMapRange, LargeGridMarksClippedCells) {
  paint::HeatMapSpec s;
  s.log_scale = false;
  s.range_min = 0.0;
  s.range_max = 0.3;
  for (int i = 0; i < 32; ++i) {
    s.rows.push_back(std::to_string(i));
    s.columns.push_back(std::to_string(i));
  }
  s.values.assign(32, std::vector<double>(32, 0.1));
  s.values[5][7] = 0.9;
  const auto& font = et::builtin_chart_font();
  const auto opts = et::builtin_font_options(900, 900);
  const auto l = paint::heat_map_layout(s, 900, 900, font);
  ASSERT_FALSE(l.value_text);
  EXPECT_EQ(l.beyond.above, 1u);
  const auto img = paint::paint_heat_map(et::shared_gl_context(), s, opts);
  const auto& c = l.cells[5][7];
  const glm::vec4 top = *paint::heat_map_colour(s, l, 0.9);
  EXPECT_GT(marks_in(img, c.x, c.y, c.x + c.width, c.y + c.height, top), 4);
  const auto& plain = l.cells[5][8];
  const glm::vec4 low = *paint::heat_map_colour(s, l, 0.1);
  EXPECT_EQ(marks_in(img, plain.x, plain.y, plain.x + plain.width, plain.y + plain.height, low), 0);
}

// Two maps of one sweep: different value labels, colour bar labels (linear
// 0..1 against log 1e-12..1e-6) and keys. Alone their plot rectangles
// differ; as peers they are one.
TEST(HeatMapRange, PeersShareOnePlotRectangle) {
  paint::HeatMapSpec share;
  share.value_label = "share";
  share.x_label = "x";
  share.note = "a note";
  share.log_scale = false;
  share.range_min = 0.0;
  share.range_max = 1.0;
  for (int i = 0; i < 24; ++i) {
    share.rows.push_back(std::to_string(i));
    share.columns.push_back(std::to_string(i));
    share.row_values.push_back(i);
    share.column_values.push_back(0.1 * i);
  }
  share.values.assign(24, std::vector<double>(24, 0.5));
  auto range = share;
  range.value_label = "largest relative range of the fourth integral over an orbit";
  range.log_scale = true;
  range.range_min = 1e-12;
  range.range_max = 1e-6;
  range.values.assign(24, std::vector<double>(24, 1e-9));
  range.values[3][0] = 1e-4;  // above: a key line and a bar triangle
  range.values[4][4] = NAN;   // missing: a key line on a grid without text
  const auto& font = et::builtin_chart_font();
  const int w = 1280, h = 900;
  const auto alone_a = paint::heat_map_layout(share, w, h, font);
  const auto alone_b = paint::heat_map_layout(range, w, h, font);
  ASSERT_NE(alone_a.grid.width, alone_b.grid.width) << "the test's maps differ too little";
  share.margin_peers = {range};
  range.margin_peers = {share};
  const auto a = paint::heat_map_layout(share, w, h, font);
  const auto b = paint::heat_map_layout(range, w, h, font);
  EXPECT_EQ(a.grid.x, b.grid.x);
  EXPECT_EQ(a.grid.y, b.grid.y);
  EXPECT_EQ(a.grid.width, b.grid.width);
  EXPECT_EQ(a.grid.height, b.grid.height);
  // Fitted to their grids (as files hold them) the pictures are one size too.
  const auto opts = et::builtin_font_options(w, h);
  const auto da = paint::draw_heat_map(share, opts, font, true);
  const auto db = paint::draw_heat_map(range, opts, font, true);
  EXPECT_EQ(da.height, db.height);
  // And the room is enough: each map's own needs fit within the shared one.
  EXPECT_LE(a.grid.width, std::min(alone_a.grid.width, alone_b.grid.width));
}

}  // namespace
}  // namespace epviz
