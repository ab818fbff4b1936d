// A golden's bytes (a PNG from version control) through what `epviz check`
// does with it: the size in its header, then decoding within the pixel cap.
// Neither may crash, and a file whose header claims more pixels than the cap
// must not be decoded (a few kilobytes of deflate can claim gigabytes).
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/png_reader.hpp"

namespace {

namespace fs = std::filesystem;
using namespace epviz;

// Small, so that the fuzzer reaches the refusal of large images quickly.
constexpr std::int64_t kCap = 1 << 16;

const fs::path& golden() {
  static const fs::path file =
      fs::temp_directory_path() / ("epviz-fuzz-golden-" + std::to_string(::getpid()) + ".png");
  return file;
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  {
    std::ofstream out(golden(), std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  }
  const auto header = io::read_png_size(golden());
  const auto image = io::read_png_rgba(golden(), kCap);
  if (image) {
    if (!header || image->width != header->width || image->height != header->height) std::abort();
    if (std::int64_t(image->width) * image->height > kCap) std::abort();
    if (image->rgba.size() != std::size_t(image->width) * std::size_t(image->height) * 4)
      std::abort();
  }
  return 0;
}
