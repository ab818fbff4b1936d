#pragma once
// Comparing a rendered image with its golden: the one implementation behind
// `epviz check` and epviz's own snapshot tests. Images are top-down RGBA8
// (width * height * 4 bytes). Nothing here knows GL or files.
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

namespace epviz::check {

// A pixel differs when any of its four channels differs by more than
// `max_channel_difference` (0..255).
struct PixelComparison {
  std::size_t pixels = 0;  // width * height
  std::size_t pixels_differing = 0;
  int largest_channel_difference = 0;
  double fraction_differing() const {
    return pixels ? double(pixels_differing) / double(pixels) : 0.0;
  }
};

// Throws std::invalid_argument when a buffer does not hold width x height pixels.
PixelComparison compare_pixels(int width, int height, std::span<const std::uint8_t> actual,
                               std::span<const std::uint8_t> golden, int max_channel_difference);

// A picture of where two images differ: the golden dimmed to a quarter of its
// grey level as context, and each pixel that differs by more than
// `max_channel_difference` in bright red (brighter for larger differences, so
// that small drifts still show). Opaque, same size as the inputs.
std::vector<std::uint8_t> diff_image(int width, int height, std::span<const std::uint8_t> actual,
                                     std::span<const std::uint8_t> golden,
                                     int max_channel_difference);

}  // namespace epviz::check
