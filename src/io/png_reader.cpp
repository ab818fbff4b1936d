#include "io/png_reader.hpp"

#include <stb/stb_image.h>

namespace epviz::io {

std::optional<RgbaPixels> read_png_rgba(const std::filesystem::path& path) {
  RgbaPixels out;
  int channels = 0;
  unsigned char* data = stbi_load(path.c_str(), &out.width, &out.height, &channels, 4);
  if (data == nullptr) return std::nullopt;
  out.rgba.assign(data, data + std::size_t(out.width) * std::size_t(out.height) * 4);
  stbi_image_free(data);
  return out;
}

}  // namespace epviz::io
