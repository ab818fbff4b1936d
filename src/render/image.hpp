#pragma once
// A frame read back from GL: top-down rows of RGBA8 pixels, ready for PNG or
// ffmpeg's rawvideo input.
#include <cstddef>
#include <cstdint>
#include <vector>

#include <glm/vec4.hpp>

namespace epviz::render {

struct RgbaImage {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> pixels;  // width * height * 4 bytes, row 0 at the top

  std::size_t offset(int x, int y) const {
    return (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
            static_cast<std::size_t>(x)) *
           4;
  }
  // The pixel at column x, row y (y = 0 is the top row).
  glm::u8vec4 at(int x, int y) const {
    const std::size_t i = offset(x, y);
    return {pixels[i], pixels[i + 1], pixels[i + 2], pixels[i + 3]};
  }
};

}  // namespace epviz::render
