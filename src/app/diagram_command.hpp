#pragma once
// `epviz diagram --case kovalevskaya|lagrange --area C0`: the bifurcation
// diagram of an integrable top at a fixed area constant, as CSV and a figure
// (docs/diagram.md).
#include <functional>

#include "app/cli.hpp"

namespace epviz::app {

std::function<int()> add_diagram_command(cli::Command app);

}  // namespace epviz::app
