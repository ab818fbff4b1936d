// Heat maps (paint/heat_map_painter.hpp) checked on the pixels: cells
// coloured in value order at their column and row and where the layout puts
// them, cells without a value grey, the colour bar; a fixed colour range; axis
// titles; and a 64 x 64 grid whose cells carry no text and whose labels are
// thinned so they never overlap.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "paint/figure_fixtures.hpp"
#include "paint/heat_map_painter.hpp"
#include "render/colour_map.hpp"
#include "render/render_test_support.hpp"

namespace epviz {
namespace {

namespace et = epviz::testing;
constexpr int W = 640, H = 400;
constexpr float kFont = 13.0f;  // the built-in font
const glm::vec4 kMissingGrey{0.88f, 0.88f, 0.89f, 1.0f};

paint::ChartOptions options(int width = W, int height = H) {
  return et::builtin_font_options(width, height);
}

bool near(const render::RgbaImage& img, int x, int y, const glm::vec4& c) {
  return et::max_channel_difference(et::pixel_colour(img, x, y), c) < 0.015f;
}

// The x of the first and last pixel of image row y near colour c (-1 when none).
std::pair<int, int> span_of(const render::RgbaImage& img, int y, const glm::vec4& c) {
  int first = -1, last = -1;
  for (int x = 0; x < img.width; ++x)
    if (near(img, x, y, c)) {
      if (first < 0) first = x;
      last = x;
    }
  return {first, last};
}

// Dark (text) pixels in a box.
int ink_in(const render::RgbaImage& img, int x0, int y0, int x1, int y1) {
  int n = 0;
  for (int y = std::max(0, y0); y < std::min(img.height, y1); ++y)
    for (int x = std::max(0, x0); x < std::min(img.width, x1); ++x)
      n += et::luminance(et::pixel_colour(img, x, y)) < 0.5f;
  return n;
}

// Found on the pixels alone, not from the painter's layout: the ends of the
// colour map sit where the spec puts the smallest and largest values, rows
// listed top to bottom, and the cell without a value is grey.
TEST(HeatMap, CellsFollowTheirValuesAtTheirColumnAndRow) {
  paint::HeatMapSpec s;
  s.title = "test";
  s.columns = {"a", "b", "c"};
  s.rows = {"top", "bottom"};
  s.log_scale = false;
  // Top row: highest, lowest, highest; bottom row: lowest, missing, highest.
  s.values = {{10.0, 0.0, 10.0}, {0.0, NAN, 10.0}};
  const auto img = paint::paint_heat_map(et::shared_gl_context(), s, options());
  ASSERT_EQ(img.width, W);
  const auto map = render::ColourMap::time();
  const glm::vec4 lowest = map(0.0f), highest = map(1.0f);
  // An image row through each row of cells: the first and last rows of
  // pixels that hold both ends of the map.
  int top = -1, bottom = -1;
  for (int y = 0; y < H && top < 0; ++y)
    if (span_of(img, y, lowest).first >= 0 && span_of(img, y, highest).first >= 0) top = y;
  for (int y = H - 1; y >= 0 && bottom < 0; --y)
    if (span_of(img, y, lowest).first >= 0 && span_of(img, y, highest).first >= 0) bottom = y;
  ASSERT_GE(top, 0);
  ASSERT_LT(top + 20, bottom) << "the two rows of cells are not both drawn";
  // Near the cells' edges, away from the value text at their centres.
  const int yt = top + 2, yb = bottom - 2;
  // Bottom row: lowest on the left, highest on the right, grey between.
  const auto [bl0, bl1] = span_of(img, yb, lowest);
  const auto [bh0, bh1] = span_of(img, yb, highest);
  ASSERT_GE(bl0, 0);
  ASSERT_GE(bh0, 0);
  EXPECT_LT(bl1, bh0);
  int greys = 0;
  for (int x = bl1 + 1; x < bh0; ++x) greys += near(img, x, yb, kMissingGrey);
  EXPECT_GT(greys, (bh0 - bl1) / 2) << "the cell without a value is not grey";
  // Top row: the lowest cell in the middle, between two highest ones, the
  // middle column starting where the first ends (one pixel of paper apart).
  const auto [tl0, tl1] = span_of(img, yt, lowest);
  const auto [th0, th1] = span_of(img, yt, highest);
  EXPECT_LT(th0, tl0);
  EXPECT_GT(th1, tl1);
  EXPECT_NEAR(double(tl0), double(bl1 + 1), 4.0);
  EXPECT_NEAR(double(th0), double(bl0), 1.0);  // both rows start at the grid's left edge
  // The grey cell says what grey means: its text is inside it.
  EXPECT_GT(ink_in(img, bl1 + 1, top, bh0, bottom + 1), 0);
}

paint::HeatMapSpec heat_spec() {
  paint::HeatMapSpec h;
  h.title = "Stability (test)";
  h.value_label = "step / period";
  h.rows = {"rk4", "gauss4", "midpoint"};
  h.columns = {"kovalevskaya", "lagrange"};
  h.values = {{0.01, 0.1}, {1.0, std::nan("")}, {0.03, 0.3}};
  return h;
}

// Each cell has the colour of its value on the map (log scale: a decade is a
// fixed step along it), missing values are grey, and the layout fits.
TEST(HeatMap, CellsAndColourBarFollowTheLayout) {
  const auto spec = heat_spec();
  const auto img = paint::paint_heat_map(et::shared_gl_context(), spec, options());
  const auto l = paint::heat_map_layout(spec, W, H, et::builtin_chart_font());
  EXPECT_DOUBLE_EQ(l.lo, -2.0);
  EXPECT_DOUBLE_EQ(l.hi, 0.0);
  ASSERT_EQ(l.cells.size(), 3u);
  std::vector<float> lightness;
  for (std::size_t i = 0; i < 3; ++i)
    for (std::size_t j = 0; j < 2; ++j) {
      const auto& c = l.cells[i][j];
      // A corner of the cell, away from its text.
      const glm::vec4 got = et::pixel_colour(img, c.x + 3, c.y + 3);
      const auto expected = paint::heat_map_colour(spec, l, spec.values[i][j]);
      if (!expected) {
        EXPECT_LT(et::max_channel_difference(got, glm::vec4(0.88f, 0.88f, 0.89f, 1.0f)), 0.03f);
        continue;
      }
      EXPECT_LT(et::max_channel_difference(got, *expected), 0.03f) << i << "," << j;
    }
  // Larger steps are better: brighter. 0.01 < 0.03 < 0.1 < 0.3 < 1.
  const double ordered[] = {0.01, 0.03, 0.1, 0.3, 1.0};
  for (int k = 0; k + 1 < 5; ++k)
    EXPECT_LT(et::luminance(*paint::heat_map_colour(spec, l, ordered[k])),
              et::luminance(*paint::heat_map_colour(spec, l, ordered[k + 1])));
  // The ends of the map at the ends of the range.
  EXPECT_EQ(*paint::heat_map_colour(spec, l, 0.01), *paint::heat_map_colour(spec, l, 1e-5));
  // The colour bar: its top has the colour of the largest value, its bottom of the smallest.
  const auto& b = l.colour_bar;
  EXPECT_LT(et::max_channel_difference(et::pixel_colour(img, b.x + b.width / 2, b.y + 2),
                                       *paint::heat_map_colour(spec, l, 1.0)),
            0.06f);
  EXPECT_LT(et::max_channel_difference(et::pixel_colour(img, b.x + b.width / 2, b.y + b.height - 3),
                                       *paint::heat_map_colour(spec, l, 0.01)),
            0.06f);
  EXPECT_LE(b.x + b.width, W);
  EXPECT_LE(l.grid.y + l.grid.height, H);
}

// A fixed range is the colour bar's, as given: values beyond it take its end
// colours, and two maps with different values colour a value alike.
TEST(HeatMap, FixedColourRange) {
  paint::HeatMapSpec a;
  a.rows = {"r"};
  a.columns = {"x", "y", "z"};
  a.log_scale = false;
  a.values = {{0.05, 0.1, 0.2}};
  a.range_min = 0.0;
  a.range_max = 0.3;
  auto b = a;
  b.values = {{0.1, 0.4, -1.0}};
  const auto la = paint::heat_map_layout(a, W, H, et::builtin_chart_font());
  const auto lb = paint::heat_map_layout(b, W, H, et::builtin_chart_font());
  EXPECT_DOUBLE_EQ(la.lo, 0.0);
  EXPECT_DOUBLE_EQ(la.hi, 0.3);
  EXPECT_EQ(*paint::heat_map_colour(a, la, 0.1), *paint::heat_map_colour(b, lb, 0.1));
  const auto map = render::ColourMap::time();
  EXPECT_LT(et::max_channel_difference(*paint::heat_map_colour(b, lb, 0.4), map(1.0f)), 1e-6f);
  EXPECT_LT(et::max_channel_difference(*paint::heat_map_colour(b, lb, -1.0), map(0.0f)), 1e-6f);
  // A third of the way along the map for 0.1 (a linear scale).
  EXPECT_LT(et::max_channel_difference(*paint::heat_map_colour(a, la, 0.1), map(1.0f / 3.0f)),
            1e-6f);
  // Without a range: the values' own (0.05 at the map's low end).
  a.range_min = a.range_max = NAN;
  const auto own = paint::heat_map_layout(a, W, H, et::builtin_chart_font());
  EXPECT_LT(et::max_channel_difference(*paint::heat_map_colour(a, own, 0.05), map(0.0f)), 1e-6f);
  // On a log scale a fixed range is not rounded out to whole decades.
  a.log_scale = true;
  a.range_min = 0.02;
  a.range_max = 0.5;
  const auto log = paint::heat_map_layout(a, W, H, et::builtin_chart_font());
  EXPECT_NEAR(log.lo, std::log10(0.02), 1e-12);
  EXPECT_NEAR(log.hi, std::log10(0.5), 1e-12);
}

// The axis titles: x under the column labels, y over the row labels.
TEST(HeatMap, AxisTitles) {
  paint::HeatMapSpec s;
  s.rows = {"1", "2"};
  s.columns = {"1", "2", "3"};
  s.values = {{1, 2, 3}, {4, 5, 6}};
  auto titled = s;
  titled.x_label = "energy";
  titled.y_label = "a long axis title";
  auto& gl = et::shared_gl_context();
  const float line = kFont * 1.35f;
  for (const auto* spec : {&s, &titled}) {
    const auto img = paint::paint_heat_map(gl, *spec, options());
    const auto l = paint::heat_map_layout(*spec, W, H, et::builtin_chart_font());
    const int grid_bottom = l.grid.y + l.grid.height;
    // Under the column labels' line, across the grid.
    const int x_ink =
        ink_in(img, l.grid.x, grid_bottom + int(kFont * 0.5f + line), l.grid.x + l.grid.width,
               grid_bottom + int(kFont * 0.5f + 2.4f * line));
    // Left of the grid, above its top.
    const int y_ink = ink_in(img, 0, l.grid.y - int(kFont * 0.9f + line), l.grid.x, l.grid.y - 2);
    EXPECT_EQ(x_ink > 0, spec == &titled) << x_ink;
    EXPECT_EQ(y_ink > 0, spec == &titled) << y_ink;
    // The y title fits left of the grid, not off the picture.
    EXPECT_GE(float(l.grid.x) - kFont * 0.5f, et::builtin_chart_font().width(spec->y_label));
  }
}

// A 64 x 64 grid (a sweep's chaos map): cells too small for their values get
// only their colour (none of them text), the labels are thinned to a stride
// whose spacing holds a label, and a grey cell is explained by a key.
TEST(HeatMap, LargeGridHasNoCellTextAndThinnedLabels) {
  paint::HeatMapSpec s;
  s.log_scale = false;
  s.x_label = "gamma[0]";
  s.y_label = "gamma[1]";
  s.missing = "no value (a run failed)";
  constexpr int n = 64;
  for (int k = 0; k < n; ++k) {
    char buf[16];
    std::snprintf(buf, sizeof buf, "%.3g", -0.95 + 1.9 * k / (n - 1));
    s.columns.push_back(buf);
    s.rows.insert(s.rows.begin(), buf);
  }
  s.values.assign(n, std::vector<double>(n));
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) s.values[i][j] = 0.001 * (i * n + j) + 0.123456;
  s.values[5][7] = NAN;
  const int w = 1280, h = 900;
  const auto l = paint::heat_map_layout(s, w, h, et::builtin_chart_font());
  EXPECT_FALSE(l.value_text);
  EXPECT_TRUE(l.missing_key);
  ASSERT_GT(l.column_stride, 1u);
  ASSERT_GT(l.row_stride, 1u);
  float widest = 0.0f;
  for (const auto& c : s.columns) widest = std::max(widest, et::builtin_chart_font().width(c));
  const float cell_w = float(l.grid.width) / n, cell_h = float(l.grid.height) / n;
  EXPECT_GT(float(l.column_stride) * cell_w, widest);
  EXPECT_GE(float(l.row_stride) * cell_h, kFont * 1.2f);
  EXPECT_LE(l.grid.y + l.grid.height, h);

