#pragma once
// RGBA8 frames to JPEG in memory with libjpeg-turbo (TurboJPEG API). Lives in
// serve/ rather than io/ because serve is the only module that links
// libturbojpeg, and frames for the browser are its only use.
#include <cstdint>
#include <span>
#include <vector>

namespace epviz::serve {

// Keeps one compressor handle and one output buffer between frames, so a
// stream of same-sized frames allocates nothing but the returned vector. Not
// thread-safe: one encoder per thread.
class JpegEncoder {
 public:
  JpegEncoder();  // throws std::runtime_error when TurboJPEG cannot start
  ~JpegEncoder();
  JpegEncoder(const JpegEncoder&) = delete;
  JpegEncoder& operator=(const JpegEncoder&) = delete;

  // `rgba` holds `height` top-down rows of `width` RGBA8 pixels (alpha is
  // dropped). 4:2:0 chroma subsampling; quality 1..100. Throws
  // std::invalid_argument for a size that does not match the buffer or a bad
  // quality, std::runtime_error when TurboJPEG fails.
  std::vector<std::uint8_t> encode(int width, int height, std::span<const std::uint8_t> rgba,
                                   int quality);

 private:
  void* handle_ = nullptr;           // tjhandle
  unsigned char* buffer_ = nullptr;  // tjAlloc'd, big enough for the largest frame so far
  unsigned long capacity_ = 0;
};

}  // namespace epviz::serve
