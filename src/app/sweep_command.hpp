#pragma once
// `epviz sweep SWEEP.json`: the points of a parameter sweep run in this
// process on a thread pool, one JSON row per point (docs/cluster.md).
#include <functional>

#include "app/cli.hpp"

namespace epviz::app {

std::function<int()> add_sweep_command(cli::Command app);

}  // namespace epviz::app