  const auto img = paint::paint_heat_map(et::shared_gl_context(), s, options(w, h));
  // Every cell holds only its colour: at its centre and across its middle row
  // of pixels (where value text would be), no other colour.
  int wrong = 0;
  for (int i = 0; i < n; ++i)
    for (int j = 0; j < n; ++j) {
      const auto& c = l.cells[i][j];
      const auto expected = paint::heat_map_colour(s, l, s.values[i][j]);
      if (!expected) continue;
      for (int x = c.x + 2; x < c.x + c.width - 2; ++x)
        if (et::max_channel_difference(et::pixel_colour(img, x, c.y + c.height / 2), *expected) >
            0.03f)
          ++wrong;
    }
  EXPECT_EQ(wrong, 0);
  // The cell without a value is grey (at its corner, off the diagonal hatch).
  const auto& m = l.cells[5][7];
  EXPECT_LT(et::max_channel_difference(et::pixel_colour(img, m.x + 2, m.y + 2), kMissingGrey),
            0.03f);
}

// Small grids keep the value text in every cell (a value's pixels inside its cell).
TEST(HeatMap, SmallGridCellsShowTheirValues) {
  paint::HeatMapSpec s;
  s.rows = {"rk4", "gauss4"};
  s.columns = {"euler", "lagrange"};
  s.values = {{0.01, 0.1}, {1.0, NAN}};
  const auto l = paint::heat_map_layout(s, W, H, et::builtin_chart_font());
  EXPECT_TRUE(l.value_text);
  EXPECT_FALSE(l.missing_key);
  EXPECT_EQ(l.column_stride, 1u);
  EXPECT_EQ(l.row_stride, 1u);
  const auto img = paint::paint_heat_map(et::shared_gl_context(), s, options());
  for (int i = 0; i < 2; ++i)
    for (int j = 0; j < 2; ++j) {
      const auto& c = l.cells[i][j];
      const glm::vec4 fill = paint::heat_map_colour(s, l, s.values[i][j]).value_or(kMissingGrey);
      int other = 0;
      for (int y = c.y + 2; y < c.y + c.height - 2; ++y)
        for (int x = c.x + 2; x < c.x + c.width - 2; ++x)
          other += et::max_channel_difference(et::pixel_colour(img, x, y), fill) > 0.2f;
      EXPECT_GT(other, 10) << "no text in cell " << i << "," << j;
    }
}

}  // namespace
}  // namespace epviz

