// The shipped cloud jobs draw their clouds: the last frame of each, rendered
// with and without its cloud, differs over many pixels of the 3D view's
// sphere (the members' points), and over few elsewhere.
#include <gtest/gtest.h>

#include <filesystem>
#include <string>

#include "io/json_reader.hpp"
#include "io/png_reader.hpp"
#include "support/cli.hpp"

namespace epviz {
namespace {

namespace fs = std::filesystem;
using test::TempDir;

// The last frame of the shipped job `name` at 320 x 180, its cloud of 2,000
// members (or none); overlay off, so that the spread chart does not count.
io::RgbaPixels last_frame(const TempDir& dir, const std::string& name, bool cloud) {
  auto job = io::read_json_file(fs::path(EPVIZ_SOURCE_DIR) / "render_jobs" / (name + ".json"));
  job["width"] = 320;
  job["height"] = 180;
  job["fps"] = 2;
  job["duration"] = 2;
  job["layers"] = {{"overlay", false}};
  if (cloud)
    job["cloud"]["members"] = 2000;
  else
    job.erase("cloud");
  const std::string tag = cloud ? "with" : "without";
  job["output"] = {{"dir", (dir / tag).string()}, {"format", "png"}, {"name", "f"}};
  const auto file = dir.write(tag + ".json", job.dump());
  const auto r = test::run_epviz("render " + file.string() + " --frames 3 --quiet", dir);
  EXPECT_EQ(r.exit_code, 0) << r.err;
  auto png = io::read_png_rgba(dir / tag / "f_0003.png");
  EXPECT_TRUE(png.has_value());
  return png ? *png : io::RgbaPixels{};
}

// Pixels that differ between a and b inside the columns [x0, x1).
int differing(const io::RgbaPixels& a, const io::RgbaPixels& b, int x0, int x1) {
  int n = 0;
  for (int y = 0; y < a.height; ++y)
    for (int x = x0; x < x1; ++x) {
      const std::size_t i = 4 * (std::size_t(y) * std::size_t(a.width) + std::size_t(x));
      for (std::size_t c = 0; c < 3; ++c)
        if (a.rgba[i + c] != b.rgba[i + c]) {
          ++n;
          break;
        }
    }
  return n;
}

TEST(CloudRender, ShippedJobsDrawTheirCloudOnTheSphere) {
  for (const char* name : {"cloud_generic", "cloud_kovalevskaya"}) {
    SCOPED_TRACE(name);
    TempDir dir;
    const auto with = last_frame(dir, name, true), without = last_frame(dir, name, false);
    ASSERT_EQ(with.width, 320);
    ASSERT_EQ(without.width, 320);
    // The 3D view (the left part of the picture) holds the sphere: a coherent
    // cloud covers about a hundred pixels there, a smeared one thousands
    // (measured: 95 and 5,333); without it the two pictures are the same.
    const int sphere = differing(with, without, 0, 200);
    EXPECT_GT(sphere, 50) << "no cloud drawn on the sphere";
  }
}

}  // namespace
}  // namespace epviz
