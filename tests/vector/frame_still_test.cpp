// Stills of a scene's frames as vector figures (`epviz render --format
// svg|pdf`): one page of the frame's size, its text as text, one embedded
// raster (the 3D view), and rasterised by poppler and librsvg the same
// picture as the PNG of the same frame (SSIM), also part by part (the overlay
// window, the plane's panel), so that a part left out or misplaced shows.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

#include "check/ssim.hpp"
#include "io/png_reader.hpp"
#include "paint/frame_drawer.hpp"
#include "paint/frame_painter.hpp"
#include "physics/cases.hpp"
#include "render/render_test_support.hpp"
#include "scene/plan.hpp"
#include "sim/run_spec.hpp"
#include "support/cli.hpp"
#include "support/render_job.hpp"
#include "support/temp_dir.hpp"
#include "vector/frame_still.hpp"
#include "vector/vector_fixtures.hpp"

namespace epviz {
namespace {

namespace et = epviz::testing;
namespace fs = std::filesystem;
using vector::FigureFormat;

bool have_tools() {
  for (const char* tool : {"pdfinfo", "pdftotext", "pdftoppm", "pdfimages", "rsvg-convert"})
    if (!et::have_tool(tool)) return false;
  return true;
}

// The part `r` of an RGBA image (x, y, width, height in pixels).
struct Part {
  int x = 0, y = 0, width = 0, height = 0;
};
std::vector<std::uint8_t> crop(const render::RgbaImage& image, const Part& r) {
  std::vector<std::uint8_t> out;
  for (int y = r.y; y < r.y + r.height; ++y) {
    const auto* row = image.pixels.data() + (std::size_t(y) * std::size_t(image.width)) * 4;
    out.insert(out.end(), row + std::size_t(r.x) * 4, row + std::size_t(r.x + r.width) * 4);
  }
  return out;
}
double ssim_of(const render::RgbaImage& a, const render::RgbaImage& b, const Part& r) {
  return check::ssim(r.width, r.height, crop(a, r), crop(b, r));
}
double ssim_of(const render::RgbaImage& a, const render::RgbaImage& b) {
  return ssim_of(a, b, {0, 0, a.width, a.height});
}

// A vector file rasterised at one pixel per unit, read back (empty on failure).
render::RgbaImage rasterise(const fs::path& file, const test::TempDir& dir) {
  const std::string root = (dir / (file.filename().string() + ".raster")).string();
  const std::string command =
      file.extension() == ".pdf"
          ? "pdftoppm -png -r 72 -singlefile '" + file.string() + "' '" + root + "'"
          : "rsvg-convert -o '" + root + ".png' '" + file.string() + "'";
  const auto run = et::run_tool(command);
  EXPECT_EQ(run.exit_code, 0) << command << "\n" << run.out;
  const auto read = io::read_png_rgba(root + ".png");
  if (!read) return {};
  return {read->width, read->height, read->rgba};
}

// The value of "Key:   value" in pdfinfo's output.
std::string field(const std::string& text, const std::string& key) {
  const auto at = ("\n" + text).find("\n" + key + ":");
  if (at == std::string::npos) return "(no " + key + ")";
  auto from = at + key.size() + 1;
  while (from < text.size() && text[from] == ' ') ++from;
  return text.substr(from, text.find('\n', from) - from);
}

// A shipped comparison job (three runs: legend, separation chart, drift
// table) drawn at 640 x 360 as PNG, PDF and SVG of the same frame.
class StillCommand : public ::testing::Test {
 protected:
  void SetUp() override {
    if (!have_tools())
      GTEST_SKIP() << "poppler-utils or librsvg2-bin missing (scripts/setup.sh --test)";
    for (const char* format : {"png", "pdf", "svg"}) {
      const auto r = test::run_epviz(std::string("render compare_methods --frames 30 --width 640 "
                                                 "--height 360 --quiet --format ") +
                                         format + " --out " + dir_.path().string(),
                                     dir_);
      ASSERT_EQ(r.exit_code, 0) << r.err;
    }
    const auto png = io::read_png_rgba(dir_ / "compare_methods_0030.png");
    ASSERT_TRUE(png);
    png_ = {png->width, png->height, png->rgba};
  }
  test::TempDir dir_;
  render::RgbaImage png_;
};

TEST_F(StillCommand, PdfIsOnePageOfTextWithTheViewAsItsOneImage) {
  const auto pdf = (dir_ / "compare_methods_0030.pdf").string();
  const auto info = et::run_tool("pdfinfo '" + pdf + "'");
  EXPECT_EQ(field(info.out, "Pages"), "1") << info.out;
  EXPECT_EQ(field(info.out, "Page size"), "640 x 360 pts") << info.out;
  // Text from every part: the overlay window (the job's title, the drift in
  // one line at this size, of the drawn states), the 3D view's labels and
  // key, the plane's panel and the legend.
  const auto text = et::run_tool("pdftotext -enc UTF-8 '" + pdf + "' -").out;
  for (const char* expected :
       {"Kovalevskaya top: three integrators", "t = ", "drift", "drawn", "|γ|²", "fixed point",
        "e2", "equator", "Riccati", "reference: dop853", "against t"})
    EXPECT_NE(text.find(expected), std::string::npos) << expected << " not in:\n" << text;
  // One raster, the 3D view's pixels: pdfimages lists it after two header lines.
  const auto images = et::run_tool("pdfimages -list '" + pdf + "'").out;
  EXPECT_EQ(std::count(images.begin(), images.end(), '\n'), 3) << images;
}

TEST_F(StillCommand, SvgIsXml) {
  const auto xml = et::parse_xml((dir_ / "compare_methods_0030.svg").string());
  EXPECT_EQ(xml.exit_code, 0) << xml.out;
}

TEST_F(StillCommand, RasterisedTheyLookLikeThePng) {
  for (const char* name : {"compare_methods_0030.pdf", "compare_methods_0030.svg"}) {
    const auto raster = rasterise(dir_ / name, dir_);
    ASSERT_EQ(raster.width, png_.width) << name;
    ASSERT_EQ(raster.height, png_.height) << name;
    const double s = ssim_of(png_, raster);
    EXPECT_GE(s, 0.9) << name;
    RecordProperty(name, std::to_string(s));
  }
}

// Without --frames a still is of the job's last frame; with them, one file a frame.
TEST(StillFrames, LastFrameOrTheRangeGiven) {
  test::TempDir dir;
  const auto job = dir.write("job.json", test::small_render_job(dir / "out").dump());
  ASSERT_EQ(test::run_epviz("render " + job.string() + " --quiet --format svg", dir).exit_code, 0);
  std::vector<std::string> names;
  for (const auto& e : fs::directory_iterator(dir / "out")) names.push_back(e.path().filename());
  EXPECT_EQ(names, std::vector<std::string>{"frame_0005.svg"});  // 3 fps x 2 s: frames 0..5
  ASSERT_EQ(test::run_epviz("render " + job.string() + " --quiet --format pdf --frames 1:2", dir)
                .exit_code,
            0);
  EXPECT_TRUE(fs::exists(dir / "out" / "frame_0001.pdf"));
  EXPECT_TRUE(fs::exists(dir / "out" / "frame_0002.pdf"));
  EXPECT_FALSE(fs::exists(dir / "out" / "frame_0005.pdf"));
}

class StillRefused : public ::testing::TestWithParam<test::RefusedCase> {};

TEST_P(StillRefused, BeforeAnyWork) {
  test::TempDir dir;
  const auto& c = GetParam();
  const auto out = dir / "out";
  test::expect_render_refused(dir, test::small_render_job(out).dump(), c.args, out, c.must_name);
}

INSTANTIATE_TEST_SUITE_P(
    Cases, StillRefused,
    ::testing::Values(test::RefusedCase{"Resume", "--format pdf --resume", "--resume"},
                      test::RefusedCase{"Shard", "--format svg --shard 0/2", "--shard"},
                      test::RefusedCase{"UnknownFormat", "--format eps",
                                        "(allowed: png, mp4, webm, gif, svg, pdf)"}),
    test::case_name);

TEST(StillRefusedGallery, NamesTheFormat) {
  test::TempDir dir;
  const auto out = dir / "out";
  const auto r = test::run_epviz("render gallery --format pdf --out " + out.string(), dir);
  test::expect_bad_input(r, "--format pdf");
  EXPECT_FALSE(fs::exists(out));
}

// The painter's own frame, part by part: the still's overlay window (its
// title in Greek letters and subscripts, as text) and the plane's panel are
// where the PNG has them and look the same, and the painter draws whole PNGs
// again afterwards.
TEST(FrameStill, PartsMatchThePainterAndThePainterIsLeftAsItWas) {
  if (!have_tools()) GTEST_SKIP() << "poppler-utils or librsvg2-bin missing";
  test::TempDir dir;
  scene::SceneSettings settings;
  settings.width = 720;
  settings.height = 480;  // from 480 rows the overlay shows all its lines
  settings.fps = 10;
  settings.duration = 1;
  const auto plan = scene::plan_scene(sim::preset_run(physics::Case::generic, sim::Method::dop853,
                                                      sim::Formulation::direct, 4.0, 100),
                                      settings);
  paint::FramePainter painter(et::shared_gl_context(), settings.width, settings.height);
  paint::FrameDrawer drawer(plan, settings);
  scene::Frame frame = drawer.frame(7);
  frame.overlay.title = "Heavy top: γ₁ and Ω₃";  // symbols stay text in a PDF
  const render::RgbaImage png = painter.paint(frame);
  const auto annotations = painter.annotations();
  ASSERT_TRUE(annotations.overlay_window);

  const auto pdf = dir / "still.pdf";
  {
    std::ofstream(pdf, std::ios::binary)
        << vector::frame_still_bytes(painter, frame, FigureFormat::pdf);
  }
  EXPECT_EQ(painter.paint(frame).pixels, png.pixels) << "the painter was left drawing stills";
  const auto text = et::run_tool("pdftotext -enc UTF-8 '" + pdf.string() + "' -").out;
  EXPECT_NE(text.find("Heavy top: γ₁ and Ω₃"), std::string::npos) << text;
  const auto raster = rasterise(pdf, dir);
  ASSERT_EQ(raster.width, png.width);
  ASSERT_EQ(raster.height, png.height);

  const paint::Box& w = *annotations.overlay_window;
  const Part window{int(w.min.x), int(w.min.y), int(w.width()), int(w.height())};
  const double window_ssim = ssim_of(png, raster, window);
  EXPECT_GE(window_ssim, 0.9);
  const auto layout = paint::layout_for(frame, png.width, png.height);
  ASSERT_TRUE(layout.panel_column);
  const auto& c = *layout.panel_column;
  const double panel_ssim = ssim_of(png, raster, {c.x, c.y, c.width, c.height});
  EXPECT_GE(panel_ssim, 0.9);
  RecordProperty("ssim_window", std::to_string(window_ssim));
  RecordProperty("ssim_panel", std::to_string(panel_ssim));

  EXPECT_THROW(vector::frame_still_bytes(painter, frame, FigureFormat::png), std::invalid_argument);
}

}  // namespace
}  // namespace epviz
