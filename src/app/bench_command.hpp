#pragma once
// `epviz bench`: work-precision, long-time invariant drift and stability
// studies of epviz's own methods; tables on stdout, every row to JSON.
#include <CLI/CLI.hpp>
#include <functional>

namespace epviz::app {

// Adds the subcommand to `app`; the returned function runs it after parsing and
// returns the process exit code.
std::function<int()> add_bench_command(CLI::App& app);

}  // namespace epviz::app
