#pragma once
#include <CLI/CLI.hpp>
#include <functional>

namespace epviz::app {
// `epviz cases`: the presets with their parameters, conditions and fourth integral.
std::function<int()> add_cases_command(CLI::App& app);
}  // namespace epviz::app
