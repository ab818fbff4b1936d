#pragma once
// `epviz section SECTION.json`: a Poincaré section, its crossings as CSV
// (docs/sections.md).
#include <functional>

namespace CLI {
class App;
}

namespace epviz::app {

std::function<int()> add_section_command(CLI::App& app);

}  // namespace epviz::app
