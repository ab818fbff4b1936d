#pragma once
// `epviz simulate`: one run (or every preset with --case all), samples to CSV,
// a JSON report, and a summary on stdout.
#include <functional>

#include "app/cli.hpp"

namespace epviz::app {

// Adds the subcommand to `app`; the returned function runs it after parsing and
// returns the process exit code.
std::function<int()> add_simulate_command(cli::Command app);

}  // namespace epviz::app
