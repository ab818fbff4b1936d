#include "io/frame_names.hpp"

#include <array>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <stdexcept>
#include <system_error>
#include <vector>

namespace epviz::io {
namespace {

// CRC-32 as PNG defines it (ISO 3309, reflected polynomial 0xEDB88320).
const std::array<std::uint32_t, 256>& crc_table() {
  static const std::array<std::uint32_t, 256> table = [] {
    std::array<std::uint32_t, 256> t{};
    for (std::uint32_t n = 0; n < 256; ++n) {
      std::uint32_t c = n;
      for (int k = 0; k < 8; ++k) c = (c & 1u) ? 0xEDB88320u ^ (c >> 1) : c >> 1;
      t[n] = c;
    }
    return t;
  }();
  return table;
}

std::uint32_t crc32(const std::uint8_t* data, std::size_t size) {
  const auto& table = crc_table();
  std::uint32_t c = 0xFFFFFFFFu;
  for (std::size_t i = 0; i < size; ++i) c = table[(c ^ data[i]) & 0xFFu] ^ (c >> 8);
  return c ^ 0xFFFFFFFFu;
}

std::uint32_t read_be32(const std::uint8_t* p) {
  return (std::uint32_t(p[0]) << 24) | (std::uint32_t(p[1]) << 16) | (std::uint32_t(p[2]) << 8) |
         std::uint32_t(p[3]);
}

}  // namespace

int frame_number_width(int frame_count) {
  int digits = 1;
  for (int last = frame_count > 1 ? frame_count - 1 : 0; last >= 10; last /= 10) ++digits;
  return digits < 4 ? 4 : digits;
}

std::string frame_file_name(int index, int frame_count, std::string_view prefix,
                            std::string_view extension) {
  if (index < 0 || index >= frame_count)
    throw std::invalid_argument("frame_file_name: frame " + std::to_string(index) +
                                " is not in 0.." + std::to_string(frame_count - 1));
  std::string number = std::to_string(index);
  const int width = frame_number_width(frame_count);
  if (static_cast<int>(number.size()) < width)
    number.insert(0, static_cast<std::size_t>(width) - number.size(), '0');
  std::string name(prefix);
  name += number;
  name += extension;
  return name;
}

bool png_frame_complete(const std::filesystem::path& path) {
  std::error_code ec;
  if (!std::filesystem::is_regular_file(path, ec)) return false;
  const auto size = std::filesystem::file_size(path, ec);
  if (ec || size < 8 + 25 + 12) return false;  // signature, IHDR, IEND at least
  std::vector<std::uint8_t> bytes(size);
  std::ifstream in(path, std::ios::binary);
  if (!in.read(reinterpret_cast<char*>(bytes.data()), static_cast<std::streamsize>(size)))
    return false;
  if (in.peek() != std::char_traits<char>::eof()) return false;  // grew while reading

  static constexpr std::uint8_t kSignature[8] = {0x89, 'P', 'N', 'G', '\r', '\n', 0x1A, '\n'};
  if (std::memcmp(bytes.data(), kSignature, 8) != 0) return false;
  std::size_t pos = 8;
  bool first = true;
  while (pos + 12 <= bytes.size()) {
    const std::uint32_t length = read_be32(bytes.data() + pos);
    if (length > 0x7FFFFFFFu || length > bytes.size() - pos - 12) return false;  // truncated chunk
    const std::uint8_t* type = bytes.data() + pos + 4;
    if (first && (std::memcmp(type, "IHDR", 4) != 0 || length != 13)) return false;
    first = false;
    const std::uint32_t stored = read_be32(type + 4 + length);
    if (crc32(type, 4 + std::size_t(length)) != stored) return false;
    pos += 12 + std::size_t(length);
    if (std::memcmp(type, "IEND", 4) == 0) return length == 0 && pos == bytes.size();
  }
  return false;  // ran out of data before IEND
}

}  // namespace epviz::io
