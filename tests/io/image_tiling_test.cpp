#include <gtest/gtest.h>

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "io/image_tiling.hpp"

namespace {

using namespace epviz::io;
using Pixel = std::array<std::uint8_t, 4>;

std::vector<std::uint8_t> solid(int w, int h, Pixel c) {
  std::vector<std::uint8_t> v(static_cast<std::size_t>(w) * h * 4);
  for (std::size_t i = 0; i < v.size(); i += 4)
    for (int k = 0; k < 4; ++k) v[i + k] = c[k];
  return v;
}

Pixel at(const TiledImage& image, int x, int y) {
  const std::size_t i = (static_cast<std::size_t>(y) * image.width + x) * 4;
  return {image.pixels[i], image.pixels[i + 1], image.pixels[i + 2], image.pixels[i + 3]};
}

// Every pixel of the grid: the tile colour inside tile rectangles, the background elsewhere.
void expect_layout(const TiledImage& image, const std::vector<Pixel>& colours, int tw, int th,
                   int cols, int gap, int margin, Pixel background) {
  for (int y = 0; y < image.height; ++y)
    for (int x = 0; x < image.width; ++x) {
      Pixel expected = background;
      const int gx = x - margin, gy = y - margin;
      if (gx >= 0 && gy >= 0) {
        const int col = gx / (tw + gap), row = gy / (th + gap);
        const bool inside = gx % (tw + gap) < tw && gy % (th + gap) < th && col < cols;
        const int index = row * cols + col;
        if (inside && index < static_cast<int>(colours.size()) && y < image.height - margin &&
            x < image.width - margin)
          expected = colours[static_cast<std::size_t>(index)];
      }
      ASSERT_EQ(at(image, x, y), expected) << "pixel (" << x << ", " << y << ")";
    }
}

TEST(ImageTiling, PlacesTilesRowMajorWithGapMarginAndBackground) {
  const int tw = 5, th = 3;
  const std::vector<Pixel> colours = {
      {255, 0, 0, 255}, {0, 255, 0, 255}, {0, 0, 255, 255}, {9, 8, 7, 6}, {1, 2, 3, 4}};
  std::vector<std::vector<std::uint8_t>> images;
  for (const auto& c : colours) images.push_back(solid(tw, th, c));
  std::vector<std::span<const std::uint8_t>> spans(images.begin(), images.end());
  TilingOptions options;
  options.cols = 3;
  options.gap = 2;
  options.margin = 1;
  options.background = {10, 20, 30, 255};
  const TiledImage image = tile_images(spans, tw, th, options);
  EXPECT_EQ(image.cols, 3);
  EXPECT_EQ(image.rows, 2);
  EXPECT_EQ(image.width, 1 + 3 * 5 + 2 * 2 + 1);
  EXPECT_EQ(image.height, 1 + 2 * 3 + 1 * 2 + 1);
  ASSERT_EQ(image.pixels.size(), static_cast<std::size_t>(image.width) * image.height * 4);
  // Spot checks with hand-computed coordinates.
  EXPECT_EQ(at(image, 0, 0), (Pixel{10, 20, 30, 255}));  // margin
  EXPECT_EQ(at(image, 1, 1), colours[0]);                // first tile's top-left
  EXPECT_EQ(at(image, 5, 3), colours[0]);                // first tile's bottom-right
  EXPECT_EQ(at(image, 6, 1), (Pixel{10, 20, 30, 255}));  // gap
  EXPECT_EQ(at(image, 8, 1), colours[1]);                // second tile starts at 1 + 5 + 2
  EXPECT_EQ(at(image, 15, 1), colours[2]);               // third at 1 + 2 * 7
  EXPECT_EQ(at(image, 1, 6), colours[3]);                // second row at 1 + 3 + 2
  EXPECT_EQ(at(image, 8, 8), colours[4]);
  EXPECT_EQ(at(image, 15, 6), (Pixel{10, 20, 30, 255}));  // empty cell
  expect_layout(image, colours, tw, th, 3, 2, 1, {10, 20, 30, 255});
}

TEST(ImageTiling, TilesAreCopiedUnchanged) {
  const int tw = 4, th = 2;
  std::vector<std::uint8_t> a(tw * th * 4), b(tw * th * 4);
  for (std::size_t i = 0; i < a.size(); ++i) {
    a[i] = static_cast<std::uint8_t>(i);
    b[i] = static_cast<std::uint8_t>(200 - i);
  }
  const std::vector<std::span<const std::uint8_t>> spans = {a, b};
  TilingOptions options;
  options.cols = 1;  // a column
  options.gap = 1;
  const TiledImage image = tile_images(spans, tw, th, options);
  ASSERT_EQ(image.width, 4);
  ASSERT_EQ(image.height, 5);
  for (int y = 0; y < th; ++y)
    for (int x = 0; x < tw; ++x)
      for (int k = 0; k < 4; ++k) {
        const std::size_t src = (static_cast<std::size_t>(y) * tw + x) * 4 + k;
        EXPECT_EQ(image.pixels[(static_cast<std::size_t>(y) * 4 + x) * 4 + k], a[src]);
        EXPECT_EQ(image.pixels[(static_cast<std::size_t>(y + 3) * 4 + x) * 4 + k], b[src]);
      }
  for (int x = 0; x < 4; ++x)
    EXPECT_EQ(at(image, x, 2), (Pixel{255, 255, 255, 255}));  // default background
}

TEST(ImageTiling, AutomaticColumnsMakeANearSquareGrid) {
  EXPECT_EQ(tiled_size(6, 10, 10).cols, 3);
  EXPECT_EQ(tiled_size(6, 10, 10).rows, 2);
  EXPECT_EQ(tiled_size(4, 10, 10).cols, 2);
  EXPECT_EQ(tiled_size(1, 10, 10).cols, 1);
  TilingOptions wide;
  wide.cols = 10;  // more columns than images: no empty columns
  const GridSize grid = tiled_size(3, 10, 7, wide);
  EXPECT_EQ(grid.cols, 3);
  EXPECT_EQ(grid.width, 30);
  EXPECT_EQ(grid.height, 7);
}

TEST(ImageTiling, BadInputIsRejected) {
  EXPECT_THROW(tiled_size(0, 10, 10), std::invalid_argument);
  EXPECT_THROW(tiled_size(2, 0, 10), std::invalid_argument);
  TilingOptions negative;
  negative.gap = -1;
  EXPECT_THROW(tiled_size(2, 10, 10, negative), std::invalid_argument);
  std::vector<std::uint8_t> good(4 * 4 * 4), bad(4 * 3 * 4);
  const std::vector<std::span<const std::uint8_t>> spans = {good, bad};
  EXPECT_THROW(tile_images(spans, 4, 4), std::invalid_argument);
}

TEST(ImageTiling, BlitClipsAtTheEdges) {
  std::vector<std::uint8_t> dst(3 * 3 * 4, 0);
  const auto src = solid(2, 2, {7, 7, 7, 7});
  blit_rgba(dst, 3, 3, src, 2, 2, 2, -1);  // only its bottom-left pixel lands, at (2, 0)
  for (int y = 0; y < 3; ++y)
    for (int x = 0; x < 3; ++x)
      EXPECT_EQ(dst[(static_cast<std::size_t>(y) * 3 + x) * 4], (x == 2 && y == 0) ? 7 : 0)
          << x << "," << y;
}

}  // namespace
