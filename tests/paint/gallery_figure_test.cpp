// A gallery's figure: each scene's still, drawn through its own drawer, tiled
// into one PNG; compared with the same frames drawn one by one and tiled.
#include <gtest/gtest.h>

#include <filesystem>
#include <vector>

#include "io/png_reader.hpp"
#include "paint/frame_drawer.hpp"
#include "paint/gallery_figure.hpp"
#include "paint/small_scene.hpp"
#include "physics/cases.hpp"
#include "support/temp_dir.hpp"

namespace epviz {
namespace {

namespace et = epviz::testing;

constexpr int W = et::kSmallWidth, H = et::kSmallHeight;
using Scene = et::SmallScene;

TEST(GalleryFigure, EachStillIsItsFrameDrawnAloneInItsTile) {
  test::TempDir dir;
  const Scene scenes[] = {et::small_scene(physics::Case::lagrange),
                          et::small_scene(physics::Case::kovalevskaya)};
  const int frames[] = {2, 7};
  std::vector<paint::GalleryStill> stills;
  for (int i = 0; i < 2; ++i)
    stills.push_back({{&scenes[i].plan, &scenes[i].settings, ""}, frames[i], "tile"});
  const paint::GalleryFigure figure{dir / "gallery.png", W, H, {.cols = 2, .gap = 3, .margin = 5}};
  io::ProgressOptions quiet;
  quiet.mode = io::ProgressMode::off;
  int failures = 0;
  const auto written = paint::write_gallery_figure(stills, figure, et::small_painter(), quiet,
                                                   [&](const numerics::Failure&) { ++failures; });
  EXPECT_EQ(written.failures, 0);
  EXPECT_EQ(failures, 0);

  std::vector<render::RgbaImage> alone;
  for (int i = 0; i < 2; ++i) {
    const int one[] = {frames[i]};
    alone.push_back(paint::draw_frames(scenes[i].plan, scenes[i].settings, one, et::small_painter())
                        .images.at(0));
  }
  EXPECT_NE(alone[0].pixels, alone[1].pixels) << "the two stills look alike: the check is moot";
  const std::span<const std::uint8_t> tiles[] = {alone[0].pixels, alone[1].pixels};
  const auto expected = io::tile_images(tiles, W, H, figure.tiling);
  EXPECT_EQ(written.width, expected.width);
  EXPECT_EQ(written.height, expected.height);
  const auto png = io::read_png_rgba(figure.path);
  ASSERT_TRUE(png);
  EXPECT_EQ(png->rgba, expected.pixels) << "the figure is not the stills drawn alone, tiled";
}

}  // namespace
}  // namespace epviz
