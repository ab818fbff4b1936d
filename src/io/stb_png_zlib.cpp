// stb_image_write's PNG encoder with zlib doing the deflate. stb's own deflate
// is simple and slow (tens of ms per 720p frame, the cost stb's header itself
// points at); its documented hook STBIW_ZLIB_COMPRESS lets zlib, which is far
// faster at the same level, do that part. This translation unit holds the
// encoder's implementation (static, so it cannot clash with libstb's copy).
#include "io/stb_png_zlib.hpp"

#include <zlib.h>

#include <cstdlib>

namespace {

// The contract of STBIW_ZLIB_COMPRESS: a malloc'd zlib stream (stb frees it).
unsigned char* zlib_compress(unsigned char* data, int data_len, int* out_len, int quality) {
  uLongf size = compressBound(uLong(data_len));
  auto* out = static_cast<unsigned char*>(std::malloc(size));
  if (!out) return nullptr;
  const int level = quality < 0 ? Z_DEFAULT_COMPRESSION : quality > 9 ? 9 : quality;
  if (compress2(out, &size, data, uLong(data_len), level) != Z_OK) {
    std::free(out);
    return nullptr;
  }
  *out_len = int(size);
  return out;
}

}  // namespace

#define STBIW_ZLIB_COMPRESS zlib_compress
#define STB_IMAGE_WRITE_STATIC
#define STB_IMAGE_WRITE_IMPLEMENTATION
#if defined(__GNUC__)
#pragma GCC diagnostic push
#pragma GCC diagnostic ignored "-Wunused-function"
#pragma GCC diagnostic ignored "-Wmissing-field-initializers"
#endif
#include <stb/stb_image_write.h>
#if defined(__GNUC__)
#pragma GCC diagnostic pop
#endif

namespace epviz::io::detail {

int& png_compression_level() { return stbi_write_png_compression_level; }
int& png_force_filter() { return stbi_write_force_png_filter; }

int png_to_func(void (*write)(void* context, void* data, int size), void* context, int width,
                int height, const std::uint8_t* rgba, int stride_bytes) {
  return stbi_write_png_to_func(write, context, width, height, 4, rgba, stride_bytes);
}

}  // namespace epviz::io::detail
