#pragma once
// Where epviz finds its read-only files (shaders/, assets/, render_jobs/), so
// that one binary works installed, relocated and in its build tree. In order:
//   1. ../share/epviz next to the running executable (/proc/self/exe): an
//      installed tree, wherever its prefix was copied to;
//   2. $EPVIZ_DATA_DIR;
//   3. the source tree the binary was built from (compiled in), skipped when
//      $EPVIZ_IGNORE_SOURCE_TREE is set (tests of an installed copy use it to
//      prove they do not lean on the sources).
#include <filesystem>
#include <string_view>
#include <vector>

namespace epviz::io {

std::vector<std::filesystem::path> data_search_path();

// The first data directory holding `relative` (a file or a folder, e.g.
// "assets/serve.html"), as a full path; empty when none has it.
std::filesystem::path find_data_path(std::string_view relative);

}  // namespace epviz::io
