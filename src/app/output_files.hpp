#pragma once
#include <filesystem>
#include <string_view>

namespace epviz::app {
// Writes the whole file under a temporary name and renames it, so that no
// reader ever sees half a file. Throws std::runtime_error naming the path.
void write_output_file(const std::filesystem::path& path, std::string_view content);
}  // namespace epviz::app
