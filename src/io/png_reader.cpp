#include "io/png_reader.hpp"

#include <stb/stb_image.h>
#include <zlib.h>

#include <array>
#include <fstream>
#include <iterator>
#include <string_view>
#include <vector>

namespace epviz::io {
namespace {

// Opening a FIFO or a device would block or read forever.
bool is_regular(const std::filesystem::path& path) {
  std::error_code ec;
  return std::filesystem::is_regular_file(path, ec);
}

std::int64_t big_endian32(const unsigned char* p) {
  return (std::int64_t(p[0]) << 24) | (std::int64_t(p[1]) << 16) | (std::int64_t(p[2]) << 8) |
         std::int64_t(p[3]);
}

// Every chunk (length, type, data, CRC) lies within the file. stb_image
// trusts a chunk's stated length and grows its buffer to it before reading
// the data: a 318-byte file claiming a 2 GB IDAT made it allocate 2 GB (found
// by fuzz/golden_reader_fuzz.cpp).
bool chunks_within(const std::vector<unsigned char>& bytes) {
  std::size_t at = 8;  // after the signature
  while (bytes.size() - at >= 12) {
    const std::int64_t length = big_endian32(&bytes[at]);
    if (length > std::int64_t(bytes.size() - at - 12)) return false;
    if (std::string_view(reinterpret_cast<const char*>(&bytes[at + 4]), 4) == "IEND") break;
    at += 12 + std::size_t(length);
  }
  return true;
}

// The image data (the IDAT chunks, joined) is one complete zlib stream that
// inflates to at most `limit` bytes. stb_image's inflater reads zeros past the
// end of a cut stream and goes on writing what they decode to, doubling its
// buffer: a 98-byte file of a 4 x 3 image made it allocate 2 GB (found by
// fuzz/golden_reader_fuzz.cpp). Inflated here first, into a scratch buffer,
// by zlib, which stops at the end of its input.
bool image_data_inflates_within(const std::vector<unsigned char>& bytes, std::size_t limit) {
  std::vector<unsigned char> data;
  for (std::size_t at = 8; bytes.size() - at >= 12;) {
    const auto length = std::size_t(big_endian32(&bytes[at]));
    const std::string_view type(reinterpret_cast<const char*>(&bytes[at + 4]), 4);
    if (type == "IDAT") data.insert(data.end(), &bytes[at + 8], &bytes[at + 8] + length);
    if (type == "IEND") break;
    at += 12 + length;
  }
  z_stream z{};
  if (inflateInit(&z) != Z_OK) return false;
  z.next_in = data.data();
  z.avail_in = uInt(data.size());
  std::array<unsigned char, 16384> scratch{};
  std::size_t out = 0;
  int status = Z_OK;
  while (status == Z_OK && out <= limit) {
    z.next_out = scratch.data();
    z.avail_out = uInt(scratch.size());
    status = inflate(&z, Z_NO_FLUSH);
    out += scratch.size() - z.avail_out;
    // No progress without more input: the stream is cut short.
    if (status == Z_BUF_ERROR || (status == Z_OK && z.avail_in == 0 && z.avail_out != 0)) break;
  }
  inflateEnd(&z);
  return status == Z_STREAM_END && out <= limit;
}

}  // namespace

std::optional<PngSize> read_png_size(const std::filesystem::path& path) {
  if (!is_regular(path)) return std::nullopt;
  // Signature (8 bytes), then the first chunk: length (4), "IHDR", width, height.
  std::array<unsigned char, 24> head{};
  std::ifstream in(path, std::ios::binary);
  if (!in.read(reinterpret_cast<char*>(head.data()), head.size())) return std::nullopt;
  constexpr std::string_view signature("\x89PNG\r\n\x1a\n", 8);
  if (std::string_view(reinterpret_cast<const char*>(head.data()), 8) != signature ||
      std::string_view(reinterpret_cast<const char*>(head.data()) + 12, 4) != "IHDR")
    return std::nullopt;
  return PngSize{big_endian32(&head[16]), big_endian32(&head[20])};
}

std::optional<RgbaPixels> read_png_rgba(const std::filesystem::path& path,
                                        std::int64_t max_pixels) {
  const auto size = read_png_size(path);
  // Divided, not multiplied: a header may claim 2^32 - 1 by 2^32 - 1.
  if (!size || size->width < 1 || size->height < 1 || size->width > max_pixels / size->height)
    return std::nullopt;
  std::ifstream in(path, std::ios::binary);
  const std::vector<unsigned char> bytes((std::istreambuf_iterator<char>(in)),
                                         std::istreambuf_iterator<char>());
  if (bytes.size() < 8 || !chunks_within(bytes)) return std::nullopt;
  // The most a W x H image's data inflates to: a filter byte a row and 8
  // bytes a pixel (16-bit RGBA), twice over for the interlaced passes' rows.
  const auto most = 2 * std::size_t(size->height) * (1 + 8 * std::size_t(size->width)) + 64;
  if (!image_data_inflates_within(bytes, most)) return std::nullopt;
  RgbaPixels out;
  int channels = 0;
  unsigned char* data =
      stbi_load_from_memory(bytes.data(), int(bytes.size()), &out.width, &out.height, &channels, 4);
  if (data == nullptr) return std::nullopt;
  out.rgba.assign(data, data + std::size_t(out.width) * std::size_t(out.height) * 4);
  stbi_image_free(data);
  return out;
}

}  // namespace epviz::io
