#pragma once
#include <functional>

#include "app/cli.hpp"

namespace epviz::app {
// `epviz cases`: the presets with their parameters, conditions and fourth integral.
std::function<int()> add_cases_command(cli::Command app);
}  // namespace epviz::app
