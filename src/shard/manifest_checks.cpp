#include "shard/manifest_checks.hpp"

#include <algorithm>
#include <filesystem>
#include <string_view>

#include "io/printable.hpp"
#include "io/video_format.hpp"

namespace epviz::shard {

namespace {

namespace fs = std::filesystem;

bool has_control(std::string_view s) {
  return std::any_of(s.begin(), s.end(),
                     [](char c) { return static_cast<unsigned char>(c) < 0x20 || c == 0x7f; });
}

// The options `epviz sweep`, `epviz render` and `epviz section` write into a
// shard's command (app/sweep_command, app/render_command,
// section/section_shard), each followed by its value.
bool known_option(const std::string& kind, const std::string& option) {
  static const std::vector<std::string> rows{"--out", "-j"};
  static const std::vector<std::string> render{"--out", "--width", "--height", "--format"};
  const auto& allowed = kind == "render" ? render : rows;
  return std::find(allowed.begin(), allowed.end(), option) != allowed.end();
}

}  // namespace

std::string output_name_problem(const std::string& name) {
  if (name.empty()) return "";
  if (name == "." || name == ".." || name.find('/') != std::string::npos || has_control(name) ||
      name.size() > 255)
    return "expected a plain file name (the merge writes it into the output folder), got '" +
           io::printable(name) + "'";
  return "";
}

std::string file_path_problem(const std::string& path) {
  const fs::path p(path);
  bool climbs = false;
  for (const auto& part : p) climbs = climbs || part == "..";
  if (path.empty() || p.is_absolute() || climbs || has_control(path) || path.size() > 4096)
    return "expected a path inside the manifest's folder (relative, without '..'), got '" +
           io::printable(path) + "'";
  return "";
}

std::string render_file_problem(const std::string& path, const std::string& output) {
  const std::string want = output.empty() ? ".png" : fs::path(output).extension().string();
  bool video = output.empty();
  for (auto f : {io::VideoFormat::mp4, io::VideoFormat::webm, io::VideoFormat::gif})
    video = video || want == io::video_format_extension(f);
  if (!video || fs::path(path).extension().string() != want)
    return "a render's files are " +
           std::string(output.empty() ? "PNG frames (.png)" : "video segments like its output") +
           ", got '" + io::printable(path) + "' for output '" + io::printable(output) + "'";
  return "";
}

std::string hash_problem(const std::string& hash) {
  if (hash.empty() || hash.size() > 64 ||
      hash.find_first_not_of("0123456789abcdef") != std::string::npos)
    return "expected hex digits, got '" + io::printable(hash) + "'";
  return "";
}

std::string text_problem(const std::string& text) {
  if (has_control(text) || text.size() > 4096)
    return "expected one line of text, got '" + io::printable(text) + "'";
  return "";
}

std::string command_problem(const std::vector<std::string>& command, const std::string& kind,
                            const std::string& source) {
  const std::string shape = "expected [\"epviz\", \"" + kind +
                            "\", the source, then options of epviz " + kind + " with a value each]";
  if (command.size() < 3 || command[0] != "epviz" || command[1] != kind || command[2] != source ||
      command.size() % 2 == 0)
    return shape;
  for (std::size_t i = 3; i < command.size(); i += 2) {
    if (!known_option(kind, command[i]))
      return shape + ", got option '" + io::printable(command[i]) + "'";
    if (!text_problem(command[i + 1]).empty())
      return "the value of " + command[i] + ": " + text_problem(command[i + 1]);
  }
  return "";
}

}  // namespace epviz::shard
