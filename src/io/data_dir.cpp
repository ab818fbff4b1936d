#include "io/data_dir.hpp"

#include <cstdlib>
#include <system_error>

namespace epviz::io {

std::vector<std::filesystem::path> data_search_path() {
  std::vector<std::filesystem::path> path;
  std::error_code error;
  const auto exe = std::filesystem::read_symlink("/proc/self/exe", error);
  if (!error) path.push_back(exe.parent_path().parent_path() / "share" / "epviz");
  if (const char* env = std::getenv("EPVIZ_DATA_DIR"); env != nullptr && *env != '\0')
    path.emplace_back(env);
  const char* ignore = std::getenv("EPVIZ_IGNORE_SOURCE_TREE");
  if (ignore == nullptr || *ignore == '\0') path.emplace_back(EPVIZ_BUILD_SOURCE_DIR);
  return path;
}

std::filesystem::path find_data_path(std::string_view relative) {
  for (const auto& dir : data_search_path()) {
    const auto candidate = dir / relative;
    std::error_code error;
    if (std::filesystem::exists(candidate, error)) return candidate;
  }
  return {};
}

}  // namespace epviz::io
