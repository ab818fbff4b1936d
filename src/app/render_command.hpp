#pragma once
#include <functional>

namespace CLI {
class App;  // CLI11: included only where a command is defined
}

namespace epviz::app {
// `epviz render JOB`: PNG sequences, videos, and galleries of render jobs.
std::function<int()> add_render_command(CLI::App& app);
}  // namespace epviz::app
