#include "check/golden_record.hpp"

#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

#include "io/bad_input.hpp"
#include "io/fnv1a.hpp"
#include "io/json_text.hpp"
#include "io/printable.hpp"

namespace epviz::check {

std::string file_hash(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(file.string() + ": cannot be read to hash it");
  std::ostringstream s;
  s << in.rdbuf();
  io::Fnv1a64 h;
  h.add(s.str());
  return "fnv1a64:" + h.hex();
}

RenderEnvironment render_environment(std::string renderer, std::string version, std::string font) {
  RenderEnvironment e{std::move(renderer), std::move(version), std::move(font), ""};
  if (e.font_file != "builtin") e.font_hash = file_hash(e.font_file);
  return e;
}

std::string to_json_text(const GoldenRecord& r) {
  nlohmann::ordered_json j;
  j["epviz_version"] = r.epviz_version;
  j["gl_renderer"] = r.gl_renderer;
  j["gl_version"] = r.gl_version;
  j["font_file"] = r.font_file;
  j["font_hash"] = r.font_hash;
  j["job_file"] = r.job_file;
  j["job_hash"] = r.job_hash;
  j["frames"] = r.frames;
  j["width"] = r.width;
  j["height"] = r.height;
  return io::json_text(j, 2) + "\n";
}

namespace {

constexpr std::uintmax_t kMaxRecordBytes = 1 << 20;

[[noreturn]] void refuse_record(const std::filesystem::path& file, const std::string& what) {
  throw io::BadInput(io::printable(file.string(), 200) + ": " + what);
}

}  // namespace

std::optional<GoldenRecord> read_golden_record(const std::filesystem::path& file) {
  namespace fs = std::filesystem;
  std::error_code ec;
  const auto type = fs::symlink_status(file, ec).type();
  if (type == fs::file_type::not_found) return std::nullopt;
  if (type != fs::file_type::regular)
    refuse_record(file,
                  "not a regular file (golden.json must be a plain file written by --update)");
  if (fs::file_size(file, ec) > kMaxRecordBytes)
    refuse_record(file, "larger than 1 MiB; not a golden record (re-create it with --update)");
  std::ifstream in(file);
  if (!in) refuse_record(file, "cannot be read");
  std::ostringstream text;
  text << in.rdbuf();
  std::string key;
  try {
    const auto j = io::parse_json(text.str());
    GoldenRecord r;
    key = "epviz_version";
    r.epviz_version = j.at(key).get<std::string>();
    key = "gl_renderer";
    r.gl_renderer = j.at(key).get<std::string>();
    key = "gl_version";
    r.gl_version = j.at(key).get<std::string>();
    key = "font_file";
    r.font_file = j.value(key, "");
    key = "font_hash";
    r.font_hash = j.value(key, "");
    key = "job_file";
    r.job_file = j.value(key, "");
    key = "job_hash";
    r.job_hash = j.value(key, "");
    key = "frames";
    r.frames = j.value(key, std::vector<int>{});
    for (const int f : r.frames)
      if (f < 0)
        refuse_record(file,
                      "frames: " + std::to_string(f) + " is not a frame (allowed: 0 or more)");
    key = "width";
    r.width = j.value(key, 0);
    key = "height";
    r.height = j.value(key, 0);
    if (r.width < 0 || r.height < 0) refuse_record(file, "width, height: expected 0 or more");
    return r;
  } catch (const nlohmann::json::exception& e) {
    refuse_record(file,
                  (key.empty() ? std::string("not JSON") : key + ": missing or of the wrong type") +
                      " (" + io::printable(e.what(), 120) +
                      "); a damaged golden record: re-create it with --update");
  }
}

}  // namespace epviz::check
