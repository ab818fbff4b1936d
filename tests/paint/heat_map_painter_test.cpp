// The heat map painter: cells coloured by the colour map in value order,
// left to right and bottom to top as the spec lists them, and cells without
// a value grey. Checked on the pixels (checks that can fail).
#include <gtest/gtest.h>

#include <cmath>

#include "paint/heat_map_painter.hpp"
#include "render/colour_map.hpp"
#include "render/render_test_support.hpp"

namespace epviz {
namespace {

namespace et = epviz::testing;
constexpr int W = 640, H = 400;

bool near(const render::RgbaImage& img, int x, int y, const glm::vec4& c) {
  const auto* p = &img.pixels[(std::size_t(y) * img.width + x) * 4];
  for (int k = 0; k < 3; ++k)
    if (std::abs(int(p[k]) - int(std::lround(c[k] * 255.0f))) > 3) return false;
  return true;
}

// The x of the first and last pixel of row y near colour c (-1 when none).
std::pair<int, int> span_of(const render::RgbaImage& img, int y, const glm::vec4& c) {
  int first = -1, last = -1;
  for (int x = 0; x < img.width; ++x)
    if (near(img, x, y, c)) {
      if (first < 0) first = x;
      last = x;
    }
  return {first, last};
}

TEST(HeatMapPainter, CellsFollowTheirValuesAndPositions) {
  paint::HeatMapSpec s;
  s.title = "test";
  s.columns = {"a", "b", "c"};
  s.rows = {"low", "high"};
  // Bottom row: lowest, missing, highest; top row: highest, lowest, highest.
  s.values = {0.0, NAN, 10.0, 10.0, 0.0, 10.0};
  const auto img = paint::paint_heat_map(et::shared_gl_context(), s,
                                         {.width = W, .height = H, .builtin_font = true});
  ASSERT_EQ(img.width, W);
  const auto map = render::ColourMap::time();
  const glm::vec4 lowest = map(0.0f), highest = map(1.0f), grey{0.86f, 0.86f, 0.87f, 1.0f};
  // Find the bottom and top rows of cells: a row of the image through each.
  int bottom = -1, top = -1;
  for (int y = H - 1; y >= 0 && bottom < 0; --y)
    if (span_of(img, y, lowest).first >= 0 && span_of(img, y, highest).first >= 0) bottom = y;
  for (int y = 0; y < H && top < 0; ++y)
    if (span_of(img, y, lowest).first >= 0 && span_of(img, y, highest).first >= 0) top = y;
  ASSERT_GE(bottom, 0);
  ASSERT_GE(top, 0);
  ASSERT_LT(top + 20, bottom) << "the two rows of cells are not both drawn";
  const int yb = bottom - 10, yt = top + 10;
  // Bottom row: lowest on the left, highest on the right, grey between.
  const auto [bl0, bl1] = span_of(img, yb, lowest);
  const auto [bh0, bh1] = span_of(img, yb, highest);
  ASSERT_GE(bl0, 0);
  ASSERT_GE(bh0, 0);
  EXPECT_LT(bl1, bh0);
  int greys = 0;
  for (int x = bl1 + 1; x < bh0; ++x) greys += near(img, x, yb, grey);
  EXPECT_GT(greys, (bh0 - bl1) / 2) << "the missing cell is not grey";
  // Top row: the lowest cell in the middle, between two highest ones.
  const auto [tl0, tl1] = span_of(img, yt, lowest);
  const auto [th0, th1] = span_of(img, yt, highest);
  EXPECT_LT(th0, tl0);
  EXPECT_GT(th1, tl1);
  EXPECT_NEAR(double(tl0), double(bl1 + 1), 3.0);  // the middle column starts where the first ends
}

}  // namespace
}  // namespace epviz
