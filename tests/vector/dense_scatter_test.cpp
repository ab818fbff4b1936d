// Scatters in vector files: a few thousand dots stay vectors, one path per
// colour; a million (a Poincaré section of 1,024 orbits x 1,000 crossings)
// become one image under vector axes and text, so the file stays small, and
// rasterised it is still the GL painter's picture.
#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <cstdint>
#include <string>

#include "check/ssim.hpp"
#include "io/png_reader.hpp"
#include "paint/figure_painter.hpp"
#include "render/render_test_support.hpp"
#include "support/temp_dir.hpp"
#include "vector/cairo_painter.hpp"
#include "vector/vector_figure.hpp"
#include "vector/vector_fixtures.hpp"

namespace epviz {
namespace {

namespace et = epviz::testing;
using vector::FigureFormat;

// `orbits` scatter series of `points` dots each, in the section's style:
// half of them filling a disc at random (a chaotic sea), half on circles
// (invariant curves), one colour per series.
chart::Figure scatter(int orbits, int points, std::uint64_t seed = 88172645463325252ull) {
  chart::ChartSpec c;
  c.title = "Poincaré section (test)";
  c.x_label = "γ₁";
  c.y_label = "Ω₃";
  std::uint64_t state = seed;
  const auto uniform = [&] {  // xorshift64: the same points on every machine
    state ^= state << 13;
    state ^= state >> 7;
    state ^= state << 17;
    return double(state >> 11) * 0x1.0p-53;
  };
  for (int o = 0; o < orbits; ++o) {
    chart::ChartSeries s;
    s.style = chart::SeriesStyle::markers;
    s.marker_size = chart::MarkerSize::dot;
    s.colour_key = o;
    s.marker_key = 0;
    const double radius = 0.2 + 0.8 * double(o) / orbits;
    for (int k = 0; k < points; ++k) {
      const double a = 2.0 * M_PI * uniform(), r = o % 2 == 0 ? std::sqrt(uniform()) : radius;
      s.points.push_back({r * std::cos(a), r * std::sin(a)});
    }
    c.series.push_back(std::move(s));
  }
  c.marker_legend = {{"crossings, one colour per orbit", 0}};
  return {"scatter.png", c};
}

std::size_t count(const std::string& text, const std::string& what) {
  std::size_t n = 0;
  for (auto at = text.find(what); at != std::string::npos; at = text.find(what, at + 1)) ++n;
  return n;
}

const paint::ChartOptions kSectionSize{.width = 1100, .height = 1000, .font_px = 15.0f};

// 16 x 500 dots: below the image threshold, the dots of each series are one
// path, so the file holds tens of paths, not thousands.
TEST(DenseScatter, ThousandsOfDotsAreAPathPerColour) {
  const std::string svg = vector::vector_figure_bytes(scatter(16, 500), FigureFormat::svg);
  EXPECT_EQ(count(svg, "<image"), 0u);
  EXPECT_LT(count(svg, "<path"), 200u);
  EXPECT_LT(svg.size(), 2'000'000u);
}

// The size of a section of 1,024 orbits x 1,000 crossings: one image, the
// axes and text still vectors, in a few MB. Measured 6.2 MB (the image is
// 2078 x 1792 pixels of dots in random colours); a path per dot made 390 MB,
// and paths alone, however compact, would cost some 160 MB.
TEST(DenseScatter, AMillionDotsAreOneImageUnderVectorText) {
  const auto start = std::chrono::steady_clock::now();
  const std::string svg =
      vector::vector_figure_bytes(scatter(1024, 1000), FigureFormat::svg, kSectionSize);
  RecordProperty("svg_bytes", std::to_string(svg.size()));
  RecordProperty(
      "svg_seconds",
      std::to_string(
          std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()));
  EXPECT_LT(svg.size(), 12'000'000u);
  EXPECT_EQ(count(svg, "<image"), 1u);
  EXPECT_GT(count(svg, "<use"), 100u);  // the labels' glyphs
}

// Past the threshold the layer is an image; rasterised, the SVG is the GL
// painter's picture (the dots where the PNG has them).
TEST(DenseScatter, TheImageLayerLooksLikeThePng) {
  if (!et::have_tool("rsvg-convert")) GTEST_SKIP() << "rsvg-convert is not installed";
  const chart::Figure figure = scatter(32, 1000);
  const auto gl = paint::paint_figure(et::shared_gl_context(), figure, kSectionSize);
  test::TempDir dir;
  const auto svg = dir / "scatter.svg";
  vector::write_vector_figure(svg, figure, FigureFormat::svg, kSectionSize);
  ASSERT_EQ(count(test::slurp(svg), "<image"), 1u);
  ASSERT_EQ(
      et::run_tool("rsvg-convert -o '" + (dir / "svg.png").string() + "' '" + svg.string() + "'")
          .exit_code,
      0);
  const auto raster = io::read_png_rgba(dir / "svg.png");
  ASSERT_TRUE(raster);
  ASSERT_EQ(raster->width, gl.width);
  ASSERT_EQ(raster->height, gl.height);
  EXPECT_GE(check::ssim(gl.width, gl.height, gl.pixels, raster->rgba), 0.9);
  // The PDF holds the same one image, and its labels as text.
  if (et::have_tool("pdfimages") && et::have_tool("pdftotext")) {
    const auto pdf = dir / "scatter.pdf";
    vector::write_vector_figure(pdf, figure, FigureFormat::pdf, kSectionSize);
    const auto images = et::run_tool("pdfimages -list '" + pdf.string() + "'");
    ASSERT_EQ(images.exit_code, 0) << images.out;
    // Two header lines, the image and its alpha (a "smask").
    EXPECT_EQ(count(images.out, "\n"), 4u) << images.out;
    EXPECT_EQ(count(images.out, " smask "), 1u) << images.out;
    const auto text = et::run_tool("pdftotext -enc UTF-8 '" + pdf.string() + "' -");
    for (const char* label : {"Poincaré section (test)", "γ₁", "Ω₃", "crossings"})
      EXPECT_NE(text.out.find(label), std::string::npos) << label << " not in\n" << text.out;
  }
  // And the oracle tells scatters apart: the PNG of other random dots does not pass.
  const auto other =
      paint::paint_figure(et::shared_gl_context(), scatter(32, 1000, 12345), kSectionSize);
  EXPECT_LT(check::ssim(gl.width, gl.height, other.pixels, raster->rgba), 0.9);
}

// `list` painted by cairo on black, `width` x `height`: its pixels' red and blue.
class CairoPixels {
 public:
  CairoPixels(const render::DrawList& list, int width, int height)
      : surface_(cairo_image_surface_create(CAIRO_FORMAT_ARGB32, width, height)) {
    cairo_t* cr = cairo_create(surface_);
    cairo_set_source_rgb(cr, 0, 0, 0);
    cairo_paint(cr);
    vector::paint_shapes(cr, list);
    cairo_destroy(cr);
    cairo_surface_flush(surface_);
  }
  ~CairoPixels() { cairo_surface_destroy(surface_); }
  CairoPixels(const CairoPixels&) = delete;
  CairoPixels& operator=(const CairoPixels&) = delete;
  // ARGB32 in native byte order: blue, green, red, alpha on this machine.
  int red(int x, int y) const { return channel(x, y, 2); }
  int blue(int x, int y) const { return channel(x, y, 0); }

