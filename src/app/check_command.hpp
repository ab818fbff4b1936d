#pragma once
#include <CLI/CLI.hpp>
#include <functional>

namespace epviz::app {
// `epviz check JOB...`: renders chosen frames of jobs in memory and compares
// them with committed goldens (render regression checks for CI).
std::function<int()> add_check_command(CLI::App& app);
}  // namespace epviz::app
