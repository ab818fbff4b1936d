// A shard manifest's bytes (`*.manifest.json`, written by another machine or
// user) through what `epviz merge` does with it before joining anything: the
// strict reader, the checks of its fields, the check of its files against the
// folder, and the rerun advice it prints. Bad input must end in the error a
// user sees (exit 2), never in a crash; and what is accepted must keep every
// path inside the folder and the advice on one line.
#include <unistd.h>

#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include "io/bad_input.hpp"
#include "shard/manifest.hpp"

namespace {

namespace fs = std::filesystem;
using namespace epviz;

// One folder per fuzzing process, holding the manifest under test and one
// shard file it may name.
const fs::path& folder() {
  static const fs::path dir = [] {
    const fs::path d =
        fs::temp_directory_path() / ("epviz-fuzz-manifest-" + std::to_string(::getpid()));
    fs::create_directories(d);
    std::ofstream(d / "rows.shard-0-of-2.jsonl") << "{\"index\":0}\n";
    return d;
  }();
  return dir;
}

bool escapes(const std::string& path) {
  const fs::path p(path);
  if (p.is_absolute() || p.has_root_name() || p.has_root_directory()) return true;
  for (const auto& part : p)
    if (part == "..") return true;
  return false;
}

void read_manifest_bytes(const std::uint8_t* data, std::size_t size) {
  const fs::path file = folder() / "rows.shard-0-of-2.manifest.json";
  {
    std::ofstream out(file, std::ios::binary | std::ios::trunc);
    out.write(reinterpret_cast<const char*>(data), std::streamsize(size));
  }
  const shard::Manifest m = shard::read_manifest(file);
  if (escapes(m.output)) std::abort();
  for (const auto& f : m.files)
    if (escapes(f.path)) std::abort();
  (void)shard::file_problems(m, folder());
  for (long j : {0L, m.shard.count - 1}) {
    const std::string advice = shard::rerun_command(m, j);
    for (char c : advice)
      if (c == '\n' || c == '\r' || c == '\0') std::abort();
  }
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  try {
    read_manifest_bytes(data, size);
  } catch (const io::BadInput&) {
  }
  return 0;
}
