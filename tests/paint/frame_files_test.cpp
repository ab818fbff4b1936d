// A scene's frames drawn into PNG files (with --resume's skipping of complete
// ones) or, without files, the last frame kept: compared with the same frames
// drawn one by one.
#include <gtest/gtest.h>

#include <algorithm>
#include <filesystem>
#include <vector>

#include "io/png_reader.hpp"
#include "paint/frame_files.hpp"
#include "paint/small_scene.hpp"
#include "physics/cases.hpp"
#include "support/temp_dir.hpp"

namespace epviz {
namespace {

namespace et = epviz::testing;
namespace fs = std::filesystem;

using Scene = et::SmallScene;

// Frame `index` drawn alone, through a drawer of its own.
std::vector<std::uint8_t> drawn_alone(const Scene& s, int index) {
  const int frames[] = {index};
  auto drawn = paint::draw_frames(s.plan, s.settings, frames, et::small_painter());
  EXPECT_FALSE(drawn.failure);
  return drawn.images.at(0).pixels;
}

io::ProgressOptions no_progress() {
  io::ProgressOptions o;
  o.mode = io::ProgressMode::off;
  return o;
}

std::vector<fs::path> pngs_in(const fs::path& dir) {
  std::vector<fs::path> found;
  for (const auto& e : fs::directory_iterator(dir))
    if (e.path().extension() == ".png") found.push_back(e.path());
  std::sort(found.begin(), found.end());
  return found;
}

TEST(FrameFiles, APngPerFrameOfTheRangeAndResumeRedrawsOnlyWhatIsMissing) {
  test::TempDir dir;
  const auto s = et::small_scene(physics::Case::lagrange);
  ASSERT_GE(s.plan.frames, 6);
  const paint::FrameFiles files{dir / "out", "f", std::nullopt, s.settings.fps, true};
  const auto quiet = no_progress();
  {
    paint::FrameDrawer drawer(s.plan, s.settings);
    const auto w = paint::write_frames(drawer, et::small_painter(), {2, 4}, files, quiet);
    EXPECT_EQ(w.drawn, 3);
    EXPECT_EQ(w.skipped, 0);
    EXPECT_FALSE(w.kept) << "a frame was kept although files were written";
  }
  auto written = pngs_in(dir / "out");
  ASSERT_EQ(written.size(), 3u);
  fs::remove(written[1]);  // frame 3
  paint::FrameDrawer drawer(s.plan, s.settings);
  const auto again = paint::write_frames(drawer, et::small_painter(), {2, 4}, files, quiet);
  EXPECT_EQ(again.drawn, 1);
  EXPECT_EQ(again.skipped, 2);
  ASSERT_EQ(pngs_in(dir / "out").size(), 3u);
  const auto redrawn = io::read_png_rgba(written[1]);
  ASSERT_TRUE(redrawn);
  EXPECT_EQ(redrawn->rgba, drawn_alone(s, 3)) << "the redrawn frame is not frame 3";
}

TEST(FrameFiles, WithoutFilesTheLastFrameIsKept) {
  const auto s = et::small_scene(physics::Case::lagrange);
  paint::FrameDrawer drawer(s.plan, s.settings);
  const auto w =
      paint::write_frames(drawer, et::small_painter(), {1, 3}, std::nullopt, no_progress());
  EXPECT_EQ(w.drawn, 3);
  ASSERT_TRUE(w.kept);
  EXPECT_EQ(w.kept->pixels, drawn_alone(s, 3));
  EXPECT_NE(w.kept->pixels, drawn_alone(s, 1)) << "frames 1 and 3 look alike: the check is moot";
}

}  // namespace
}  // namespace epviz
