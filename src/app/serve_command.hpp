#pragma once
#include <CLI/CLI.hpp>
#include <functional>

namespace epviz::app {
// `epviz serve [JOB]`: the renderer live in a web browser (docs/serve.md).
std::function<int()> add_serve_command(CLI::App& app);
}  // namespace epviz::app
