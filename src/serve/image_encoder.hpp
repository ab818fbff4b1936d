#pragma once
// A rendered frame to the bytes the page shows: JPEG (the default; a 720p
// rendered frame at quality 85 measured ~1.2 ms and ~85 kB, PNG ~11 ms and
// ~380 kB) or lossless PNG.
#include <cstdint>
#include <optional>
#include <vector>

#include "render/image.hpp"
#include "serve/jpeg_encoder.hpp"
#include "serve/server.hpp"

namespace epviz::serve {

struct EncodedImage {
  std::vector<std::uint8_t> bytes;
  const char* mime = "";  // "image/jpeg" or "image/png"
};

// Not thread-safe (it keeps a TurboJPEG handle): the render thread owns one.
class ImageEncoder {
 public:
  ImageEncoder(ImageFormat format, int jpeg_quality);
  // Throws std::invalid_argument for an image whose pixels do not match its size.
  EncodedImage encode(const render::RgbaImage& image);

 private:
  ImageFormat format_;
  int jpeg_quality_;
  std::optional<JpegEncoder> jpeg_;  // made on first use, on the thread that encodes
};

}  // namespace epviz::serve
