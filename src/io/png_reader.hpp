#pragma once
// Reading PNG files (goldens) into top-down RGBA8 through stb_image. Goldens
// come from version control, so a file is read only when it is a regular file
// and its header promises an image of a bounded size: a few kilobytes of
// deflate can claim gigabytes of pixels.
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

struct PngSize {
  std::int64_t width = 0, height = 0;
};

// The most pixels read_png_rgba decodes by default: 16 M, 64 MiB of RGBA
// (above a 4K frame).
inline constexpr std::int64_t kMaxPngPixels = std::int64_t(1) << 24;

// The width and height in the PNG signature and IHDR chunk, without decoding
// anything; nullopt when the path is not a regular file starting like a PNG.
std::optional<PngSize> read_png_size(const std::filesystem::path& path);

// The image, converted to RGBA8; nullopt when the file is missing, not a
// regular file, not a readable image, or larger than `max_pixels`.
std::optional<RgbaPixels> read_png_rgba(const std::filesystem::path& path,
                                        std::int64_t max_pixels = kMaxPngPixels);

}  // namespace epviz::io
