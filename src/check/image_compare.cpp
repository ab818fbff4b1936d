#include "check/image_compare.hpp"

#include <algorithm>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace epviz::check {
namespace {

std::size_t checked_pixels(int width, int height, std::size_t actual, std::size_t golden) {
  if (width < 0 || height < 0) throw std::invalid_argument("image size must not be negative");
  const std::size_t pixels = std::size_t(width) * std::size_t(height);
  if (actual != pixels * 4 || golden != pixels * 4)
    throw std::invalid_argument("image buffers of " + std::to_string(actual) + " and " +
                                std::to_string(golden) + " bytes do not hold " +
                                std::to_string(width) + "x" + std::to_string(height) +
                                " RGBA pixels");
  return pixels;
}

int largest_channel_difference(const std::uint8_t* a, const std::uint8_t* b) {
  int largest = 0;
  for (int c = 0; c < 4; ++c) largest = std::max(largest, std::abs(int(a[c]) - int(b[c])));
  return largest;
}

}  // namespace

PixelComparison compare_pixels(int width, int height, std::span<const std::uint8_t> actual,
                               std::span<const std::uint8_t> golden, int max_channel_difference) {
  PixelComparison result;
  result.pixels = checked_pixels(width, height, actual.size(), golden.size());
  for (std::size_t p = 0; p < result.pixels; ++p) {
    const int d = largest_channel_difference(&actual[p * 4], &golden[p * 4]);
    result.largest_channel_difference = std::max(result.largest_channel_difference, d);
    result.pixels_differing += d > max_channel_difference;
  }
  return result;
}

std::vector<std::uint8_t> diff_image(int width, int height, std::span<const std::uint8_t> actual,
                                     std::span<const std::uint8_t> golden,
                                     int max_channel_difference) {
  const std::size_t pixels = checked_pixels(width, height, actual.size(), golden.size());
  std::vector<std::uint8_t> out(pixels * 4);
  for (std::size_t p = 0; p < pixels; ++p) {
    const std::uint8_t* g = &golden[p * 4];
    std::uint8_t* o = &out[p * 4];
    const int d = largest_channel_difference(&actual[p * 4], g);
    if (d > max_channel_difference) {
      o[0] = std::uint8_t(std::min(255, 128 + d));
      o[1] = 0;
      o[2] = 0;
    } else {
      const int grey = (int(g[0]) + int(g[1]) + int(g[2])) / 3;
      o[0] = o[1] = o[2] = std::uint8_t(grey / 4);
    }
    o[3] = 255;
  }
  return out;
}

}  // namespace epviz::check
