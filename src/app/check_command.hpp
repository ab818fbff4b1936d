#pragma once
// `epviz check JOB...`: renders chosen frames of jobs in memory and compares
// them with committed goldens (render regression checks for CI).
#include <functional>

#include "app/cli.hpp"

namespace epviz::app {

// Adds the subcommand to `app`; the returned function runs it after parsing and
// returns the process exit code.
std::function<int()> add_check_command(cli::Command app);

}  // namespace epviz::app
