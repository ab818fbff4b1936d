#pragma once
#include <functional>

namespace CLI {
class App;  // CLI11: included only where a command is defined
}

namespace epviz::app {
// `epviz cases`: the presets with their parameters, conditions and fourth integral.
std::function<int()> add_cases_command(CLI::App& app);
}  // namespace epviz::app
