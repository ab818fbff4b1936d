#pragma once
// Small RGBA8 images for the check tests, made pixel by pixel.
#include <cstdint>
#include <vector>

#include "check/frame_verdict.hpp"

namespace epviz::check {

struct TestImage {
  int w = 0, h = 0;
  std::vector<std::uint8_t> rgba;  // top-down, w * h * 4 bytes

  std::uint8_t* pixel(int x, int y) { return &rgba[(std::size_t(y) * w + x) * 4]; }
  const std::uint8_t* pixel(int x, int y) const { return &rgba[(std::size_t(y) * w + x) * 4]; }
  double grey(int x, int y) const {
    const auto* p = pixel(x, y);
    return 0.299 * p[0] + 0.587 * p[1] + 0.114 * p[2];
  }
  ImageView view() const { return {w, h, rgba}; }
};

inline TestImage flat_image(int w, int h, std::uint8_t r, std::uint8_t g, std::uint8_t b) {
  TestImage im{w, h, std::vector<std::uint8_t>(std::size_t(w) * h * 4, 255)};
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x) {
      im.pixel(x, y)[0] = r;
      im.pixel(x, y)[1] = g;
      im.pixel(x, y)[2] = b;
    }
  return im;
}

// A disc on a flat background, like a rendered body: in its flat windows,
// rounded floating-point sums once made a variance slightly negative and an
// image's SSIM with itself slightly below 1.
inline TestImage disc_image(int w, int h) {
  TestImage im = flat_image(w, h, 23, 31, 47);
  for (int y = 0; y < h; ++y)
    for (int x = 0; x < w; ++x)
      if ((x - w / 2) * (x - w / 2) + (y - h / 2) * (y - h / 2) < w * w / 16) {
        im.pixel(x, y)[0] = 204;
        im.pixel(x, y)[1] = 158;
        im.pixel(x, y)[2] = 92;
      }
  return im;
}

}  // namespace epviz::check
