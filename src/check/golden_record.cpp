#include "check/golden_record.hpp"

#include <cstdio>
#include <fstream>
#include <nlohmann/json.hpp>
#include <sstream>
#include <stdexcept>

namespace epviz::check {

std::uint64_t fnv1a64(std::string_view bytes) {
  std::uint64_t h = 0xcbf29ce484222325ull;  // offset basis
  for (const char c : bytes) {
    h ^= static_cast<unsigned char>(c);
    h *= 0x100000001b3ull;  // FNV prime
  }
  return h;
}

std::string job_file_hash(const std::filesystem::path& file) {
  std::ifstream in(file, std::ios::binary);
  if (!in) throw std::runtime_error(file.string() + ": cannot read the job file to hash it");
  std::ostringstream s;
  s << in.rdbuf();
  char hex[17];
  std::snprintf(hex, sizeof hex, "%016llx", static_cast<unsigned long long>(fnv1a64(s.str())));
  return std::string("fnv1a64:") + hex;
}

std::string to_json_text(const GoldenRecord& r) {
  nlohmann::ordered_json j;
  j["epviz_version"] = r.epviz_version;
  j["gl_renderer"] = r.gl_renderer;
  j["gl_version"] = r.gl_version;
  j["job_file"] = r.job_file;
  j["job_hash"] = r.job_hash;
  j["frames"] = r.frames;
  j["width"] = r.width;
  j["height"] = r.height;
  return j.dump(2) + "\n";
}

std::optional<GoldenRecord> read_golden_record(const std::filesystem::path& file) {
  std::ifstream in(file);
  if (!in) return std::nullopt;
  try {
    const auto j = nlohmann::json::parse(in);
    GoldenRecord r;
    r.epviz_version = j.at("epviz_version").get<std::string>();
    r.gl_renderer = j.at("gl_renderer").get<std::string>();
    r.gl_version = j.at("gl_version").get<std::string>();
    r.job_file = j.value("job_file", "");
    r.job_hash = j.value("job_hash", "");
    r.frames = j.value("frames", std::vector<int>{});
    r.width = j.value("width", 0);
    r.height = j.value("height", 0);
    return r;
  } catch (const nlohmann::json::exception&) {
    return std::nullopt;
  }
}

}  // namespace epviz::check
