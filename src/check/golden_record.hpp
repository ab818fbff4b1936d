#pragma once
// golden.json, written next to a job's goldens by `epviz check --update`:
// what made them, so that a later check can tell when the renderer changed
// (a Mesa upgrade moves antialiased edges), the font did, or the job file did.
#include <cstdint>
#include <filesystem>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace epviz::check {

// What draws a run's frames: the GL renderer and the overlay's font.
struct RenderEnvironment {
  std::string gl_renderer, gl_version;  // GL_RENDERER, GL_VERSION
  std::string font_file;                // a path, or "builtin" (ImGui's bitmap font)
  std::string font_hash;                // file_hash of font_file; "" for builtin
};

struct GoldenRecord {
  std::string epviz_version;
  std::string gl_renderer;  // GL_RENDERER, e.g. "llvmpipe (LLVM 15.0.6, 256 bits)"
  std::string gl_version;   // GL_VERSION, e.g. "4.5 (Core Profile) Mesa 22.3.6"
  // The overlay's font: its file (or "builtin", ImGui's bitmap font) and
  // file_hash of it ("" for builtin). Empty in records of older epviz.
  std::string font_file, font_hash;
  std::string job_file;
  std::string job_hash;  // "fnv1a64:" + 16 hex digits of the job file's bytes
  std::vector<int> frames;
  int width = 0, height = 0;
};

// "fnv1a64:0123456789abcdef" of the file's contents (a job file, a font);
// throws std::runtime_error when it cannot be read.
std::string file_hash(const std::filesystem::path& file);

// The environment of GL `renderer` and `version` drawing with the overlay
// font `font` (a path, or "builtin"), whose file is hashed here.
RenderEnvironment render_environment(std::string renderer, std::string version, std::string font);

std::string to_json_text(const GoldenRecord& r);
// nullopt when the file is missing. golden.json comes from version control:
// a link, a FIFO, a directory, more than 1 MiB, or content that is not a golden
// record (a key missing or of the wrong type, a negative frame) throws
// io::BadInput naming the file and the key.
std::optional<GoldenRecord> read_golden_record(const std::filesystem::path& file);

}  // namespace epviz::check
