#pragma once
// What every command's options share: the values are read by io
// (option_values.hpp, output_paths.hpp); an empty value is refused here,
// where CLI11 is.
#include "io/option_values.hpp"
#include "io/output_paths.hpp"

namespace CLI {
class App;  // CLI11: included only where options are defined
}

namespace epviz::app {

using io::parse_integer;
using io::parse_number;
using io::parse_vec3;
using io::require_distinct_files;

// Makes an empty value (`--case ''`) an error of every option of `command`
// and of its subcommands that takes a value, instead of the same as not giving
// the option. Call it once every option is added.
void reject_empty_values(CLI::App& command);

}  // namespace epviz::app