 private:
  int channel(int x, int y, int c) const {
    const unsigned char* data = cairo_image_surface_get_data(surface_);
    return int(data[y * cairo_image_surface_get_stride(surface_) + 4 * x + c]);
  }
  cairo_surface_t* surface_;
};

// The renderer's square dots (a cloud of states in the (a, b) panel) are
// squares of their size in a vector figure too, in their colour.
TEST(VectorDots, SquaresOfTheirSizeWhereTheRendererPutsThem) {
  render::DrawList list;
  const render::ColouredVertex dots[] = {{{10.0f, 10.0f, 0.0f}, {1, 0, 0, 1}},
                                         {{30.0f, 20.0f, 0.0f}, {0, 0, 1, 1}}};
  list.add_dots(dots, 4.0f);
  const CairoPixels p(list, 40, 30);
  int red = 0, blue = 0;
  for (int y = 0; y < 30; ++y)
    for (int x = 0; x < 40; ++x) {
      red += p.red(x, y) > 200;
      blue += p.blue(x, y) > 200;
    }
  EXPECT_EQ(red, 16);
  EXPECT_EQ(blue, 16);
  EXPECT_GT(p.red(9, 9), 200);
  EXPECT_GT(p.blue(29, 19), 200);
}

// A path coloured along its length (the (a, b) plane's trail, by time) keeps
// its colours in a vector figure: each segment blends its ends' colours, as
// the GL line shader does, rather than taking the first vertex's colour.
TEST(VectorLines, AColourAlongAPathIsBlendedAsGlDoes) {
  render::DrawList list;
  const render::LineVertex path[] = {{{0.0f, 10.0f, 0.0f}, {1, 0, 0, 1}},
                                     {{50.0f, 10.0f, 0.0f}, {1, 0, 0, 1}},
                                     {{100.0f, 10.0f, 0.0f}, {0, 0, 1, 1}}};
  list.add_polyline(path, 4.0f);
  const CairoPixels p(list, 100, 20);
  EXPECT_GT(p.red(10, 10), 240);
  EXPECT_LT(p.blue(10, 10), 15);
  EXPECT_GT(p.blue(95, 10), 220) << "the end of the path keeps its own colour";
  EXPECT_LT(p.red(95, 10), 35);
  EXPECT_NEAR(p.red(75, 10), 128, 20) << "half way along the last segment";
  EXPECT_NEAR(p.blue(75, 10), 128, 20);
}

}  // namespace
}  // namespace epviz
