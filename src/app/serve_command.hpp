#pragma once
#include <functional>

namespace CLI {
class App;  // CLI11: included only where a command is defined
}

namespace epviz::app {
// `epviz serve [JOB]`: the renderer live in a web browser (docs/serve.md).
std::function<int()> add_serve_command(CLI::App& app);
}  // namespace epviz::app
