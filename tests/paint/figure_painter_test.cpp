// Figures as `epviz bench` and `epviz merge` hand them to the painters
// (chart/chart_spec.hpp): a chart and a table each paint as a non-blank
// picture, a table with more rows than the requested height holds is drawn
// taller, and a heat map no taller than its grid needs.
#include <gtest/gtest.h>

#include <cmath>

#include "paint/figure_fixtures.hpp"
#include "paint/figure_painter.hpp"
#include "render/render_test_support.hpp"

namespace epviz {
namespace {

constexpr paint::ChartOptions kSmall{
    .width = 480, .height = 300, .msaa_samples = 0, .builtin_font = true};

chart::Figure work_precision_figure() { return {"work_precision.png", testing::two_series()}; }

chart::Figure table_figure(int rows) {
  chart::TableSpec t{"Stability studies", {"study", "case", "method", "result"}, {}};
  for (int i = 0; i < rows; ++i)
    t.rows.push_back({"max_step", "kovalevskaya", "rk4", "max step 0.33"});
  return {"stability.png", t};
}

// Pixels darker than mid-grey: ink on the white page.
int dark_pixels(const render::RgbaImage& img) {
  int dark = 0;
  for (int i = 0; i < img.width * img.height; ++i) dark += img.pixels[std::size_t(i) * 4] < 128;
  return dark;
}

TEST(FigurePainter, ChartAndTableFiguresAreNotBlank) {
  auto& context = testing::shared_gl_context();
  for (const auto& figure : {work_precision_figure(), table_figure(1)}) {
    const auto img = paint::paint_figure(context, figure, kSmall);
    EXPECT_EQ(img.width, kSmall.width) << figure.file_name;
    EXPECT_EQ(img.height, kSmall.height) << figure.file_name;
    EXPECT_GT(dark_pixels(img), 200) << figure.file_name;
  }
}

TEST(FigurePainter, LongTableIsDrawnTaller) {
  auto& context = testing::shared_gl_context();
  const auto img = paint::paint_figure(context, table_figure(60), kSmall);
  EXPECT_EQ(img.width, kSmall.width);
  EXPECT_GT(img.height, kSmall.height);
  EXPECT_GT(dark_pixels(img), 200);
}

chart::Figure heat_map_figure(int rows) {
  chart::HeatMapSpec h;
  h.title = "Stability";
  h.columns = {"euler", "lagrange"};
  for (int i = 0; i < rows; ++i) {
    h.rows.push_back("method " + std::to_string(i));
    h.values.push_back({0.1 * (i + 1), 1.0});
  }
  return {"stability_map.png", h};
}

// A small grid leaves no empty page under it; a large one keeps the requested
// height (its cells get lower).
TEST(FigurePainter, HeatMapIsAsTallAsItsGridNeeds) {
  auto& context = testing::shared_gl_context();
  const auto small = paint::paint_figure(context, heat_map_figure(2), kSmall);
  EXPECT_EQ(small.width, kSmall.width);
  EXPECT_LT(small.height, kSmall.height * 2 / 3);
  // The column labels under the grid are inside the picture: ink in its bottom quarter.
  int ink = 0;
  for (int y = small.height * 3 / 4; y < small.height; ++y)
    for (int x = 0; x < small.width; ++x)
      ink += small.pixels[std::size_t(y * small.width + x) * 4] < 128;
  EXPECT_GT(ink, 20);
  const auto large = paint::paint_figure(context, heat_map_figure(40), kSmall);
  EXPECT_EQ(large.height, kSmall.height);
}

}  // namespace
}  // namespace epviz
