#pragma once
// What every command's options share: the values are read by io
// (option_values.hpp, output_paths.hpp); an empty value is refused where the
// options are defined (cli::reject_empty_values, app/cli.hpp).
#include "app/cli.hpp"
#include "io/option_values.hpp"
#include "io/output_paths.hpp"

namespace epviz::app {

using io::parse_integer;
using io::parse_number;
using io::parse_vec3;
using io::require_separate_files;

}  // namespace epviz::app
