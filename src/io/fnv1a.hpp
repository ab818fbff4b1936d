#pragma once
// 64-bit FNV-1a (Fowler, Noll, Vo): a fingerprint of bytes, to notice
// accidents (a file cut short or edited, another machine's name), not a
// defence against forgery. One implementation for the shard checksums, the
// job hash in golden.json and the machine token of temporaries.
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>

namespace epviz::io {

class Fnv1a64 {
 public:
  void add(std::string_view bytes) {
    for (unsigned char c : bytes) {
      h_ ^= c;
      h_ *= 1099511628211ull;  // the FNV prime
    }
  }
  std::uint64_t value() const { return h_; }
  // 16 lower-case hex digits.
  std::string hex() const {
    char buf[17];
    std::snprintf(buf, sizeof buf, "%016llx", static_cast<unsigned long long>(h_));
    return buf;
  }

 private:
  std::uint64_t h_ = 14695981039346656037ull;  // the offset basis
};

inline std::uint64_t fnv1a64(std::string_view bytes) {
  Fnv1a64 h;
  h.add(bytes);
  return h.value();
}

}  // namespace epviz::io
