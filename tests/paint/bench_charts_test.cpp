// Figures as `epviz bench` hands them to the painter (chart/chart_spec.hpp):
// a chart and a table each paint as a non-blank picture, and a table with more
// rows than the requested height holds is drawn taller.
#include <gtest/gtest.h>

#include <cmath>

#include "paint/chart_painter.hpp"
#include "render/render_test_support.hpp"

namespace epviz {
namespace {

constexpr paint::ChartOptions kSmall{
    .width = 480, .height = 300, .msaa_samples = 0, .builtin_font = true};

chart::Figure work_precision_figure() {
  chart::ChartSpec spec;
  spec.title = "Work-precision: euler";
  spec.x_label = "CPU time [ms]";
  spec.y_label = "error at t_end";
  spec.log_x = spec.log_y = true;
  for (const char* method : {"rk4", "dop853"}) {
    chart::ChartSeries s;
    s.name = method;
    for (int k = 0; k < 3; ++k)
      s.points.push_back({0.01 * (k + 1), std::pow(10.0, -3.0 - 2.0 * k)});
    spec.series.push_back(s);
  }
  return {"work_precision_euler.png", spec};
}

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

TEST(BenchCharts, ChartAndTableFiguresAreNotBlank) {
  auto& context = testing::shared_gl_context();
  for (const auto& figure : {work_precision_figure(), table_figure(1)}) {
    const auto img = paint::paint_figure(context, figure, kSmall);
    EXPECT_EQ(img.width, kSmall.width) << figure.file_name;
    EXPECT_EQ(img.height, kSmall.height) << figure.file_name;
    EXPECT_GT(dark_pixels(img), 200) << figure.file_name;
  }
}

TEST(BenchCharts, LongTableIsDrawnTaller) {
  auto& context = testing::shared_gl_context();
  const auto img = paint::paint_figure(context, table_figure(60), kSmall);
  EXPECT_EQ(img.width, kSmall.width);
  EXPECT_GT(img.height, kSmall.height);
  EXPECT_GT(dark_pixels(img), 200);
}

}  // namespace
}  // namespace epviz
