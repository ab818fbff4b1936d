// Writing a list of figures into a folder: the format's extension in place of
// each figure's own, GL opened only for PNG, nothing opened for no figures.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "io/png_reader.hpp"
#include "paint/figure_painter.hpp"
#include "render/render_test_support.hpp"
#include "support/temp_dir.hpp"
#include "vector/figure_files.hpp"
#include "vector/vector_fixtures.hpp"

namespace epviz {
namespace {

namespace et = epviz::testing;
using vector::FigureFormat;

const paint::ChartOptions kOptions{.width = 480, .height = 320};

// SVG and PDF need no GL: a --gl value that names no backend is never read.
TEST(FigureFiles, VectorFormatsOpenNoGl) {
  test::TempDir dir;
  const std::vector<chart::Figure> figures{et::unicode_chart(), et::unicode_heat_map()};
  const auto written =
      vector::write_figures(figures, dir.path(), FigureFormat::svg, "vulkan", kOptions);
  ASSERT_EQ(written.size(), 2u);
  EXPECT_EQ(written[0], dir / "drift.svg");
  EXPECT_EQ(written[1], dir / "atlas.svg");
  for (const auto& path : written) EXPECT_NE(test::slurp(path).find("<svg"), std::string::npos);
  EXPECT_TRUE(vector::write_figures({}, dir.path(), FigureFormat::png, "vulkan").empty());
}

TEST(FigureFiles, PngIsTheGlPaintersPicture) {
  test::TempDir dir;
  const auto figure = et::unicode_chart();
  const auto written = vector::write_figures({figure}, dir.path(), FigureFormat::png, "", kOptions);
  ASSERT_EQ(written.size(), 1u);
  EXPECT_EQ(written[0], dir / "drift.png");
  const auto expected = paint::paint_figure(et::shared_gl_context(), figure, kOptions);
  const auto image = io::read_png_rgba(written[0]);
  ASSERT_TRUE(image);
  EXPECT_EQ(image->width, expected.width);
  EXPECT_EQ(image->height, expected.height);
  EXPECT_EQ(image->rgba, expected.pixels);
}

}  // namespace
}  // namespace epviz
