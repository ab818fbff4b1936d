// check::compare_pixels and check::diff_image: the threshold is exclusive,
// every channel (alpha too) counts, and the diff marks exactly the pixels counted.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "check/image_compare.hpp"

namespace epviz::check {
namespace {

std::vector<std::uint8_t> flat(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  std::vector<std::uint8_t> v(std::size_t(w) * h * 4);
  for (std::size_t p = 0; p < v.size() / 4; ++p) {
    v[p * 4] = r;
    v[p * 4 + 1] = g;
    v[p * 4 + 2] = b;
    v[p * 4 + 3] = 255;
  }
  return v;
}

TEST(ComparePixels, ThresholdIsTheLargestDifferenceThatCountsAsEqual) {
  const auto golden = flat(4, 2, 100, 100, 100);
  auto actual = golden;
  actual[0 * 4 + 0] = 104;  // difference 4: equal at threshold 4
  actual[1 * 4 + 1] = 95;   // difference 5: differs
  actual[2 * 4 + 3] = 250;  // alpha differs by 5
  const auto c = compare_pixels(4, 2, actual, golden, 4);
  EXPECT_EQ(c.pixels, 8u);
  EXPECT_EQ(c.pixels_differing, 2u);
  EXPECT_EQ(c.largest_channel_difference, 5);
  EXPECT_DOUBLE_EQ(c.fraction_differing(), 2.0 / 8.0);
  EXPECT_EQ(compare_pixels(4, 2, actual, golden, 3).pixels_differing, 3u);
  EXPECT_EQ(compare_pixels(4, 2, actual, golden, 5).pixels_differing, 0u);
}

TEST(ComparePixels, IdenticalImagesDoNotDiffer) {
  const auto a = flat(3, 3, 1, 2, 3);
  const auto c = compare_pixels(3, 3, a, a, 0);
  EXPECT_EQ(c.pixels_differing, 0u);
  EXPECT_EQ(c.largest_channel_difference, 0);
}

TEST(ComparePixels, RejectsBuffersOfTheWrongSize) {
  const auto a = flat(3, 3, 1, 2, 3), b = flat(3, 2, 1, 2, 3);
  EXPECT_THROW(compare_pixels(3, 3, a, b, 4), std::invalid_argument);
  EXPECT_THROW(diff_image(3, 3, b, a, 4), std::invalid_argument);
}

TEST(DiffImage, DifferingPixelsRedOverADimmedGolden) {
  const auto golden = flat(2, 1, 200, 100, 0);
  auto actual = golden;
  actual[4] = 0;  // second pixel: red channel differs by 200
  const auto d = diff_image(2, 1, actual, golden, 4);
  ASSERT_EQ(d.size(), 8u);
  // First pixel: the golden's grey level (100) at a quarter.
  EXPECT_EQ(d[0], 25);
  EXPECT_EQ(d[1], 25);
  EXPECT_EQ(d[2], 25);
  EXPECT_EQ(d[3], 255);
  // Second pixel: red, brighter for a larger difference.
  EXPECT_EQ(d[4], 255);
  EXPECT_EQ(d[5], 0);
  EXPECT_EQ(d[6], 0);
  EXPECT_EQ(d[7], 255);
}

}  // namespace
}  // namespace epviz::check
