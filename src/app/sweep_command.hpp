#pragma once
// `epviz sweep SWEEP.json`: the points of a parameter sweep run in this
// process on a thread pool, one JSON row per point (docs/cluster.md).
#include <functional>

namespace CLI {
class App;
}

namespace epviz::app {

std::function<int()> add_sweep_command(CLI::App& app);

}  // namespace epviz::app