namespace epviz {
namespace {

// Numeric axes (a sweep's atlas): the same 64 x 64 grid labelled at round
// values between the cells, a tick under (left of) the grid at each, with
// labels that keep apart; the row values run downwards, as rows are listed.
TEST(HeatMap, NumericAxesAreLabelledAtRoundValues) {
  paint::HeatMapSpec s;
  s.log_scale = false;
  constexpr int n = 64;
  for (int k = 0; k < n; ++k) {
    const double v = -0.739 + 1.651 * k / (n - 1);
    s.columns.push_back(std::to_string(v));
    s.column_values.push_back(v);
    s.rows.insert(s.rows.begin(), std::to_string(v));
    s.row_values.insert(s.row_values.begin(), v);
  }
  s.values.assign(n, std::vector<double>(n, 0.5));
  s.values[0][0] = 0.1;
  const int w = 1280, h = 900;
  const auto l = paint::heat_map_layout(s, w, h, et::builtin_chart_font());
  ASSERT_GE(l.column_ticks.size(), 3u);
  ASSERT_GE(l.row_ticks.size(), 3u);
  const float cell_w = float(l.grid.width) / n, cell_h = float(l.grid.height) / n;
  const auto& font = et::builtin_chart_font();
  for (std::size_t k = 1; k < l.column_ticks.size(); ++k) {
    const auto& a = l.column_ticks[k - 1];
    const auto& b = l.column_ticks[k];
    EXPECT_GT(float(b.position - a.position) * cell_w,
              0.5f * (font.width(a.label) + font.width(b.label)));
    EXPECT_GT(b.value, a.value);
  }
  for (std::size_t k = 1; k < l.row_ticks.size(); ++k) {
    EXPECT_GT(float(l.row_ticks[k].position - l.row_ticks[k - 1].position) * cell_h, kFont);
    EXPECT_LT(l.row_ticks[k].value, l.row_ticks[k - 1].value);  // downwards
  }
  const auto img = paint::paint_heat_map(et::shared_gl_context(), s, options(w, h));
  // A tick (a hairline, antialiased: grey rather than black) on the paper
  // next to the grid, where nothing else is drawn.
  auto marked = [&](int x0, int y0, int x1, int y1) {
    int grey = 0;
    for (int y = y0; y < y1; ++y)
      for (int x = x0; x < x1; ++x) grey += et::luminance(et::pixel_colour(img, x, y)) < 0.85f;
    return grey;
  };
  const int grid_bottom = l.grid.y + l.grid.height;
  for (const auto& t : l.column_ticks) {
    const int x = l.grid.x + int(std::lround((t.position + 0.5) * cell_w));
    EXPECT_GT(marked(x - 1, grid_bottom + 1, x + 2, grid_bottom + 3), 0) << t.label;
    EXPECT_EQ(marked(x - 6, grid_bottom + 1, x - 3, grid_bottom + 3), 0) << t.label;
  }
  for (const auto& t : l.row_ticks) {
    const int y = l.grid.y + int(std::lround((t.position + 0.5) * cell_h));
    EXPECT_GT(marked(l.grid.x - 3, y - 1, l.grid.x - 1, y + 2), 0) << t.label;
  }
  // An axis of names keeps its labels (no ticks).
  auto names = s;
  names.column_values.clear();
  names.row_values.clear();
  const auto ln = paint::heat_map_layout(names, w, h, font);
  EXPECT_TRUE(ln.column_ticks.empty());
  EXPECT_TRUE(ln.row_ticks.empty());
}

}  // namespace
}  // namespace epviz

