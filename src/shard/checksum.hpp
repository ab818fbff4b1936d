#pragma once
// Checksums of the files a shard writes, so that a merge can tell a complete
// file from one cut short or changed since: 64-bit FNV-1a (io/fnv1a.hpp),
// written as 16 hex digits. It detects accidents (truncation, a rerun writing other bytes), not
// tampering, which is all a merge needs.
#include <cstdint>
#include <filesystem>
#include <string>
#include <string_view>

#include "io/fnv1a.hpp"

namespace epviz::shard {

std::string checksum_of(std::string_view bytes);
// The file's size and checksum; throws std::runtime_error naming the file when it cannot be read.
struct FileDigest {
  std::uintmax_t bytes = 0;
  std::string checksum;
};
FileDigest digest_file(const std::filesystem::path& path);

}  // namespace epviz::shard
