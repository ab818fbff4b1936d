#pragma once
#include <functional>

#include "app/cli.hpp"

namespace epviz::app {
// `epviz serve [JOB]`: the renderer live in a web browser (docs/serve.md).
std::function<int()> add_serve_command(cli::Command app);
}  // namespace epviz::app