namespace epviz {
namespace {

// A cell whose value could not be decided is hatched, not grey like a cell
// without a value, and says so in the cell and in a key under the grid.
TEST(HeatMap, UndecidedCellsAreHatchedAndLabelled) {
  paint::HeatMapSpec s;
  s.title = "test";
  s.columns = {"a", "b", "c"};
  s.rows = {"only"};
  s.log_scale = false;
  s.values = {{1.0, NAN, NAN}};  // b: no value; c: undecided
  s.undecided = {{false, false, true}};
  s.undecided_label = "not decided";
  const auto l = paint::heat_map_layout(s, W, H, et::builtin_chart_font());
  ASSERT_TRUE(l.value_text);
  EXPECT_TRUE(l.undecided_key);
  const auto drawing = paint::draw_heat_map(s, options(), et::builtin_chart_font(), false);
  int labels = 0;
  for (const auto& layer : drawing.layers)
    for (const auto& t : layer.list.labels()) labels += t.text == "not decided";
  EXPECT_EQ(labels, 2) << "in the cell and in the key";

  const auto img = paint::paint_heat_map(et::shared_gl_context(), s, options());
  const glm::vec4 stripe{0.62f, 0.62f, 0.64f, 1.0f};
  // A row of pixels near the top edge of the cells, away from their text.
  const auto& missing = l.cells[0][1];
  const auto& hatched = l.cells[0][2];
  const int y = missing.y + 3;
  int stripes_missing = 0, greys_missing = 0, stripes_hatched = 0, greys_hatched = 0;
  for (int x = missing.x + 2; x < missing.x + missing.width - 2; ++x) {
    stripes_missing += near(img, x, y, stripe);
    greys_missing += near(img, x, y, kMissingGrey);
  }
  for (int x = hatched.x + 2; x < hatched.x + hatched.width - 2; ++x) {
    stripes_hatched += et::max_channel_difference(et::pixel_colour(img, x, y), stripe) < 0.15f;
    greys_hatched += near(img, x, y, kMissingGrey);
  }
  EXPECT_EQ(stripes_missing, 0);
  EXPECT_GT(greys_missing, missing.width / 2);
  EXPECT_GE(stripes_hatched, hatched.width / 20) << "no stripes across the undecided cell";
  EXPECT_LT(greys_hatched, hatched.width / 4) << "the undecided cell is grey like a missing one";
}

}  // namespace
}  // namespace epviz
