#pragma once
#include <functional>

#include "app/cli.hpp"

namespace epviz::app {
// `epviz render JOB`: PNG sequences, videos, and galleries of render jobs.
std::function<int()> add_render_command(cli::Command app);
}  // namespace epviz::app
