// SVG and PDF figures: well-formed, one page of the figure's size, labels
// (Greek, sub- and superscripts) kept as text in the PDF, and, rasterised by
// poppler and librsvg, the same picture as the GL painter's PNG of the same
// spec (SSIM, since the two rasterisers antialias differently).
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "check/ssim.hpp"
#include "io/bad_input.hpp"
#include "io/png_reader.hpp"
#include "paint/figure_painter.hpp"
#include "render/render_test_support.hpp"
#include "support/temp_dir.hpp"
#include "vector/figure_format.hpp"
#include "vector/vector_figure.hpp"
#include "vector/vector_fixtures.hpp"

namespace epviz {
namespace {

namespace et = epviz::testing;
using vector::FigureFormat;

constexpr int kWidth = 640, kHeight = 400;
const paint::ChartOptions kOptions{.width = kWidth, .height = kHeight};

std::vector<std::string> labels_of(const chart::Figure& f) {
  if (const auto* c = std::get_if<chart::ChartSpec>(&f.content))
    return {c->title, c->x_label, c->y_label, c->series[0].name};
  if (const auto* h = std::get_if<chart::HeatMapSpec>(&f.content))
    return {h->title, h->x_label, h->y_label, h->value_label, h->columns[2]};
  const auto& t = std::get<chart::TableSpec>(f.content);
  return {t.title, t.header[1], t.rows[1][0]};
}

// The value of "Key:   value" in pdfinfo's output.
std::string field(const std::string& text, const std::string& key) {
  const std::string line = "\n" + text;
  const auto start = line.find("\n" + key + ":");
  if (start == std::string::npos) return "(no " + key + ")";
  auto from = start + key.size() + 2;
  const auto end = line.find('\n', from);
  while (from < end && line[from] == ' ') ++from;
  return line.substr(from, end - from);
}

class VectorFigure : public ::testing::TestWithParam<chart::Figure (*)()> {
 protected:
  void SetUp() override {
    for (const char* tool : {"pdfinfo", "pdftotext", "pdftoppm", "rsvg-convert", "python3"})
      if (!et::have_tool(tool))
        GTEST_SKIP() << tool << " is not installed (scripts/setup.sh --test installs it)";
  }
  // The GL painter's picture of the same figure, in the same font.
  render::RgbaImage gl_png(const chart::Figure& f) {
    return paint::paint_figure(et::shared_gl_context(), f, kOptions);
  }
  double ssim_with(const render::RgbaImage& gl, const std::filesystem::path& png) {
    const auto raster = io::read_png_rgba(png);
    if (!raster) {
      ADD_FAILURE() << "no raster " << png;
      return 0.0;
    }
    if (raster->width != gl.width || raster->height != gl.height) {
      ADD_FAILURE() << "raster " << raster->width << "x" << raster->height << ", PNG " << gl.width
                    << "x" << gl.height;
      return 0.0;
    }
    return check::ssim(gl.width, gl.height, gl.pixels, raster->rgba);
  }
  test::TempDir dir_;
};

TEST_P(VectorFigure, PdfIsOnePageOfTextMatchingThePng) {
  const chart::Figure figure = GetParam()();
  const auto pdf = dir_ / "figure.pdf";
  vector::write_vector_figure(pdf, figure, FigureFormat::pdf, kOptions);
  const render::RgbaImage gl = gl_png(figure);

  const auto info = et::run_tool("pdfinfo '" + pdf.string() + "'");
  ASSERT_EQ(info.exit_code, 0) << info.out;
  EXPECT_EQ(field(info.out, "Pages"), "1") << info.out;
  EXPECT_EQ(field(info.out, "Page size"),
            std::to_string(gl.width) + " x " + std::to_string(gl.height) + " pts")
      << info.out;

  const auto text = et::run_tool("pdftotext -enc UTF-8 '" + pdf.string() + "' -");
  ASSERT_EQ(text.exit_code, 0) << text.out;
  for (const auto& l : labels_of(figure))
    EXPECT_NE(text.out.find(l), std::string::npos) << "'" << l << "' not in\n" << text.out;

  // 72 dpi: a point of the page per pixel.
  const auto raster = dir_ / "pdf";
  const auto r = et::run_tool("pdftoppm -png -r 72 -singlefile '" + pdf.string() + "' '" +
                              raster.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const double ssim = ssim_with(gl, dir_ / "pdf.png");
  EXPECT_GE(ssim, 0.9);
  RecordProperty("ssim_pdf", std::to_string(ssim));
}

TEST_P(VectorFigure, SvgIsXmlMatchingThePng) {
  const chart::Figure figure = GetParam()();
  const auto svg = dir_ / "figure.svg";
  vector::write_vector_figure(svg, figure, FigureFormat::svg, kOptions);
  const auto xml = et::parse_xml(svg.string());
  EXPECT_EQ(xml.exit_code, 0) << xml.out;
  const auto png = dir_ / "svg.png";
  const auto r = et::run_tool("rsvg-convert -o '" + png.string() + "' '" + svg.string() + "'");
  ASSERT_EQ(r.exit_code, 0) << r.out;
  const double ssim = ssim_with(gl_png(figure), png);
  EXPECT_GE(ssim, 0.9);
  RecordProperty("ssim_svg", std::to_string(ssim));
}

INSTANTIATE_TEST_SUITE_P(Figures, VectorFigure,
                         ::testing::Values(&et::unicode_chart, &et::unicode_heat_map,
                                           &et::unicode_table));

// The SSIM bound above tells figures apart: a chart's PDF does not pass for
// the heat map's PNG.
TEST(VectorFigureOracle, DifferentFiguresAreFarApart) {
  if (!et::have_tool("pdftoppm")) GTEST_SKIP() << "pdftoppm is not installed";
  test::TempDir dir;
  const auto pdf = dir / "chart.pdf";
  vector::write_vector_figure(pdf, et::unicode_chart(), FigureFormat::pdf, kOptions);
  ASSERT_EQ(et::run_tool("pdftoppm -png -r 72 -singlefile '" + pdf.string() + "' '" +
                         (dir / "chart").string() + "'")
                .exit_code,
            0);
  const auto raster = io::read_png_rgba(dir / "chart.png");
  ASSERT_TRUE(raster);
  paint::ChartSpec other = std::get<chart::ChartSpec>(et::unicode_chart().content);
  other.log_y = false;  // the same data on a linear axis: another picture
  const auto gl = paint::paint_figure(et::shared_gl_context(), {"other.png", other}, kOptions);
  ASSERT_EQ(gl.width, raster->width);
  ASSERT_EQ(gl.height, raster->height);
  EXPECT_LT(check::ssim(gl.width, gl.height, gl.pixels, raster->rgba), 0.9);
}

TEST(FigureFormat, NamesAndRefusals) {
  EXPECT_EQ(vector::parse_figure_format(""), FigureFormat::png);
  EXPECT_EQ(vector::parse_figure_format("svg"), FigureFormat::svg);
  EXPECT_EQ(vector::parse_figure_format("pdf"), FigureFormat::pdf);
  EXPECT_EQ(vector::figure_file_name("drift_euler.png", FigureFormat::svg), "drift_euler.svg");
  try {
    vector::parse_figure_format("eps");
    FAIL() << "eps accepted";
  } catch (const io::BadInput& e) {
    EXPECT_STREQ(e.what(), "--format: 'eps' is not a figure format (expected png, svg or pdf)");
  }
  EXPECT_THROW(vector::vector_figure_bytes(et::unicode_table(), FigureFormat::png),
               std::invalid_argument);
}

}  // namespace
}  // namespace epviz
