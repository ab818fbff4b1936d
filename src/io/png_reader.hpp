#pragma once
// Reading PNG files (goldens) into top-down RGBA8 through stb_image.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <vector>

namespace epviz::io {

struct RgbaPixels {
  int width = 0;
  int height = 0;
  std::vector<std::uint8_t> rgba;  // width * height * 4 bytes, row 0 at the top
};

// The image, converted to RGBA8; nullopt when the file is missing or not a
// readable image.
std::optional<RgbaPixels> read_png_rgba(const std::filesystem::path& path);

}  // namespace epviz::io
