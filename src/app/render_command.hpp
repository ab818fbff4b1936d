#pragma once
#include <CLI/CLI.hpp>
#include <functional>

namespace epviz::app {
// `epviz render JOB`: PNG sequences, videos, and galleries of render jobs.
std::function<int()> add_render_command(CLI::App& app);
}  // namespace epviz::app
