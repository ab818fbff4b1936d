#include "shard/checksum.hpp"

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <stdexcept>
#include <vector>

namespace epviz::shard {

std::string checksum_of(std::string_view bytes) {
  io::Fnv1a64 h;
  h.add(bytes);
  return h.hex();
}

FileDigest digest_file(const std::filesystem::path& path) {
  std::FILE* f = std::fopen(path.c_str(), "rb");
  if (!f) throw std::runtime_error(path.string() + ": cannot read (" + std::strerror(errno) + ")");
  io::Fnv1a64 h;
  FileDigest d;
  std::vector<char> buf(1 << 16);
  std::size_t n;
  while ((n = std::fread(buf.data(), 1, buf.size(), f)) > 0) {
    h.add({buf.data(), n});
    d.bytes += n;
  }
  const bool bad = std::ferror(f);
  std::fclose(f);
  if (bad) throw std::runtime_error(path.string() + ": read error");
  d.checksum = h.hex();
  return d;
}

}  // namespace epviz::shard
